"""The server's own limits, against a real server started the way ``leadscrew-selector``
starts it (``python -m app.cli``), over real sockets.

Connections that send nothing, half a head or half a body are closed within the request
read timeout (2 s here; each test allows 10 s); heads past the size or count limit get
431 before the server has read much past the limit; the health check answers afterwards.
"""

import os
import select
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import httpx
import pytest

from app.server.security import SECURITY_HEADERS
from deploy.local import free_port, wait_until_healthy

ROOT = Path(__file__).resolve().parents[2]
READ_TIMEOUT_S = 2
KEEP_ALIVE_S = 1
#: how long a test waits for the server to close: well past the settings above
CLOSE_WITHIN_S = 10
MAX_HEADER_BYTES = 32 * 1024
MB = 1024 * 1024
#: every test uses the module's one server: they run on one xdist worker (``--dist loadgroup``)
pytestmark = pytest.mark.xdist_group("server-limits")
#: open connections past which requests are refused (1,024 by default; fewer sockets here)
MAX_CONNECTIONS = 64


def _status(port: int, path: str) -> int | None:
    try:
        return httpx.get(f"http://127.0.0.1:{port}{path}", timeout=5).status_code
    except httpx.HTTPError:
        return None


@pytest.fixture(scope="module")
def port() -> Iterator[int]:
    free = free_port()
    env = {
        **os.environ,
        "LEADSCREW_REQUEST_READ_TIMEOUT_S": str(READ_TIMEOUT_S),
        "LEADSCREW_KEEP_ALIVE_TIMEOUT_S": str(KEEP_ALIVE_S),
        "LEADSCREW_MAX_HEADER_BYTES": str(MAX_HEADER_BYTES),
        "LEADSCREW_MAX_CONNECTIONS": str(MAX_CONNECTIONS),
    }
    cmd = [sys.executable, "-m", "app.cli", "--port", str(free), "--log-level", "warning"]
    proc = subprocess.Popen(cmd, cwd=ROOT, env=env)
    try:
        wait_until_healthy(free, proc, "app.cli")
        yield free
    finally:
        proc.terminate()
        proc.wait(timeout=10)


def _closed_within(sock: socket.socket, seconds: float) -> tuple[bool, bytes]:
    """Read until the server closes; (closed in time, what it sent)."""
    sock.settimeout(seconds)
    received = b""
    deadline = time.monotonic() + seconds
    try:
        while time.monotonic() < deadline:
            data = sock.recv(65536)
            if not data:
                return True, received
            received += data
    except ConnectionResetError:
        return True, received
    except TimeoutError:
        pass
    return False, received


def test_a_connection_that_sends_nothing_is_closed(port: int) -> None:
    with socket.create_connection(("127.0.0.1", port)) as sock:
        closed, _ = _closed_within(sock, CLOSE_WITHIN_S)
    assert closed
    assert _status(port, "/api/v1/health") == 200


def test_half_sent_headers_are_closed_even_if_they_trickle(port: int) -> None:
    """A byte every half second keeps the connection busy but never finishes the head."""
    with socket.create_connection(("127.0.0.1", port)) as sock:
        sock.sendall(b"GET /api/v1/health HTTP/1.1\r\nHost: x\r\nX-Slow: ")
        started = time.monotonic()
        closed = False
        while time.monotonic() - started < CLOSE_WITHIN_S:
            try:
                sock.sendall(b"a")
            except OSError:
                closed = True
                break
            if select.select([sock], [], [], 0.5)[0]:
                closed, _ = _closed_within(sock, 1)
                if closed:
                    break
    assert closed, f"still open after {CLOSE_WITHIN_S} s"


def test_a_half_sent_body_is_closed(port: int) -> None:
    head = (
        "POST /api/v1/select HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
        "Content-Length: 100\r\n\r\n"
    )
    with socket.create_connection(("127.0.0.1", port)) as sock:
        sock.sendall(head.encode() + b'{"load_n": 1')
        closed, _ = _closed_within(sock, CLOSE_WITHIN_S)
    assert closed


def test_an_idle_keep_alive_connection_is_closed(port: int) -> None:
    with socket.create_connection(("127.0.0.1", port)) as sock:
        sock.sendall(b"GET /api/v1/health HTTP/1.1\r\nHost: x\r\n\r\n")
        closed, answer = _closed_within(sock, CLOSE_WITHIN_S)
    assert answer.startswith(b"HTTP/1.1 200")
    assert closed


