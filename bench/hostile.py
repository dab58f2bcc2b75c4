"""Figures under hostile or excessive load, each against its target.

* Overload: 256 connections on one worker, every request a different query. The
  requests that are served must stay fast (p99 under 1 s) and no client may time out;
  the rest are shed with 503. Measured with ``bench.load`` (latency by status) and with
  wrk (its own socket timeouts), while the health check is polled; wrk against the bare
  ceiling app shows what the machine itself gives at 256 connections.
* Hostile heads: 1,000 requests with a 1 MB HX-History-Restore-Request header, 20
  unfinished 20 MB headers, 10 concurrent 50 MB headers, and 1,000 header values just
  under the limit; the server's RSS before and after.
* Slow-header flood through nginx (deploy/) in front of two app processes: normal
  requests while 200 sockets trickle half a request head.

Servers here are started as ``leadscrew-selector`` starts them (``python -m app.cli``),
so the server limits of ``app.server.protocol`` apply.
"""

import multiprocessing
import os
import select
import socket
import statistics
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor
from contextlib import contextmanager
from pathlib import Path

from app.server.settings import Settings
from bench import load, wrk
from bench.report import Report
from bench.web import CLIENT_CPUS, HERE, SERVER_CPU, fetch, free_port, rss_kib, server
from deploy.local import NGINX, nginx_in_front, wait_until_healthy
from deploy.local import slow_header_flood as trickle
from deploy.local import stop as stop_process

ROOT = Path(__file__).resolve().parents[1]
SELECT = "/api/v1/select?load_n=%s&speed_mm_s=50&length_mm=500&lead_mm=10"
FRAGMENT = "/?load=%s&speed=50&length=500&lead=10"
GZIP = {"Accept-Encoding": "gzip"}
MB = 1024 * 1024
SPAWN = multiprocessing.get_context("spawn")


@contextmanager
def cli_server() -> Iterator[tuple[int, int]]:
    """``python -m app.cli`` on a free port (pinned to the server CPU); (port, pid)."""
    port = free_port()
    cmd = [sys.executable, "-m", "app.cli", "--port", str(port), "--log-level", "warning"]
    if CLIENT_CPUS is not None:
        cmd = ["taskset", "-c", SERVER_CPU, *cmd]
    proc = subprocess.Popen(cmd, cwd=ROOT)
    try:
        wait_until_healthy(port, proc, "app.cli")
        yield port, proc.pid
    finally:
        stop_process(proc)


def _load_on_client_cpus(
    port: int, path: str, headers: dict[str, str], seconds: int
) -> load.LoadResult:
    """The 256-connection client, in a process of its own on the client CPUs: in this
    process it would share the GIL with the health poller and skew its timings."""
    if CLIENT_CPUS is not None:
        os.sched_setaffinity(0, {int(c) for c in CLIENT_CPUS.split(",")})
    return load.run(port, path, connections=256, seconds=seconds, headers=headers)


# --- overload --------------------------------------------------------------------------


def _poll_health(port: int, stop: threading.Event, answers: list[tuple[int, float]]) -> None:
    while not stop.wait(0.5):
        started = time.monotonic()
        try:
            status = fetch(port, "/api/v1/health")[0]
        except OSError:
            status = 0
        answers.append((status, time.monotonic() - started))


