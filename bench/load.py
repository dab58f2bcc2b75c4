"""A keep-alive HTTP load generator that times each answer by its status.

wrk gives one latency distribution for every answer; under load shedding the 503s are
fast and the figure that matters is the latency of the requests that were served. This
client keeps ``connections`` connections each with one request outstanding (as wrk
does), a different query on every request, and records (status, seconds) per answer;
an answer slower than ``timeout_s`` counts as a client timeout and its connection is
replaced, as wrk's ``--timeout`` does.
"""

import asyncio
import itertools
import time
from dataclasses import dataclass, field

import uvloop


@dataclass
class LoadResult:
    """Answers by status with their latencies, client timeouts and connection errors."""

    latencies_s: dict[int, list[float]] = field(default_factory=dict)
    timeouts: int = 0
    errors: int = 0
    seconds: float = 0.0

    @property
    def answers(self) -> int:
        return sum(len(v) for v in self.latencies_s.values())

    def share(self, status: int) -> float:
        return len(self.latencies_s.get(status, [])) / max(1, self.answers)

    def percentile_ms(self, status: int, fraction: float) -> float | None:
        values = sorted(self.latencies_s.get(status, []))
        if not values:
            return None
        return values[min(len(values) - 1, int(fraction * len(values)))] * 1e3


async def _read_answer(reader: asyncio.StreamReader) -> int:
    """Read one response with a Content-Length body; its status."""
    head = await reader.readuntil(b"\r\n\r\n")
    status = int(head[9:12])
    length = 0
    for line in head.split(b"\r\n")[1:]:
        name, _, value = line.partition(b":")
        if name.strip().lower() == b"content-length":
            length = int(value)
    await reader.readexactly(length)
    return status


async def _connection(
    port: int,
    counter: "itertools.count[int]",
    template: str,
    headers: bytes,
    until: float,
    timeout_s: float,
    result: LoadResult,
) -> None:
    """One client connection, reopened after a timeout or an error, until ``until``."""
    while time.monotonic() < until:
        try:
            reader, writer = await asyncio.open_connection("127.0.0.1", port)
        except OSError:
            result.errors += 1
            await asyncio.sleep(0.01)
            continue
        try:
            while time.monotonic() < until:
                path = template % (50 + next(counter) / 1000)
                head = f"GET {path} HTTP/1.1\r\nHost: bench\r\n".encode() + headers + b"\r\n"
                started = time.monotonic()
                writer.write(head)
                status = await asyncio.wait_for(_read_answer(reader), timeout_s)
                result.latencies_s.setdefault(status, []).append(time.monotonic() - started)
        except TimeoutError:
            result.timeouts += 1
        except (OSError, asyncio.IncompleteReadError, ValueError):
            result.errors += 1
        finally:
            writer.close()


async def _run(
    port: int,
    template: str,
    headers: dict[str, str],
    connections: int,
    seconds: float,
    timeout_s: float,
) -> LoadResult:
    result = LoadResult()
    raw = b"".join(f"{k}: {v}\r\n".encode() for k, v in headers.items())
    counter = itertools.count()
    started = time.monotonic()
    until = started + seconds
    await asyncio.gather(
        *(
            _connection(port, counter, template, raw, until, timeout_s, result)
            for _ in range(connections)
        )
    )
    result.seconds = time.monotonic() - started
    return result


def run(
    port: int,
    template: str,
    *,
    connections: int,
    seconds: float,
    headers: dict[str, str] | None = None,
    timeout_s: float = 2.0,
) -> LoadResult:
    """Load ``template`` (``%s`` takes a load that differs on every request)."""
    with asyncio.Runner(loop_factory=uvloop.new_event_loop) as runner:
        return runner.run(_run(port, template, headers or {}, connections, seconds, timeout_s))
