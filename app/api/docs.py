"""/docs: Swagger UI from vendored files, started by a static script (no CDN, no inline JS).

FastAPI's built-in page loads Swagger UI from a CDN and starts it with an inline script;
both break the Content-Security-Policy (``script-src 'self'``) and the offline rule.
``static/css/docs.css`` raises Swagger UI's colours to WCAG AA contrast and
``static/js/docs.js`` configures it for assistive technology (see both files).
"""

from fastapi import APIRouter
from fastapi.responses import HTMLResponse

SWAGGER_UI_VERSION = "5.35.0"
PAGE = f"""<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <meta name="viewport" content="width=device-width, initial-scale=1">
  <title>leadscrew-selector API</title>
  <link rel="stylesheet" href="/static/vendor/swagger-ui-{SWAGGER_UI_VERSION}.css">
  <link rel="stylesheet" href="/static/css/docs.css">
  <script src="/static/vendor/swagger-ui-bundle-{SWAGGER_UI_VERSION}.js" defer></script>
  <script src="/static/js/docs.js" defer></script>
</head>
<body>
  <div id="swagger-ui" data-openapi-url="/openapi.json"></div>
</body>
</html>
"""

router = APIRouter(include_in_schema=False)


@router.get("/docs", response_class=HTMLResponse)
async def docs() -> HTMLResponse:
    return HTMLResponse(PAGE)
