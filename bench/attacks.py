"""The attacks of issues 23 and 31, each run again against the server as shipped: "held" when
the defence holds, "BROKEN" when the attack gets through.

1. Overload through nginx (deploy/): 256 connections of distinct selects; shedding must
   not turn into 502s, the health check must stay up, 429s carry Retry-After and
   error.log stays small.
2. Floods of one worker (64 connections, a different query each) while the health check
   is polled: ``detail=full&limit=100``, ``/catalog`` and results pages of a hundred
   (issue 31, item 2); its 99th percentile under 1 s, its slowest under the probes'
   timeout (deploy/k8s).
3. Idle sockets past the connection limit: the health check answers, other requests get
   503 with Retry-After and the security headers.
4. Advice at the edge of the inputs and a forged typed record: no 500.
5. Share links of numbers typed with many figures: the same answer, every link served.
6. Hostile catalog files from LEADSCREW_CATALOG_DIRS: exit 2 naming the file.
7. X-Cache and bad command-line values.
8. The Kubernetes manifests: preStop, PodDisruptionBudget, probe timeouts above the
   health latency measured in 2.
9. Issue 31: ``--catalog-dir`` with one worker and two; full forms in disguise
   (``detail=ful%6C``, a limit in the body) counted by their cost; numbers past any float
   and a hot axis without a 500; share links that reproduce the API and a motor curve;
   the 405's Allow; what the cache's timing reveals. (Its hostile catalog files are in 6,
   its command-line values in 7.) Its item 7 (9.7): nginx's access log under a flood of
   429s from one address, and SIGTERM under 16 kept-alive clients.

Figures are taken on whatever else the machine is doing; each attack runs seconds.
"""

import http.client
import json
import multiprocessing
import os
import random
import re
import socket
import statistics
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from concurrent.futures import ProcessPoolExecutor
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import yaml

from bench import load, wrk
from bench.hostile import cli_server
from bench.report import Report
from deploy.local import NGINX, free_port, nginx_in_front, stop, wait_until_healthy

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "my-family" / "my-family.toml"
SELECT = "/api/v1/select?load_n=%s&speed_mm_s=50&length_mm=500&lead_mm=10"
COSTLY = SELECT.replace("&lead_mm=10", "") + "&detail=full&limit=100"
HEALTH = "/api/v1/health"
#: how often the health check is polled during an attack, as a balancer or kubelet would
POLL_S = 0.25
SPAWN = multiprocessing.get_context("spawn")
PROBE_ADDRESS = "127.0.0.2"


def held(report: Report, name: str, value: str, ok: bool) -> None:
    """One attack's verdict: held, or broken."""
    report.attack(name, value, ok)


def manifests() -> dict[str, dict[str, Any]]:
    """The Kubernetes manifests of deploy/k8s by kind."""
    docs = [
        doc
        for path in sorted((ROOT / "deploy" / "k8s").glob("*.yaml"))
        for doc in yaml.safe_load_all(path.read_text())
        if doc
    ]
    return {doc["kind"]: doc for doc in docs}


def container() -> dict[str, Any]:
    """The app's container in the Deployment."""
    (app,) = manifests()["Deployment"]["spec"]["template"]["spec"]["containers"]
    return app


