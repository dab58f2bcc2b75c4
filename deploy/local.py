"""The production setup run on this machine: app processes as ``leadscrew-selector``
starts them, nginx from ``nginx.conf.template`` in front of them, and a slow-header flood
against it. The deploy tests (tests/deploy/test_deploy.py) and the hostile-load bench
(bench/hostile.py) both drive it from here.
"""

import getpass
import http.client
import os
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
NGINX = "/usr/sbin/nginx"
HEALTH = "/api/v1/health"
#: The most a process may take to answer its health check: a ceiling against a hang, not
#: the expected wait (the wait ends as soon as it answers, or the process exits). Generous:
#: on the 2-core machine shared by several test runs, one worker each, a start has taken
#: over 60 s.
START_CEILING_S = 600.0


def free_port() -> int:
    """A TCP port on 127.0.0.1 that nothing listens on now."""
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def healthy(port: int, path: str = HEALTH) -> bool:
    """Whether ``path`` (the health check) on ``port`` answers 200."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=2)
    try:
        conn.request("GET", path)
        return conn.getresponse().status == 200
    except OSError:
        return False
    finally:
        conn.close()


def wait_until_healthy(
    port: int,
    proc: subprocess.Popen[bytes] | subprocess.Popen[str],
    what: str,
    path: str = HEALTH,
) -> None:
    """Wait for ``path`` (the health check) on ``port`` to answer 200; RuntimeError if
    ``proc`` exits first, or if it has not answered within ``START_CEILING_S``."""
    deadline = time.monotonic() + START_CEILING_S
    while not healthy(port, path):
        if proc.poll() is not None or time.monotonic() > deadline:
            raise RuntimeError(f"{what} did not start (exit {proc.poll()})")
        time.sleep(0.1)


def stop(proc: subprocess.Popen[bytes]) -> None:
    """Terminate ``proc``; kill it if it has not ended within 10 s."""
    proc.terminate()
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


def start_app(port: int, env: Mapping[str, str] | None = None) -> subprocess.Popen[bytes]:
    """One app process on ``port``, started as ``leadscrew-selector`` starts it, with
    ``env`` added to the environment (settings: ``LEADSCREW_*``)."""
    cmd = [sys.executable, "-m", "app.cli", "--port", str(port), "--log-level", "warning"]
    return subprocess.Popen(cmd, cwd=ROOT, env={**os.environ, **(env or {})})


@contextmanager
def nginx_in_front(
    prefix: Path, apps: int = 2, env: Mapping[str, str] | None = None
) -> Iterator[int]:
    """nginx (config from ``deploy/render.py``, checked with ``nginx -t``) in front of
    ``apps`` app processes (``env`` added to their environment), run from the prefix
    folder ``prefix``; yields nginx's port."""
    started: list[subprocess.Popen[bytes]] = []
    nginx = None
    try:
        upstreams = []
        for _ in range(apps):
            port = free_port()
            started.append(start_app(port, env))
            upstreams += ["--upstream", f"127.0.0.1:{port}"]
        for proc, address in zip(started, upstreams[1::2], strict=True):
            wait_until_healthy(int(address.rsplit(":", 1)[1]), proc, "app.cli")
        listen = free_port()
        render = [sys.executable, str(ROOT / "deploy" / "render.py"), "--listen"]
        render += [f"127.0.0.1:{listen}", *upstreams, "--static-root", str(ROOT / "static")]
        render += ["--user", getpass.getuser()]
        (prefix / "logs").mkdir(exist_ok=True)
        (prefix / "temp").mkdir(exist_ok=True)
        config = subprocess.run(render, capture_output=True, text=True, check=True).stdout
        (prefix / "nginx.conf").write_text(config)
        args = [NGINX, "-p", str(prefix), "-c", str(prefix / "nginx.conf")]
        args += ["-e", str(prefix / "logs" / "error.log")]
        subprocess.run([*args, "-t"], check=True, capture_output=True)
        nginx = subprocess.Popen([*args, "-g", "daemon off;"])
        wait_until_healthy(listen, nginx, "nginx")
        yield listen
    finally:
        if nginx is not None:
            stop(nginx)
        for proc in started:
            stop(proc)


def slow_header_flood(
    port: int, sockets: int, halt: threading.Event, open_counts: list[int]
) -> None:
    """Open ``sockets`` connections to ``port`` that send half a request head, then one
    header byte a second each until ``halt``; ``open_counts`` gets how many took the
    byte, each second."""
    flood = []
    for _ in range(sockets):
        sock = socket.create_connection(("127.0.0.1", port), timeout=5)
        sock.sendall(b"GET /api/v1/health HTTP/1.1\r\nHost: x\r\nX-Slow: ")
        flood.append(sock)
    while not halt.wait(1.0):
        alive = 0
        for sock in flood:
            try:
                sock.sendall(b"a")
                alive += 1
            except OSError:
                pass
        open_counts.append(alive)
    for sock in flood:
        sock.close()
