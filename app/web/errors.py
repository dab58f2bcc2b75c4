"""Every error in one shape: JSON ``{"error", "detail"}`` on /api, the error page
elsewhere, with the status of the error."""

from fastapi import Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse, Response
from starlette.exceptions import HTTPException
from starlette.routing import Match

from app.server.errors import AppError, validation_details
from app.web.templating import templates

#: the methods a route of this app may declare
ROUTED_METHODS = ("GET", "POST", "PUT", "PATCH", "DELETE")


def _respond(request: Request, status: int, error: str, detail: list[dict[str, str]]) -> Response:
    if request.url.path.startswith("/api/"):
        return JSONResponse({"error": error, "detail": detail}, status_code=status)
    return templates.TemplateResponse(
        request,
        "error.html",
        {"status": status, "error": error, "detail": detail},
        status_code=status,
    )


async def app_error_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, AppError)
    return _respond(request, exc.status, exc.error, exc.detail)


async def http_error_handler(request: Request, exc: Exception) -> Response:
    """Routing errors (unknown path, wrong method) in the same shape as every error."""
    assert isinstance(exc, HTTPException)
    reason = {404: "not found", 405: "method not allowed"}.get(exc.status_code, str(exc.detail))
    response = _respond(
        request,
        exc.status_code,
        reason,
        [{"field": "request", "message": f"{request.method} {request.url.path}: {reason}"}],
    )
    if exc.headers:
        response.headers.update(exc.headers)
    if exc.status_code == 405:
        response.headers["Allow"] = ", ".join(_allowed(request))
    return response


def _allowed(request: Request) -> list[str]:
    """Every method some route answers on this path, by asking the router for each: it
    names only the first route's (POST for /api/v1/select, which a GET route serves
    too); HEAD wherever GET is (app.server.head)."""
    routes = request.app.router.routes
    methods = {
        method
        for method in ROUTED_METHODS
        if any(r.matches({**request.scope, "method": method})[0] == Match.FULL for r in routes)
    }
    if "GET" in methods:
        methods.add("HEAD")
    return sorted(methods)


async def validation_error_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, RequestValidationError)
    return _respond(request, 422, "invalid input", validation_details(exc.errors()))
