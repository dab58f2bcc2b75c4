"""After a shed request (503, Retry-After) nothing more is read from its connection for
the Retry-After, so 64 clients asking again at once cannot keep the event loop refusing
them while the health check waits (issue 31, item 2); a connection through the proxy
(X-Forwarded-For) is read on at once; SIGTERM ends the pause, and what was sent
meanwhile is answered with ``Connection: close``, never reset.

The console script as deployed, one unit of work allowed (``MAX_REQUESTS_IN_FLIGHT=1``):
a POST whose body has not been sent yet holds that unit for as long as the test likes,
so every other select is shed, without a race.
"""

import os
import select
import signal
import socket
import subprocess
import sys
from pathlib import Path

from deploy.local import free_port, wait_until_healthy
from tests.server.test_shutdown import _request, _responses, _until_closed

ROOT = Path(__file__).resolve().parents[2]
SELECT = "/api/v1/select?load_n=100&speed_mm_s=50&length_mm=500"
BODY = b'{"load_n": 100, "speed_mm_s": 50, "length_mm": 500}'
RETRY_AFTER_S = 30


def _answer(sock: socket.socket) -> tuple[int, dict[str, str]]:
    """Read one whole response (head and Content-Length body): (status, headers)."""
    data = b""
    while b"\r\n\r\n" not in data:
        chunk = sock.recv(65536)
        assert chunk, "closed before an answer"
        data += chunk
    head, _, body = data.partition(b"\r\n\r\n")
    length = int(head.lower().split(b"content-length:")[1].split(b"\r\n")[0])
    while len(body) < length:
        body += sock.recv(65536)
    ((status, headers),) = _responses(head + b"\r\n\r\n" + body[:length])
    return status, headers


def _shed(sock: socket.socket, extra: bytes = b"") -> tuple[int, dict[str, str]]:
    sock.sendall(_request(SELECT).replace(b"\r\n\r\n", b"\r\n" + extra + b"\r\n"))
    return _answer(sock)


def test_a_shed_connection_is_read_again_after_retry_after_or_at_sigterm() -> None:
    port = free_port()
    env = {
        **os.environ,
        "LEADSCREW_MAX_REQUESTS_IN_FLIGHT": "1",
        "LEADSCREW_OVERLOAD_RETRY_AFTER_S": str(RETRY_AFTER_S),
    }
    cmd = [sys.executable, "-m", "app.cli", "--port", str(port), "--log-level", "warning"]
    proc = subprocess.Popen(
        cmd, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT
    )
    socks: list[socket.socket] = []
    try:
        wait_until_healthy(port, proc, "app.cli")  # type: ignore[arg-type]
        holder, shed, proxied, other = socks = [
            socket.create_connection(("127.0.0.1", port), timeout=30) for _ in range(4)
        ]
        # the POST's head only: admitted, it holds the one unit while it waits for its body
        holder.sendall(
            f"POST /api/v1/select HTTP/1.1\r\nHost: test\r\nContent-Type: application/json\r\n"
            f"Content-Length: {len(BODY)}\r\n\r\n".encode()
        )
        for _ in range(100):  # until the POST is admitted: from then on, every select is shed
            status, headers = _shed(shed)
            if status == 503:
                break
        assert (status, headers["retry-after"]) == (503, str(RETRY_AFTER_S))
        shed.sendall(_request("/api/v1/health"))  # asked again at once: read after the pause

        status, _ = _shed(proxied, b"X-Forwarded-For: 203.0.113.7\r\n")
        assert status == 503
        proxied.sendall(_request("/api/v1/health"))
        assert _answer(proxied)[0] == 200  # through the proxy: read on at once

        other.sendall(_request("/api/v1/health"))
        assert _answer(other)[0] == 200  # the health check on another connection
        ready, _, _ = select.select([shed], [], [], 0.5)
        assert ready == [], "the shed connection was read before its Retry-After"

        holder.sendall(BODY)
        assert _answer(holder)[0] == 200
        proc.send_signal(signal.SIGTERM)
        data, end = _until_closed(shed)
        output, _ = proc.communicate(timeout=30)
    finally:
        for sock in socks:
            sock.close()
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 0, output
    # the request sent during the pause, answered once the stop ended it, then a clean close
    assert end == "closed"
    ((status, headers),) = _responses(data)
    assert (status, headers["connection"]) == (200, "close")
