"""HTTP figures: throughput and latency against a bare ceiling, page weight, memory, soak.

The app is served as ``leadscrew-selector`` serves it (``python -m app.cli``, log level
warning: no access log): its event loop (``app.cli.event_loop``: asyncio's for one worker,
uvloop for several) and its HTTP protocol (``app.server.protocol``, which reads nothing
more from a connection it has shed for the answer's Retry-After, so a client told to come
back later is not served again at once). The bare ceiling is a plain uvicorn subprocess
(``--http httptools``, uvloop, the faster of the two loops for it). One worker is pinned
to CPU 0 when there are two or more CPUs; wrk runs pinned to the others, so the server and
the load generator do not fight over one core.
"""

import gzip
import http.client
import math
import os
import subprocess
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import urlsplit

from bench import wrk
from bench.report import Report
from deploy.local import free_port, stop, wait_until_healthy

ROOT = Path(__file__).resolve().parents[1]
HERE = Path(__file__).resolve().parent
SELECT = "/api/v1/select?load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10"
FRAGMENT = "/?load=100&speed=50&length=500&lead=10"
HX = {"HX-Request": "true"}
# Browsers and most HTTP clients ask for gzip; the app compresses, so measure that cost.
GZIP = {"Accept-Encoding": "gzip"}
SERVER_CPU = "0"
CLIENT_CPUS = ",".join(str(i) for i in range(1, os.cpu_count() or 1)) or None