def _overload_run(
    report: Report, port: int, name: str, path: str, headers: dict[str, str], seconds: int
) -> None:
    """One 256-connection run of ``path`` while the health check is polled."""
    stop = threading.Event()
    health: list[tuple[int, float]] = []
    poller = threading.Thread(target=_poll_health, args=(port, stop, health))
    poller.start()
    try:
        with ProcessPoolExecutor(max_workers=1, mp_context=SPAWN) as pool:
            r = pool.submit(_load_on_client_cpus, port, path, headers, seconds).result()
    finally:
        stop.set()
        poller.join()
    served_p99 = r.percentile_ms(200, 0.99)
    shed_p99 = r.percentile_ms(503, 0.99)
    report.info(
        f"{name}: answers",
        f"{r.answers:,} in {r.seconds:.0f} s: {len(r.latencies_s.get(200, [])):,} served, "
        f"{len(r.latencies_s.get(503, [])):,} shed (503)",
    )
    report.info(f"{name}: 503 share", f"{r.share(503) * 100:.1f} %")
    report.info(f"{name}: served p50", f"{r.percentile_ms(200, 0.5) or float('nan'):.0f} ms")
    report.info(f"{name}: 503 p99", f"{shed_p99 or float('nan'):.0f} ms")
    report.line(
        f"{name}: p99 of served requests",
        "none served" if served_p99 is None else f"{served_p99:.0f} ms",
        "< 1000 ms",
        served_p99 is not None and served_p99 < 1000,
    )
    report.line(f"{name}: client timeouts (2 s)", f"{r.timeouts}", "0", r.timeouts == 0)
    report.info(f"{name}: connection errors", f"{r.errors}")
    ok = [latency for status, latency in health if status == 200]
    report.line(
        f"{name}: health checks answered 200",
        f"{len(ok)} of {len(health)}",
        "all",
        bool(health) and len(ok) == len(health),
    )
    if ok:
        report.info(f"{name}: slowest health check", f"{max(ok) * 1e3:.0f} ms")


def overload(report: Report, seconds: int) -> None:
    report.section("Overload: 256 connections on one worker, a different query each request")
    limit = Settings().max_requests_in_flight
    report.info("server", f"python -m app.cli (one worker), max_requests_in_flight {limit}")
    with cli_server() as (port, _):
        runs = (
            ("select", SELECT.replace("%s", "%.3f"), GZIP),
            ("fragment", FRAGMENT.replace("%s", "%.3f"), {**GZIP, "HX-Request": "true"}),
        )
        for _, path, headers in runs:  # warm-up
            load.run(port, path, connections=8, seconds=1, headers=headers)
        for name, path, headers in runs:
            _overload_run(report, port, name, path, headers, seconds)
        r = wrk.run(
            f"http://127.0.0.1:{port}{SELECT % 100}",
            seconds,
            connections=256,
            headers=GZIP,
            cpus=CLIENT_CPUS,
            script=HERE / "distinct.lua",
            script_args=(SELECT,),
        )
        report.info(
            "wrk -t2 -c256, select",
            f"{r.requests_per_s:.0f} answers/s, p99 of all answers {r.p99_ms:.0f} ms, "
            f"{r.non_2xx_3xx:,} non-2xx of {r.requests:,}",
        )
        timeouts = r.socket_errors["timeout"]
        report.line("wrk -c256: socket timeouts", f"{timeouts}", "0", timeouts == 0)
    # the same load on a bare endpoint: what this machine and wrk give at 256 connections
    with server("bench.ceiling_app:app", factory=False) as (ceiling_port, _):
        url = f"http://127.0.0.1:{ceiling_port}/ceiling"
        c = wrk.run(url, seconds, connections=256, headers=GZIP, cpus=CLIENT_CPUS)
    report.info(
        "wrk -t2 -c256, bare ceiling app",
        f"{c.requests_per_s:.0f} answers/s, p99 {c.p99_ms:.0f} ms, "
        f"socket timeouts {c.socket_errors['timeout']}",
    )


# --- hostile heads ---------------------------------------------------------------------


def _send_head(port: int, head: bytes, filler_bytes: int) -> bytes:
    """Send ``head`` then up to ``filler_bytes`` of one header value, stopping when the
    server answers or closes; the first bytes of its answer."""
    piece = b"a" * 65536
    sent = 0
    with socket.create_connection(("127.0.0.1", port), timeout=30) as sock:
        sock.sendall(head)
        while sent < filler_bytes and not select.select([sock], [], [], 0)[0]:
            try:
                sock.sendall(piece)
            except OSError:
                break
            sent += len(piece)
        try:
            return sock.recv(64)
        except OSError:
            return b""


def _statuses(answers: list[bytes]) -> str:
    counts: dict[str, int] = {}
    for answer in answers:
        status = answer[9:12].decode() if answer.startswith(b"HTTP/") else "closed"
        counts[status] = counts.get(status, 0) + 1
    return ", ".join(f"{status}: {n:,}" for status, n in sorted(counts.items()))


