"""HTTP routes: ``api`` (JSON under /api/v1) and ``pages`` (HTML with HTMX partials)."""
