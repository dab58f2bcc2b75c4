"""One error type with an HTTP status, shown as JSON on /api and as HTML on pages."""

from typing import Any

from fastapi import Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse, Response

from app.templating import templates


class AppError(Exception):
    def __init__(self, status: int, error: str, detail: list[dict[str, str]] | None = None):
        super().__init__(error)
        self.status, self.error, self.detail = status, error, detail or []


def _field(loc: tuple[Any, ...]) -> str:
    parts = [str(p) for p in loc if p not in ("body", "query", "path")]
    # union tags are not fields a user wrote
    parts = [p for p in parts if p not in ("catalog", "custom")]
    return ".".join(parts) or "request"


def validation_details(errors: Any) -> list[dict[str, str]]:
    """Field-level messages from pydantic errors: the dotted field and the reason."""
    return [
        {"field": _field(tuple(e.get("loc", ()))), "message": str(e.get("msg", ""))} for e in errors
    ]


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


async def validation_error_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, RequestValidationError)
    return _respond(request, 422, "invalid input", validation_details(exc.errors()))
