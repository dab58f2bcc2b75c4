"""The API's route: a name it does not read, where it is a page's (a share link's
``load``, whose API name carries its unit) or close to an API name, answered with the
name to use.

The input models refuse unknown names (``extra="forbid"``): pydantic's message, "Extra
inputs are not permitted", says nothing of the name meant. The field table knows both
names of every input (``app.contract.params.api_hint``), and the screw's model its own
(``app.contract.screws.screw_hint``); this route puts its hint in the 422 of the refused
name, in the body as in the query.
"""

from collections.abc import Callable, Coroutine
from typing import Any

from fastapi import Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import Response

from app.contract.params import api_hint
from app.contract.screws import screw_hint
from app.server.errors import ApiRoute


def hinted(error: dict[str, Any]) -> dict[str, Any]:
    """A validation error of a refused name, saying which name: with the hint of it
    where there is one."""
    loc = error.get("loc") or ()
    if error.get("type") != "extra_forbidden" or not loc or not isinstance(loc[-1], str):
        return error
    hint = screw_hint(loc[-1]) if "screw" in loc[:-1] else api_hint(loc[-1])
    return {**error, "msg": hint or f"'{loc[-1][:100]}' is not an input this route reads"}


class HintedRoute(ApiRoute):
    """An API route whose 422 for an unread name says which name the API reads."""

    def get_route_handler(self) -> Callable[[Request], Coroutine[Any, Any, Response]]:
        handler = super().get_route_handler()

        async def route(request: Request) -> Response:
            try:
                return await handler(request)
            except RequestValidationError as exc:
                errors = [hinted(dict(e)) for e in exc.errors()]
                raise RequestValidationError(errors, body=exc.body) from None

        return route
