"""One error type with an HTTP status, the field-level details of invalid input, and the
API route that answers an unreadable body as invalid input. ``app.web.errors`` shows them
as JSON on /api and as HTML on pages."""

import re
from collections.abc import Callable, Coroutine
from typing import Any

from fastapi import Request
from fastapi.responses import Response
from fastapi.routing import APIRoute
from starlette.exceptions import HTTPException

from app.catalog.motors import UndrivableMotor, UnknownMotor
from app.catalog.own import UnknownNutMaterial
from app.catalog.supports import UnknownSupport


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
            except UnknownMotor as exc:
                raise AppError(
                    422, "invalid input", [{"field": "motor", "message": str(exc)}]
                ) from exc
            except (UnknownSupport, UnknownNutMaterial, UndrivableMotor) as exc:
                raise AppError(
                    422, "invalid input", [{"field": exc.field, "message": str(exc)}]
                ) from exc
            except HTTPException as exc:
                if exc.status_code != 400:
                    raise
                reason = "Malformed JSON body: not readable as UTF-8 JSON"
                raise AppError(
                    422, "invalid input", [{"field": "request", "message": reason}]
                ) from exc

        return route