def get(
    port: int, path: str, headers: dict[str, str] | None = None, source: str = "127.0.0.1"
) -> tuple[int, dict[str, str], bytes]:
    """One GET on a new connection from address ``source``: (status, headers in lower
    case, body)."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10, source_address=(source, 0))
    try:
        conn.request("GET", path, headers=headers or {})
        resp = conn.getresponse()
        return resp.status, {k.lower(): v for k, v in resp.getheaders()}, resp.read()
    finally:
        conn.close()


def poll_health(
    port: int, stop: threading.Event, answers: list[tuple[int, float]], poll_s: float = POLL_S
) -> None:
    """Ask for the health check every ``poll_s`` until ``stop``, from an address of its own
    (127.0.0.2: nginx limits per address, and a balancer is not the attacker): (status,
    seconds) each; status 0 when it was not answered within 10 s."""
    while not stop.wait(poll_s):
        started = time.monotonic()
        try:
            status = get(port, HEALTH, source=PROBE_ADDRESS)[0]
        except OSError:
            status = 0
        answers.append((status, time.monotonic() - started))


def _load(port: int, path: str, connections: int, seconds: float) -> load.LoadResult:
    return load.run(port, path, connections=connections, seconds=seconds, timeout_s=10)


def under_load(
    port: int, path: str, connections: int, seconds: float, poll_s: float = POLL_S
) -> tuple[load.LoadResult, list[tuple[int, float]]]:
    """``connections`` clients on ``path`` for ``seconds`` while the health check is polled
    every ``poll_s``."""
    stop = threading.Event()
    health: list[tuple[int, float]] = []
    poller = threading.Thread(target=poll_health, args=(port, stop, health, poll_s))
    poller.start()
    try:
        # the clients in a process of their own: here they would hold the GIL the poller
        # needs, and its timings would be the client's, not the server's
        with ProcessPoolExecutor(max_workers=1, mp_context=SPAWN) as pool:
            result = pool.submit(_load, port, path, connections, seconds).result()
    finally:
        stop.set()
        poller.join()
    return result, health


def health_figures(health: list[tuple[int, float]]) -> tuple[int, float, float]:
    """(checks answered 200, p50 and slowest latency [s] of all checks)."""
    latencies = sorted(latency for _, latency in health) or [float("nan")]
    ok = sum(1 for status, _ in health if status == 200)
    return ok, statistics.median(latencies), latencies[-1]


def p99(health: list[tuple[int, float]]) -> float:
    """The 99th percentile of the checks' latencies [s] (the slowest of fewer than 100)."""
    latencies = sorted(latency for _, latency in health) or [float("nan")]
    return latencies[min(len(latencies) - 1, int(0.99 * len(latencies)))]


# --- 1. overload through nginx ------------------------------------------------------------