def _send_head(port: int, head: bytes, filler_bytes: int) -> tuple[bytes, int]:
    """Send ``head``, then up to ``filler_bytes`` more of one header value in 64 KiB
    pieces, stopping as soon as the server answers; (answer, bytes sent)."""
    piece = b"a" * 65536
    sent = 0
    with socket.create_connection(("127.0.0.1", port), timeout=CLOSE_WITHIN_S) as sock:
        sock.sendall(head)
        while sent < filler_bytes and not select.select([sock], [], [], 0)[0]:
            try:
                sock.sendall(piece)
            except OSError:
                break
            sent += len(piece)
        _, answer = _closed_within(sock, CLOSE_WITHIN_S)
    return answer, sent


def test_a_megabyte_header_is_refused_with_431(port: int) -> None:
    head = b"GET /api/v1/select HTTP/1.1\r\nHost: x\r\nHX-History-Restore-Request: "
    answer, _ = _send_head(port, head, MB)
    assert answer.startswith(b"HTTP/1.1 431"), answer[:100]
    assert _status(port, "/api/v1/health") == 200


def test_concurrent_50mb_headers_are_refused_long_before_the_end(port: int) -> None:
    """The reported case: ten clients each sending a 50 MB header at once."""
    head = b"GET / HTTP/1.1\r\nHost: x\r\nX-Big: "
    with ThreadPoolExecutor(max_workers=10) as pool:
        results = list(pool.map(lambda _: _send_head(port, head, 50 * MB), range(10)))
    for answer, sent in results:
        assert answer.startswith(b"HTTP/1.1 431"), answer[:100]
        assert sent < 50 * MB // 4
    assert _status(port, "/api/v1/health") == 200


def test_too_many_headers_are_refused_with_431(port: int) -> None:
    lines = "".join(f"X-H{i}: 1\r\n" for i in range(150))
    with socket.create_connection(("127.0.0.1", port)) as sock:
        sock.sendall(f"GET /api/v1/health HTTP/1.1\r\nHost: x\r\n{lines}\r\n".encode())
        _, answer = _closed_within(sock, CLOSE_WITHIN_S)
    assert answer.startswith(b"HTTP/1.1 431"), answer[:100]


def test_headers_within_the_limits_are_served(port: int) -> None:
    headers = {f"X-H{i}": "v" * 200 for i in range(60)}
    response = httpx.get(f"http://127.0.0.1:{port}/api/v1/health", headers=headers, timeout=5)
    assert response.status_code == 200


def test_head_on_the_real_server_sends_no_body(port: int) -> None:
    """Two requests on one connection: had HEAD sent a body, the second answer would
    not start where the first one's head ends."""
    with socket.create_connection(("127.0.0.1", port), timeout=5) as sock:
        sock.sendall(
            b"HEAD /api/v1/health HTTP/1.1\r\nHost: x\r\n\r\n"
            b"GET /api/v1/health HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n"
        )
        _, answer = _closed_within(sock, CLOSE_WITHIN_S)
    first, _, rest = answer.partition(b"\r\n\r\n")
    assert first.startswith(b"HTTP/1.1 200") and b"content-length: " in first
    assert rest.startswith(b"HTTP/1.1 200")


def test_idle_sockets_past_the_connection_limit_leave_health_and_headers(port: int) -> None:
    """More idle sockets than the connection limit: the health check is still answered;
    any other request gets a 503 with Retry-After and the security headers, and its
    connection is closed (the place it held goes back)."""
    idle = [socket.create_connection(("127.0.0.1", port), timeout=5) for _ in range(70)]
    try:
        with httpx.Client(timeout=5) as client:
            refused = client.get(f"http://127.0.0.1:{port}/api/v1/select?load_n=1")
            # not every idle socket accepted yet (or some closed by the read timeout): more
            while refused.status_code != 503:
                assert len(idle) < 200, "no 503 past the connection limit"
                idle.append(socket.create_connection(("127.0.0.1", port), timeout=5))
                refused = client.get(f"http://127.0.0.1:{port}/api/v1/select?load_n=1")
            health = client.get(f"http://127.0.0.1:{port}/api/v1/health")
    finally:
        for sock in idle:
            sock.close()
    assert health.status_code == 200
    assert refused.status_code == 503 and refused.headers["retry-after"] == "1"
    assert refused.headers["connection"] == "close"
    assert refused.json()["error"] == "server busy"
    for name, value in SECURITY_HEADERS:
        assert refused.headers[name.decode()] == value.decode()
    deadline = time.monotonic() + CLOSE_WITHIN_S
    while _status(port, "/api/v1/select?load_n=1") != 422:  # served again once they close
        assert time.monotonic() < deadline
        time.sleep(0.2)
