"""One error type with an HTTP status, shown as JSON on /api and as HTML on pages."""

import re
from collections.abc import Callable, Coroutine
from typing import Any

from fastapi import Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse, Response
from fastapi.routing import APIRoute
from starlette.exceptions import HTTPException

from app.web.templating import templates


class AppError(Exception):
    def __init__(self, status: int, error: str, detail: list[dict[str, str]] | None = None):
        super().__init__(error)
        self.status, self.error, self.detail = status, error, detail or []


# Union members that pydantic puts in an error's location: the screw's discriminator tags,
# a Literal member ("literal['steel','stainless-303']") and an input model ("MaterialIn";
# input models are named *In). They are not fields a user wrote.
_UNION_TAG = re.compile(r"catalog|custom|literal\[.*\]|[A-Z][A-Za-z]*In")


def _field(loc: tuple[Any, ...]) -> str:
    parts = [str(p) for p in loc if p not in ("body", "query", "path")]
    parts = [p for p in parts if not _UNION_TAG.fullmatch(p)]
    return ".".join(parts) or "request"


def _detail(error: Any) -> dict[str, str]:
    loc = tuple(error.get("loc", ()))
    if error.get("type") == "json_invalid":
        # the location of a JSON syntax error is a character offset, not a field
        reason = (error.get("ctx") or {}).get("error", "")
        where = f" at character {loc[-1]}" if loc and isinstance(loc[-1], int) else ""
        return {"field": "request", "message": f"Malformed JSON body{where}: {reason}".strip()}
    return {"field": _field(loc), "message": str(error.get("msg", ""))}


def validation_details(errors: Any) -> list[dict[str, str]]:
    """Field-level messages from pydantic errors: the dotted field and the reason."""
    return [_detail(e) for e in errors]


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
    return response


async def validation_error_handler(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, RequestValidationError)
    return _respond(request, 422, "invalid input", validation_details(exc.errors()))


class ApiRoute(APIRoute):
    """An API route whose unreadable request bodies come back as invalid input.

    FastAPI answers a body it cannot even decode (bytes that are not UTF-8) with its own
    400 ``{"detail": "There was an error parsing the body"}``; here it is malformed JSON
    like any other: a 422 in the error shape.
    """

    def get_route_handler(self) -> Callable[[Request], Coroutine[Any, Any, Response]]:
        handler = super().get_route_handler()

        async def route(request: Request) -> Response:
            try:
                return await handler(request)
            except HTTPException as exc:
                if exc.status_code != 400:
                    raise
                reason = "Malformed JSON body: not readable as UTF-8 JSON"
                raise AppError(
                    422, "invalid input", [{"field": "request", "message": reason}]
                ) from exc

        return route