def fetch(
    port: int, path: str, headers: dict[str, str] | None = None
) -> tuple[int, dict[str, str], bytes]:
    """One GET; the body as sent on the wire (still compressed)."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    try:
        conn.request("GET", path, headers=headers or {})
        resp = conn.getresponse()
        return resp.status, {k.lower(): v for k, v in resp.getheaders()}, resp.read()
    finally:
        conn.close()


@contextmanager
def server(target: str, *, factory: bool, workers: int = 1) -> Iterator[tuple[int, int]]:
    """A subprocess serving ``target`` with this checkout's code (its root first on
    PYTHONPATH): the app (``factory``) as ``python -m app.cli`` serves it, anything else by
    plain uvicorn; yields (port, pid) once it answers. One worker is pinned to CPU 0;
    more share every CPU with wrk."""
    port = free_port()
    if factory:
        cmd = [sys.executable, "-m", "app.cli", "--workers", str(workers)]
    else:
        cmd = [sys.executable, "-m", "uvicorn", target, "--loop", "uvloop", "--http", "httptools"]
        cmd += ["--no-access-log"]
    cmd += ["--host", "127.0.0.1", "--port", str(port), "--log-level", "warning"]
    if CLIENT_CPUS is not None and workers == 1:
        cmd = ["taskset", "-c", SERVER_CPU, *cmd]
    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")])),
    }
    proc = subprocess.Popen(cmd, cwd=ROOT, env=env)
    try:
        probe = "/api/v1/health" if factory else "/ceiling"
        wait_until_healthy(port, proc, target, probe)
        yield port, proc.pid
    finally:
        stop(proc)


def rss_kib(pid: int) -> int:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    raise RuntimeError(f"no VmRSS for {pid}")


class _Assets(HTMLParser):
    """Scripts and stylesheets a page references."""

    def __init__(self) -> None:
        super().__init__()
        self.urls: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        if tag == "script" and a.get("src"):
            self.urls.append(str(a["src"]))
        elif tag == "link" and "stylesheet" in (a.get("rel") or "").split() and a.get("href"):
            self.urls.append(str(a["href"]))


def _wire(port: int, path: str, headers: dict[str, str]) -> tuple[int, int, dict[str, str]]:
    """(status, body bytes on the wire, headers) of one GET accepting gzip."""
    status, head, body = fetch(port, path, {**GZIP, **headers})
    return status, len(body), head


def page_weight(report: Report, port: int) -> None:
    report.section("Page weight (bytes on the wire with Accept-Encoding: gzip)")
    status, head, body = fetch(port, "/", GZIP)
    if status != 200:
        report.line("GET /", f"status {status}", "200", False)
        return
    html = gzip.decompress(body) if head.get("content-encoding") == "gzip" else body
    parser = _Assets()
    parser.feed(html.decode())
    total = len(body)
    report.info(f"/ ({head.get('content-encoding', 'identity')})", f"{len(body):,} B")
    for url in parser.urls:
        if urlsplit(url).netloc:
            report.line(f"external asset {url}", "off-site", "none", False)
            continue
        status, size, ahead = _wire(port, url, {})
        if status != 200:
            report.line(f"GET {url}", f"status {status}", "200", False)
        total += size
        encoding = ahead.get("content-encoding", "identity")
        report.info(f"{url} ({encoding})", f"{size:,} B")
        report.info("", f"cache-control: {ahead.get('cache-control', '(none)')}")
    report.line(
        "first load of / (HTML+CSS+JS)",
        f"{total / 1024:.1f} KiB",
        "<= 500 KiB",
        total <= 500 * 1024,
    )
    status, size, _ = _wire(port, FRAGMENT, HX)
    report.line(
        "one results fragment" + ("" if status == 200 else f" (status {status})"),
        f"{size / 1024:.1f} KiB",
        "<= 60 KiB",
        status == 200 and size <= 60 * 1024,
    )
    status, _, body = fetch(port, FRAGMENT, HX)
    report.line(
        "one results fragment, HTML before gzip",
        f"{len(body) / 1000:.1f} kB",
        "<= 25 kB",
        status == 200 and len(body) <= 25_000,
    )
    status, size, _ = _wire(port, SELECT, {})
    report.info(f"one select JSON response (status {status})", f"{size / 1024:.1f} KiB")
    status, head, body = fetch(port, SELECT)
    report.line(
        "select JSON, default request, before gzip",
        f"{len(body) / 1000:.1f} kB",
        "<= 12 kB",
        status == 200 and len(body) <= 12_000,
    )


def _show(report: Report, name: str, r: wrk.WrkResult) -> None:
    report.info(
        name,
        f"{r.requests_per_s:8.0f} req/s  p50 {r.p50_ms:6.2f} ms  p99 {r.p99_ms:7.2f} ms  "
        f"({r.requests} requests)",
    )
    if r.errors:
        kinds = ", ".join(f"{k} {v}" for k, v in r.socket_errors.items() if v)
        report.info("", f"errors: non-2xx/3xx {r.non_2xx_3xx}; socket: {kinds or 'none'}")


def throughput(report: Report, seconds: int) -> None:
    report.section(
        f"HTTP, one uvicorn worker, wrk -t2 -c32 -d{seconds}s (gzip accepted; wrk on "
        f"CPUs {CLIENT_CPUS or 'shared'}, server on CPU {SERVER_CPU if CLIENT_CPUS else 'shared'})"
    )
    with (
        server("bench.ceiling_app:app", factory=False) as (ceiling_port, _),
        server("app.main:create_app", factory=True) as (port, _),
    ):
        base = f"http://127.0.0.1:{port}"
        runs = {
            "ceiling": (f"http://127.0.0.1:{ceiling_port}/ceiling", GZIP),
            "select": (base + SELECT, GZIP),
            "fragment": (base + FRAGMENT, {**GZIP, **HX}),
        }
        for url, headers in runs.values():  # warm-up
            wrk.run(url, 2, headers=headers, cpus=CLIENT_CPUS)
        results = {
            name: wrk.run(url, seconds, headers=headers, cpus=CLIENT_CPUS)
            for name, (url, headers) in runs.items()
        }
        # the same routes with a different query on every request: no cache hits
        for name, path, headers in (
            ("select, distinct queries", SELECT, GZIP),
            ("fragment, distinct queries", FRAGMENT, {**GZIP, **HX}),
        ):
            template = path.replace("load_n=100", "load_n=%s").replace("load=100", "load=%s")
            results[name] = wrk.run(
                base + path,
                seconds,
                headers=headers,
                cpus=CLIENT_CPUS,
                script=HERE / "distinct.lua",
                script_args=(template,),
            )
        report.info("", "select and fragment repeat one query (after the first, cache hits);")
        report.info("", "'distinct queries' computes every response (no cache hits)")
        for name, r in results.items():
            _show(report, name, r)
        ceiling = results["ceiling"].requests_per_s
        for name, share in (
            ("select", 0.5),
            ("fragment", 0.3),
            ("select, distinct queries", 0.10),
            ("fragment, distinct queries", 0.05),
        ):
            r = results[name]
            ratio = r.answered_per_s / ceiling  # 503s of shed requests are not throughput
            report.line(
                f"{name}: answered throughput / ceiling",
                f"{ratio * 100:.1f} %",
                f">= {share * 100:.0f} %",
                ratio >= share,
            )
            report.line(f"{name}: p99 latency", f"{r.p99_ms:.1f} ms", "< 50 ms", r.p99_ms < 50)
            report.line(f"{name}: errors in the {seconds} s run", f"{r.errors}", "0", r.errors == 0)
        time.sleep(2.0)  # the work wrk's connections left in progress ends (Retry-After 1 s)
        page_weight(report, port)
        one = results["select, distinct queries"].answered_per_s
    two_workers(report, seconds, one)


def distinct_select(port: int, seconds: int) -> wrk.WrkResult:
    """wrk -t2 -c32 on the select API, a different query on every request."""
    template = SELECT.replace("load_n=100", "load_n=%s")
    return wrk.run(
        f"http://127.0.0.1:{port}{SELECT}",
        seconds,
        headers=GZIP,
        cpus=CLIENT_CPUS,
        script=HERE / "distinct.lua",
        script_args=(template,),
    )


def two_workers(report: Report, seconds: int, one_rps: float) -> None:
    """Distinct selects against two uvicorn workers, as a share of one worker's rate."""
    report.section("HTTP, two uvicorn workers (unpinned, sharing the CPUs with wrk)")
    with server("app.main:create_app", factory=True, workers=2) as (port, _):
        distinct_select(port, 2)  # warm-up: both workers load the catalog and the code
        r = distinct_select(port, seconds)
    _show(report, "select, distinct queries, 2 workers", r)
    ratio = r.answered_per_s / one_rps if one_rps else 0.0
    report.line(
        "two workers / one worker (distinct select)", f"{ratio:.2f}", ">= 1.8", ratio >= 1.8
    )
    report.line("2 workers: p99 latency", f"{r.p99_ms:.1f} ms", "< 50 ms", r.p99_ms < 50)


