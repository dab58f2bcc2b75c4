"""What the app promises at its edges: every input declared once (the field table,
the API model generated from it, the page form and share links read from it), the
typed output models and their views, and units."""
