"""Computing off the event loop: the full forms of a selection (``detail=full`` and the
exports), the pairs, comparisons and every page that runs a selection (results, detail)
run on a few threads of their own.

A costly request (every number of a hundred candidates takes about 50 ms, a results page
of a hundred about 80 ms) computed on the event loop holds up everything else the loop
does, the health check included: with 64 clients on such queries the health check waited
seconds, past any probe's timeout. On its own threads the compute leaves the loop free to
accept, parse and answer; the threads are few (``compute_threads``) so the loop competes
for the interpreter with few others, and how much work waits for them is bounded by the
admission in ``app.server.overload``. A compact select (a few milliseconds) stays on the
loop: handing it to a thread and back would cost about as much as it frees. Pages that
depend on nothing but the catalog (/catalog, /guide, /validation) are rendered once."""

import asyncio
import sys
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from functools import cache, partial
from typing import ParamSpec, TypeVar

from app.server.settings import get_settings

P = ParamSpec("P")
T = TypeVar("T")


@cache
def executor() -> ThreadPoolExecutor:
    """The process's compute threads (one pool, whatever the number of apps).

    With them comes a shorter thread switch interval (``thread_switch_interval_s``). The
    event loop gives up the interpreter at each socket call (poll, read, send) and then
    waits for a busy compute thread to hand it back, which Python makes it do after the
    switch interval, 5 ms by default: a loop answering a flood makes hundreds of such
    calls a second, each of which could wait that long. At 0.5 ms each waits a tenth.
    """
    settings = get_settings()
    sys.setswitchinterval(settings.thread_switch_interval_s)
    return ThreadPoolExecutor(settings.compute_threads, thread_name_prefix="compute")


async def computed(work: Callable[P, T], *args: P.args, **kwargs: P.kwargs) -> T:
    """``work(*args, **kwargs)`` on a compute thread; its exceptions propagate here."""
    return await asyncio.get_running_loop().run_in_executor(
        executor(), partial(work, *args, **kwargs)
    )