def _refusal(port: int) -> tuple[int, dict[str, str]]:
    """Static files from one address faster than nginx's rate: (how many of 600 were
    refused 429, the headers of one refusal)."""
    refused: list[dict[str, str]] = []

    def burst(_: int) -> None:
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
        for _ in range(100):
            conn.request("GET", "/static/css/app.css")
            response = conn.getresponse()
            response.read()
            if response.status == 429:
                refused.append({k.lower(): v for k, v in response.getheaders()})
        conn.close()

    threads = [threading.Thread(target=burst, args=(i,)) for i in range(6)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return len(refused), refused[0] if refused else {}


def overload_through_nginx(report: Report, seconds: float, tmp: Path) -> None:
    report.section("1. Overload through nginx: 256 connections, a different select each")
    report.info("apps", "two, MAX_REQUESTS_IN_FLIGHT=4 (the 64 connections nginx admits shed)")
    if not Path(NGINX).exists():
        report.line("1. nginx", "not measured", "nginx installed", None)
        return
    tmp.mkdir()
    # per-address limits let 64 connections through; processes that take 4 units of work
    # at a time shed most of them, as many more addresses would make them shed
    with nginx_in_front(tmp, env={"LEADSCREW_MAX_REQUESTS_IN_FLIGHT": "4"}) as port:
        result, health = under_load(port, SELECT.replace("%s", "%.3f"), 256, seconds)
        refused, headers = _refusal(port)
        log = tmp / "logs" / "error.log"
        log_bytes = log.stat().st_size
        limiting = log.read_text(errors="replace").count("limiting")
    ok, p50, slowest = health_figures(health)
    report.info("answers", _statuses(result))
    report.info("health checks (from another address)", f"{ok} of {len(health)} answered 200")
    report.info("health p50, slowest", f"{p50 * 1e3:.0f} ms, {slowest * 1e3:.0f} ms")
    bad_gateway = len(result.latencies_s.get(502, []))
    held(report, "1. no 502 while the apps shed", f"{bad_gateway} x 502", bad_gateway == 0)
    held(report, "1. health checks through nginx", f"{ok} of {len(health)}",
         ok == len(health) > 0)  # fmt: skip
    retry = headers.get("retry-after", "none")
    report.info("429s in a 600-request static burst", f"{refused}")
    held(report, "1. 429 carries Retry-After and CSP", f"Retry-After {retry}",
         refused > 0 and retry == "1" and "content-security-policy" in headers)  # fmt: skip
    report.info("error.log", f"{log_bytes:,} bytes, {limiting} lines about limiting")
    held(report, "1. error.log quiet under refusals", f"{log_bytes:,} B",
         limiting == 0 and log_bytes < 1024 * 1024)  # fmt: skip


# --- 2. costly valid queries --------------------------------------------------------------


#: the health check's 99th percentile under every flood of issue 31 (item 2)
HEALTH_P99_S = 1.0
#: health checks per second during a flood: enough for a 99th percentile in a few seconds
FLOOD_POLL_S = 0.05
#: issue 31's floods of one worker, 64 connections each: the costly API form, the catalog
#: page (81 ms to render, never cached: 7.9 s health p50 before), distinct results pages
#: of a hundred (4.7 s health p50 before); a different query on every request
FLOODS = {
    "detail=full&limit=100": COSTLY,
    "/catalog": "/catalog?r=%s",
    "results pages, limit=100": "/?load=%s&speed=50&length=500&limit=100",
}


def costly_queries(report: Report, seconds: float) -> float:
    """Attacks 2 and 2b; returns the slowest health check [s] (the probes' timeout must
    exceed it)."""
    report.section("2. Health under floods of one worker: 64 connections, a new query each")
    slowest_all = 0.0
    for name, path in FLOODS.items():
        with cli_server() as (port, _):
            result, health = under_load(port, path.replace("%s", "%.3f"), 64, seconds,
                                        FLOOD_POLL_S)  # fmt: skip
        ok, p50, slowest = health_figures(health)
        slowest_all = max(slowest_all, slowest)
        tail = p99(health)
        report.info(f"{name}: answers", _statuses(result))
        report.info(f"{name}: health p50, p99, slowest", f"{p50 * 1e3:.0f} ms, "
                    f"{tail * 1e3:.0f} ms, {slowest * 1e3:.0f} ms ({ok} of {len(health)} "
                    "answered 200)")  # fmt: skip
        report.info(f"{name}: load average (1 min)", f"{os.getloadavg()[0]:.1f}")
        held(report, f"2. {name}: health p99 under {HEALTH_P99_S:g} s", f"{tail * 1e3:.0f} ms",
             ok == len(health) > 0 and tail < HEALTH_P99_S)  # fmt: skip
    timeout = container()["readinessProbe"]["timeoutSeconds"]
    held(report, f"2. health slowest (readiness timeout {timeout} s)",
         f"{slowest_all * 1e3:.0f} ms", slowest_all < timeout)  # fmt: skip
    return slowest_all


def _statuses(result: load.LoadResult) -> str:
    counts = ", ".join(f"{s}: {len(v):,}" for s, v in sorted(result.latencies_s.items()))
    return f"{counts}; timeouts {result.timeouts}, errors {result.errors}"


# --- 3. idle sockets past the connection limit --------------------------------------------


def idle_sockets(report: Report) -> None:
    report.section("3. 1,030 idle sockets against one worker (connection limit 1,024)")
    with cli_server() as (port, _):
        idle = [socket.create_connection(("127.0.0.1", port), timeout=5) for _ in range(1030)]
        try:
            time.sleep(0.5)  # every socket accepted
            health = get(port, HEALTH)
            refused = get(port, SELECT % 100)
        finally:
            for sock in idle:
                sock.close()
    report.info("health, select", f"{health[0]}, {refused[0]}")
    held(report, "3. health answered past the limit", f"{health[0]}", health[0] == 200)
    headers = refused[1]
    ok = refused[0] == 503 and headers.get("retry-after") == "1"
    held(report, "3. 503 with Retry-After and CSP", f"{refused[0]}",
         ok and "content-security-policy" in headers)  # fmt: skip


# --- 4. advice at the edge of the inputs ----------------------------------------------------

EDGE_PAGES = {
    "no load admits the screw": "/?load=0&speed=50&length=500&moving_mass_kg=800"
    "&orientation=vertical",
    "forged typed record": "/?load=50&speed=50&length=500&typed_load=50|evil"
    "&from_force_unit=N&force_unit=lbf",
}


def advice(report: Report) -> None:
    report.section("4. Advice at the edge of the inputs, and a forged typed record")
    with cli_server() as (port, _):
        api = json.loads(get(port, "/api/v1/select?load_n=0&speed_mm_s=50&length_mm=500"
                                   "&moving_mass_kg=800&orientation=vertical")[2])  # fmt: skip
        for name, path in EDGE_PAGES.items():
            status, _, body = get(port, path)
            held(report, f"4. {name}", f"{status}, {len(body):,} B", status == 200)
    message = api["summary"]["message"]
    negative = re.findall(r" -\d[\d.]*", message)
    held(report, "4. no negative value proposed", f"{len(negative)} found", not negative)


# --- 5. share links -------------------------------------------------------------------------

TYPED_PAGES = (
    "/?load=100&lead=10&speed=50&length=3937.0078&length_unit=in",
    "/?load=100.4824&lead=10&speed=50&length=500&force_unit=lbf",
    "/?load=100.4824&speed=50.00004&length=500",
)
VERDICT = re.compile(r'class="count-passed">(\d+)<|class="verdict"')


def _links(page: str) -> tuple[str, list[str]]:
    """(the share link, the detail and export links) of a results page."""
    share = re.search(r'class="share-link" href="([^"]+)"', page)
    others = re.findall(r'class="(?:export|detail-link)" href="([^"]+)"', page)
    return share.group(1).replace("&amp;", "&") if share else "", [
        o.replace("&amp;", "&") for o in others
    ]


def share_links(report: Report) -> None:
    report.section("5. Share links of numbers typed with many figures")
    with cli_server() as (port, _):
        for path in TYPED_PAGES:
            page = get(port, path)[2].decode()
            share, others = _links(page)
            again = get(port, share)[2].decode() if share else ""
            same = bool(share) and VERDICT.findall(page) == VERDICT.findall(again)
            statuses = [get(port, link)[0] for link in others]
            ok = same and bool(statuses) and set(statuses) == {200}
            held(report, f"5. {path[2:34]}...", f"link {'same' if same else 'differs'}, "
                 f"{statuses.count(200)}/{len(statuses)} links 200", ok)  # fmt: skip


# --- 6. hostile catalog files -----------------------------------------------------------------


def _catalog_cases(tmp: Path) -> dict[str, Path]:
    """A directory per hostile file: name -> directory."""
    cases: dict[str, Callable[[Path], None]] = {
        "deep.toml": lambda p: p.write_text("a = " + "[" * 5000 + "]" * 5000 + "\n"),
        "zero.toml": lambda p: p.symlink_to("/dev/zero"),
        "fifo.toml": lambda p: os.mkfifo(p),
        "large.toml": lambda p: p.write_bytes(b"# " + b"x" * 100 * 1024 * 1024),
        "my-family.toml": lambda p: p.write_text(
            EXAMPLE.read_text().replace("value = [4] }", "value = [4000000000] }")
        ),
        # issue 31: a table 500 deep, a 100 GB id width, a built-in family's id, OD 0.8 P 2
        "table.toml": lambda p: p.write_text("[" + ".".join(["a"] * 500) + "]\nx = 1\n"),
        "width.toml": lambda p: p.write_text(
            EXAMPLE.read_text().replace("{d_mm:g}", "{d_mm:99999999999}")
        ),
        "family-b.toml": lambda p: p.write_text(
            EXAMPLE.read_text().replace('id = "MY"', 'id = "B"')
        ),
        "root.toml": lambda p: p.write_text(
            EXAMPLE.read_text().replace("mm = { value = 8.0 }", "mm = { value = 0.8 }")
        ),
    }
    dirs = {}
    for name, make in cases.items():
        directory = tmp / f"catalog-{name}"
        directory.mkdir()
        make(directory / name)
        dirs[name] = directory
    return dirs


def _start(args: list[str], env: dict[str, str]) -> tuple[int, str, float]:
    """``python -m app.cli ARGS`` until it exits (at most 60 s): (exit status, stderr, s)."""
    started = time.monotonic()
    try:
        done = subprocess.run(
            [sys.executable, "-m", "app.cli", *args],
            cwd=ROOT,
            env={**os.environ, **env},
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
        )
    except subprocess.TimeoutExpired:
        return -1, "still running after 60 s", time.monotonic() - started
    return done.returncode, done.stderr, time.monotonic() - started


def catalog_files(report: Report, tmp: Path) -> None:
    report.section("6. Hostile catalog files in LEADSCREW_CATALOG_DIRS, two workers")
    for name, directory in _catalog_cases(tmp).items():
        env = {"LEADSCREW_CATALOG_DIRS": json.dumps([str(directory)])}
        status, err, seconds = _start(["--port", "1", "--workers", "2"], env)
        ok = status == 2 and name in err and "Traceback" not in err
        ok = ok and (name != "family-b.toml" or "b-series.toml" in err)  # both files named
        held(report, f"6. {name}", f"exit {status} in {seconds:.1f} s", ok)
        report.info("   says", err.strip().splitlines()[-1][:90] if err.strip() else "")


# --- 7. X-Cache and bad command-line values -------------------------------------------------


def leaks_and_options(report: Report) -> None:
    report.section("7. Whether someone ran these inputs; bad command-line values")
    with cli_server() as (port, _):
        answers = [get(port, SELECT % 123.456)[1] for _ in range(2)]
    told = [h["x-cache"] for h in answers if "x-cache" in h]
    held(report, "7. a repeated query looks like a new one", f"X-Cache {told or 'absent'}",
         not told and answers[0].keys() == answers[1].keys())  # fmt: skip
    for args in (["--port", "80000"], ["--workers", "-3"], ["--workers", "1_0"], ["--port", " 80"]):
        status, err, _ = _start(args, {})
        held(report, f"7. {' '.join(args)}", f"exit {status}",
             status == 2 and "Traceback" not in err)  # fmt: skip


# --- 8. Kubernetes ----------------------------------------------------------------------------


def kubernetes(report: Report, slowest_health_s: float) -> None:
    report.section("8. Kubernetes manifests against the health latency of attack 2")
    kinds = manifests()
    app = container()
    stop = app.get("lifecycle", {}).get("preStop")
    held(report, "8. preStop pause", f"{stop}", stop is not None)
    held(report, "8. PodDisruptionBudget", "present" if "PodDisruptionBudget" in kinds else
         "absent", "PodDisruptionBudget" in kinds)  # fmt: skip
    for probe in ("readinessProbe", "livenessProbe"):
        timeout = app[probe]["timeoutSeconds"]
        held(report, f"8. {probe} timeout vs health slowest",
             f"{timeout} s vs {slowest_health_s:.2f} s", timeout > slowest_health_s)  # fmt: skip


# --- 9. issue 31 -------------------------------------------------------------------------------


@contextmanager
def _served(*args: str, env: dict[str, str] | None = None) -> Iterator[int]:
    """``python -m app.cli ARGS`` on a free port until the block ends; the port."""
    port = free_port()
    cmd = [sys.executable, "-m", "app.cli", "--port", str(port), "--log-level", "warning", *args]
    proc = subprocess.Popen(cmd, cwd=ROOT, env={**os.environ, **(env or {})})
    try:
        wait_until_healthy(port, proc, "app.cli")
        yield port
    finally:
        stop(proc)


def catalog_dir_option(report: Report) -> None:
    report.section("9.1 --catalog-dir with one worker and with two")
    for workers in ("1", "2"):
        with _served("--catalog-dir", str(EXAMPLE.parent), "--workers", workers) as port:
            status = get(port, "/api/v1/series/MY-Tr8-P2")[0]
        held(report, f"9.1 family MY served, {workers} worker(s)", f"{status}", status == 200)


def _together(port: int, requests: list[Callable[[http.client.HTTPConnection], None]]) -> list[int]:
    """Each request on a connection of its own, sent at the same moment: the statuses."""
    barrier = threading.Barrier(len(requests))
    statuses: list[int] = []

    def one(send: Callable[[http.client.HTTPConnection], None]) -> None:
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
        barrier.wait()
        send(conn)
        response = conn.getresponse()
        response.read()
        statuses.append(response.status)
        conn.close()

    threads = [threading.Thread(target=one, args=(send,)) for send in requests]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return statuses


def _encoded(i: int) -> Callable[[http.client.HTTPConnection], None]:
    query = f"load_n={100 + i}&speed_mm_s=50&length_mm=500&detail=ful%6C&limit=1%300"
    return lambda conn: conn.request("GET", f"/api/v1/select?{query}")


def _in_body(i: int) -> Callable[[http.client.HTTPConnection], None]:
    body = json.dumps({"load_n": 200 + i, "speed_mm_s": 50, "length_mm": 500, "limit": 100})
    headers = {"Content-Type": "application/json"}
    return lambda conn: conn.request("POST", "/api/v1/select?detail=full", body, headers)


def overload_cost(report: Report) -> None:
    report.section("9.3 Full forms in disguise against 13 units: one at a time, the rest shed")
    env = {"LEADSCREW_MAX_REQUESTS_IN_FLIGHT": "13", "LEADSCREW_RESPONSE_CACHE_BYTES": "0"}
    with _served(env=env) as port:
        for name, make in (("detail=ful%6C&limit=1%300", _encoded), ("limit in body", _in_body)):
            statuses = _together(port, [make(i) for i in range(8)])
            shed = statuses.count(503)
            report.info(f"   {name}", ", ".join(map(str, sorted(statuses))))
            held(report, f"9.3 {name} counted 13 units", f"{shed} of 8 shed", shed > 0)


BIG_NUMBERS = (
    "/?load=1e308&speed=50&length=500&force_unit=lbf",
    "/?load=50&speed=50&length=1e308&length_unit=in",
    "/?load=50&speed=50&length=500&accel=1e308&length_unit=in",
    "/?load=1e308&speed=50&length=500&force_unit=kgf",
    "/export.csv?load=1e308&speed=50&length=500&force_unit=lbf",
    "/?load=0.001&speed=3000&length=70&ambient_c=250&motor=17hs19-2004s1",
)


def no_server_errors(report: Report) -> None:
    report.section("9.4 Numbers past any float, a hot axis: no 500")
    with _served() as port:
        for path in BIG_NUMBERS:
            status = get(port, path)[0]
            held(report, f"9.4 {path[:46]}", f"{status}", status in (200, 422))


def _passed(page: bytes) -> list[str]:
    return re.findall(r'class="count-passed">(\d+)<', page.decode())


def reproducing_links(report: Report) -> None:
    report.section("9.5 The API's share_url and a motor curve's link reproduce the answer")
    bodies = ({"nut_material": "bronze "}, {"nut_material": "ANY"}, {"family": ["B "]})
    with _served() as port:
        for body in bodies:
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
            payload = {"load_n": 50, "speed_mm_s": 50, "length_mm": 500, **body}
            conn.request("POST", "/api/v1/select", json.dumps(payload),
                         {"Content-Type": "application/json"})  # fmt: skip
            answer = json.loads(conn.getresponse().read())
            conn.close()
            api = answer["summary"]["message"].split(" of ")[0].replace("No", "0")
            page = _passed(get(port, answer["share_url"])[2])
            held(report, f"9.5 {body}", f"API {api}, link {page}", page == [api])
        curve = "/?load=1&speed=50&length=500&lead=4&motor_curve=0+1%0A749.9999992498+1"
        typed = get(port, curve)[2]
        link = re.search(rb'class="share-link" href="([^"]+)"', typed)
        again = get(port, link.group(1).decode().replace("&amp;", "&"))[2] if link else b""
        held(report, "9.5 curve to 749.9999992498 rpm", f"form {_passed(typed)}, "
             f"link {_passed(again)}", bool(link) and _passed(typed) == _passed(again))  # fmt: skip
        for text in ("0+1%2F2%0A3000+1%2F4", "0+0%2C5%0A3000+0%2C25"):
            page = get(port, f"/?load=1&speed=50&length=500&motor_curve={text}")[2]
            ok = b'id="e-motor_curve"></' in page
            held(report, f"9.5 curve {text[:22]}", "read" if ok else "refused", ok)


def small_ones(report: Report) -> None:
    report.section("9.8 Allow on a 405; what the cache's timing tells")
    with _served() as port:
        for path in ("/api/v1/select", "/api/v1/pairs"):
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
            conn.request("PUT", path)
            response = conn.getresponse()
            response.read()
            conn.close()
            allow = response.getheader("allow", "")
            held(report, f"9.8 405 on {path}", allow, {"GET", "POST"} <= set(allow.split(", ")))
        times: list[tuple[float, float]] = []
        for i in range(20):
            path = SELECT % (300 + i)
            started = time.monotonic()
            get(port, path)
            middle = time.monotonic()
            get(port, path)
            times.append((middle - started, time.monotonic() - middle))
    miss = statistics.median(t for t, _ in times) * 1e3
    hit = statistics.median(t for _, t in times) * 1e3
    told = sum(1 for m, h in times if h < m)
    report.info("   miss, hit median", f"{miss:.1f} ms, {hit:.1f} ms; hit faster in {told} of 20")
    readme = (ROOT / "README.md").read_text()
    honest = "its speed does" in readme and "LEADSCREW_RESPONSE_CACHE_BYTES=0" in readme
    held(report, "9.8 README says what the cache's timing reveals", f"{honest}", honest)


# --- 9.7 issue 31, item 7: logs and shutdown under floods -------------------------------------

#: access-log lines per refusal at most: one in a hundred is sampled (deploy/)
LOG_LINES_PER_REFUSAL = 0.02


def refusal_log(report: Report, seconds: float, tmp: Path) -> None:
    report.section("9.7 nginx's access log under a flood of 429s from one address")
    if not (Path(NGINX).exists() and wrk.available()):
        report.line("9.7 access log", "not measured", "nginx and wrk installed", None)
        return
    tmp.mkdir()
    with nginx_in_front(tmp, apps=1) as port:
        result = wrk.run(f"http://127.0.0.1:{port}/static/css/app.css", int(seconds),
                         connections=16)  # fmt: skip
    # nginx has stopped: its buffered lines are written
    log = tmp / "logs" / "access.log"
    log_bytes = log.stat().st_size
    lines = log.read_text(errors="replace").count('" 429 ')
    refused = result.non_2xx_3xx
    report.info("requests, 429s", f"{result.requests:,}, {refused:,} in {seconds:g} s")
    report.info("access.log", f"{log_bytes:,} B ({log_bytes / seconds / 1e3:.0f} kB/s), "
                f"{lines:,} lines of 429")  # fmt: skip
    held(report, "9.7 429s sampled in the access log", f"{lines / max(refused, 1):.4f} lines each",
         refused > 1000 and lines / refused <= LOG_LINES_PER_REFUSAL)  # fmt: skip


def _keep_asking(port: int, stop_at: threading.Event, log: list[tuple[float, str]]) -> None:
    """One kept-alive client asking for the health check again and again, up to 20 ms
    apart (idle in between, as a browser's or a balancer's connection is), until the
    connection ends or ``stop_at``: (when the request was sent, how it ended) each, how
    being 'answered', 'answered, close', 'closed' (end of stream) or 'reset'."""
    sock = socket.create_connection(("127.0.0.1", port), timeout=30)
    request = b"GET /api/v1/health HTTP/1.1\r\nHost: bench\r\n\r\n"
    pause = random.Random(port * 1000 + threading.get_ident() % 1000)
    try:
        while not stop_at.wait(pause.uniform(0, 0.02)):
            sent = time.monotonic()
            try:
                sock.sendall(request)
                sent = time.monotonic()
                data = b""
                while b"\r\n\r\n" not in data:
                    chunk = sock.recv(65536)
                    if not chunk:
                        log.append((sent, "closed"))
                        return
                    data += chunk
            except (ConnectionResetError, BrokenPipeError):
                log.append((sent, "reset"))
                return
            head, _, body = data.partition(b"\r\n\r\n")
            match = re.search(rb"content-length: *(\d+)", head, re.I)
            length = int(match.group(1)) if match else 0
            while len(body) < length:
                body += sock.recv(65536)
            close = re.search(rb"connection: *close", head, re.I) is not None
            log.append((sent, "answered, close" if close else "answered"))
            if close:
                return
    finally:
        sock.close()


def stop_under_keep_alive(report: Report) -> None:
    report.section("9.7 SIGTERM under 16 kept-alive clients, each asking every 0-20 ms")
    port = free_port()
    cmd = [sys.executable, "-m", "app.cli", "--port", str(port), "--log-level", "warning"]
    proc = subprocess.Popen(cmd, cwd=ROOT)
    log: list[tuple[float, str]] = []
    halt = threading.Event()
    try:
        wait_until_healthy(port, proc, "app.cli")
        clients = [threading.Thread(target=_keep_asking, args=(port, halt, log)) for _ in range(16)]
        for client in clients:
            client.start()
        time.sleep(1.0)
        signalled = time.monotonic()
        proc.terminate()
        for client in clients:
            client.join(timeout=30)
        halt.set()
        status = proc.wait(timeout=30)
    finally:
        halt.set()
        stop(proc)
    before = [how for sent, how in log if sent < signalled]
    after = [how for sent, how in log if sent >= signalled]
    lost = [how for how in before if not how.startswith("answered")]
    report.info("sent before the signal", _counted(before))
    report.info("sent after it", _counted(after))
    held(report, "9.7 requests sent before SIGTERM answered", f"{len(lost)} not answered",
         not lost and len(before) > 0)  # fmt: skip
    resets = sum(1 for _, how in log if how == "reset")
    held(report, "9.7 requests after it: no reset", f"{resets} reset", resets == 0)
    held(report, "9.7 exit status", f"{status}", status == 0)


def _counted(hows: list[str]) -> str:
    counts = {how: hows.count(how) for how in sorted(set(hows))}
    return ", ".join(f"{how}: {n:,}" for how, n in counts.items()) or "none"


def issue_31(report: Report) -> None:
    """The attacks of issue 31 (its items 1, 3, 4, 5, 6 (in 6 above) and 8)."""
    catalog_dir_option(report)
    overload_cost(report)
    no_server_errors(report)
    reproducing_links(report)
    small_ones(report)


def run(report: Report, *, seconds: float, tmp: Path) -> None:
    """Every attack, each for a few seconds."""
    overload_through_nginx(report, seconds, tmp / "nginx")
    slowest = costly_queries(report, seconds)
    idle_sockets(report)
    advice(report)
    share_links(report)
    catalog_files(report, tmp)
    leaks_and_options(report)
    kubernetes(report, slowest)
    issue_31(report)
    refusal_log(report, seconds, tmp / "nginx-refusals")
    stop_under_keep_alive(report)
