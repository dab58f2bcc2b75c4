"""The log of unexpected errors (the 500s): one line per failed request, with a request
id the client is also told, and the traceback once per distinct cause.

A traceback is about 6 kB: logged for every 500, a client repeating one failing link
writes megabytes a second. The cause of a failure is where it was raised (exception
type, file and line); its traceback says everything the next failures of that cause
would, so they get only their line, naming the request whose line carries it.
"""

import logging
import secrets
import traceback
from collections import OrderedDict
from collections.abc import Mapping
from typing import Any

logger = logging.getLogger("uvicorn.error")
#: distinct causes remembered at most (the oldest forgotten first: its traceback is
#: logged again should it come back)
MAX_CAUSES = 256
#: characters of the failing path and of the error's message kept in the line
MAX_TEXT = 200


def cause_of(exc: BaseException) -> tuple[str, str, int]:
    """Where ``exc`` was raised: (type, file, line) of the innermost frame.

    >>> try:
    ...     1 / 0
    ... except ZeroDivisionError as exc:
    ...     cause_of(exc)[0]
    'ZeroDivisionError'
    """
    frames = traceback.extract_tb(exc.__traceback__)
    if not frames:
        return type(exc).__name__, "", 0
    return type(exc).__name__, frames[-1].filename, frames[-1].lineno or 0


def _printable(text: str) -> str:
    """``text`` on one line, shortened: a path or a message cannot forge log lines."""
    return text.encode("unicode_escape").decode("ascii")[:MAX_TEXT]


class FailureLog:
    """Logs each unexpected error as one line; a cause's traceback only the first time."""

    def __init__(self) -> None:
        #: cause -> the request id whose line carries its traceback
        self.seen: OrderedDict[tuple[str, str, int], str] = OrderedDict()

    def record(self, scope: Mapping[str, Any], exc: BaseException) -> str:
        """Log the failure of the request ``scope``; its new request id."""
        request_id = secrets.token_hex(8)
        cause = cause_of(exc)
        first = self.seen.get(cause)
        line = "500 %s %s request %s: %s: %s"
        args = (
            scope.get("method", ""),
            _printable(scope.get("path", "")),
            request_id,
            cause[0],
            _printable(str(exc)),
        )
        if first is None:
            self.seen[cause] = request_id
            while len(self.seen) > MAX_CAUSES:
                self.seen.popitem(last=False)
            logger.error(line, *args, exc_info=exc)
        else:
            self.seen.move_to_end(cause)
            logger.error(line + " (traceback as request %s)", *args, first)
        return request_id