def memory(report: Report, first: int, second: int, max_seconds: int) -> None:
    report.section(f"Memory: server RSS after {first:,} and {second:,} select requests")
    report.info("requests", "GET /api/v1/select, load cycling over 1,000 values, lead 10 mm")
    script = HERE / "count.lua"
    with server("app.main:create_app", factory=True) as (port, pid):
        url = f"http://127.0.0.1:{port}/api/v1/select"
        report.info("RSS at start", f"{rss_kib(pid) / 1024:.1f} MiB")
        # wrk waits out its whole duration even when the script has stopped every
        # thread, so size each phase from the rate of a short first run
        probe = wrk.run(url, 3, script=script, script_args=(str(first),), cpus=CLIENT_CPUS)
        rate = max(probe.requests_per_s, 1.0)
        done = probe.requests
        rss: list[int] = []
        for goal in (first, second):
            per_thread = str(max(1, (goal - done) // 2))
            seconds = min(max_seconds, max(2, math.ceil((goal - done) / rate * 1.2)))
            r = wrk.run(url, seconds, script=script, script_args=(per_thread,), cpus=CLIENT_CPUS)
            done += r.requests
            rss.append(rss_kib(pid))
            report.info(
                f"RSS after {done:,} requests",
                f"{rss[-1] / 1024:.1f} MiB ({r.requests_per_s:.0f} req/s, errors {r.errors})",
            )
        growth = rss[1] / rss[0] - 1
        complete = done >= second * 0.99
        report.line(
            f"RSS growth {first:,} -> {done:,} requests",
            f"{growth * 100:+.1f} %",
            "within 10 %",
            abs(growth) <= 0.10 if complete else None,
        )
        if not complete:
            report.info(
                "",
                f"stopped at {done:,} of {second:,} (phases capped at {max_seconds} s); "
                f"run with --soak for the full {second:,}",
            )


def soak(report: Report, seconds: int) -> None:
    report.section(f"Load test: wrk -t2 -c32 -d{seconds}s per endpoint, no errors allowed")
    with (
        server("bench.ceiling_app:app", factory=False) as (ceiling_port, _),
        server("app.main:create_app", factory=True) as (port, _),
    ):
        base = f"http://127.0.0.1:{port}"
        for name, url, headers in (
            ("ceiling", f"http://127.0.0.1:{ceiling_port}/ceiling", GZIP),
            ("select", base + SELECT, GZIP),
            ("fragment", base + FRAGMENT, {**GZIP, **HX}),
        ):
            r = wrk.run(url, seconds, headers=headers, cpus=CLIENT_CPUS)
            _show(report, name, r)
            report.line(
                f"{name}: non-2xx/3xx responses", f"{r.non_2xx_3xx}", "0", r.non_2xx_3xx == 0
            )
            socket_errors = sum(r.socket_errors.values())
            detail = ", ".join(f"{k} {v}" for k, v in r.socket_errors.items())
            report.line(f"{name}: socket errors", f"{socket_errors}", "0", socket_errors == 0)
            report.info("", detail)


def run(
    report: Report,
    *,
    seconds: int,
    memory_requests: tuple[int, int],
    memory_seconds: int,
    soak_seconds: int | None,
) -> None:
    if not wrk.available():
        report.section("HTTP")
        print(f"  {wrk.INSTALL_HINT}")
        report.line("HTTP figures", "not measured", "wrk installed", None)
        return
    throughput(report, seconds)
    memory(report, *memory_requests, max_seconds=memory_seconds)
    if soak_seconds:
        soak(report, soak_seconds)
