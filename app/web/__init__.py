"""The HTML pages: the selector form and results, HTMX fragments, figures and exports."""