def hostile_heads(report: Report) -> None:
    report.section("Hostile request heads against one worker (server RSS)")
    restore = b"GET %s HTTP/1.1\r\nHost: bench\r\nHX-History-Restore-Request: "
    select_path = (SELECT % 100).encode()
    with cli_server() as (port, pid):
        start = rss_kib(pid)
        report.info("RSS at start", f"{start / 1024:.1f} MiB")
        answers = [_send_head(port, restore % select_path, MB) for _ in range(1000)]
        after_1mb = rss_kib(pid)
        report.info("1,000 requests, 1 MB header each", _statuses(answers))
        report.line(
            "RSS after 1,000 x 1 MB headers",
            f"{after_1mb / 1024:.1f} MiB",
            "< start + 50 MiB",
            after_1mb < start + 50 * 1024,
        )
        with ThreadPoolExecutor(max_workers=20) as pool:
            unfinished = list(
                pool.map(lambda _: _send_head(port, b"GET / HTTP/1.1\r\nX-A: ", 20 * MB), range(20))
            )
        report.info("20 unfinished 20 MB headers", _statuses(unfinished))
        with ThreadPoolExecutor(max_workers=10) as pool:
            concurrent = list(
                pool.map(lambda _: _send_head(port, b"GET / HTTP/1.1\r\nX-B: ", 50 * MB), range(10))
            )
        report.info("10 concurrent 50 MB headers", _statuses(concurrent))
        after_big = rss_kib(pid)
        report.line(
            "RSS after the 20 MB and 50 MB headers",
            f"{after_big / 1024:.1f} MiB",
            "< start + 50 MiB",
            after_big < start + 50 * 1024,
        )
        under = []
        for i in range(1000):
            value = b"%06d" % i + b"v" * 30_000
            head = restore % select_path + value + b"\r\nConnection: close\r\n\r\n"
            under.append(_send_head(port, head, 0))
        after_under = rss_kib(pid)
        report.info("1,000 requests, 30 kB header each", _statuses(under))
        report.line(
            "RSS after 1,000 x 30 kB headers (served)",
            f"{after_under / 1024:.1f} MiB",
            "< start + 50 MiB",
            after_under < start + 50 * 1024,
        )
        status = fetch(port, "/api/v1/health")[0]
        report.line("health check afterwards", f"{status}", "200", status == 200)


# --- slow-header flood through nginx ----------------------------------------------------


def flood_through_nginx(report: Report, tmp: Path) -> None:
    report.section("Slow-header flood through nginx (deploy/) in front of two app processes")
    if not Path(NGINX).exists():
        print("  nginx not found: install it with `apt-get install nginx`.")
        report.line("slow-header flood", "not measured", "nginx installed", None)
        return
    with nginx_in_front(tmp) as port:
        stop = threading.Event()
        still_open: list[int] = []
        flood = threading.Thread(target=trickle, args=(port, 200, stop, still_open))
        flood.start()
        latencies, statuses = [], []
        try:
            time.sleep(2)
            for i in range(100):
                started = time.monotonic()
                status = fetch(port, SELECT % (100 + i), GZIP)[0]
                latencies.append(time.monotonic() - started)
                statuses.append(status)
        finally:
            stop.set()
            flood.join()
        report.info("flood", f"200 sockets, half a head then 1 byte/s; open: {min(still_open)}")
        served = statuses.count(200)
        report.line("normal requests answered 200", f"{served} of 100", "100", served == 100)
        p50 = statistics.median(latencies) * 1e3
        slowest = max(latencies) * 1e3
        report.info("normal requests, p50", f"{p50:.0f} ms")
        report.line("normal requests, slowest", f"{slowest:.0f} ms", "< 1000 ms", slowest < 1000)


def run(report: Report, *, seconds: int, tmp: Path) -> None:
    if not wrk.available():
        report.section("Hostile load")
        print(f"  {wrk.INSTALL_HINT}")
        report.line("hostile-load figures", "not measured", "wrk installed", None)
        return
    overload(report, seconds)
    hostile_heads(report)
    flood_through_nginx(report, tmp)
