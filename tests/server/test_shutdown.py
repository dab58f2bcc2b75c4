"""SIGTERM under kept-alive clients (issue 31, item 7): the console script as deployed,
16 connections that each have had an answer and stay open, requests sent just before the
signal and at moments after it.

A request sent before the signal must be answered in full; one sent after it is answered
(with ``Connection: close`` once the server has seen the signal) or meets a clean close
(end of stream, a FIN), never a reset; and the process exits 0. uvicorn's own shutdown
closed idle connections at once, so a request waiting unread in such a socket was reset.
"""

import contextlib
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

from app.server.protocol import SHUTDOWN_DRAIN_S
from deploy.local import free_port, wait_until_healthy

ROOT = Path(__file__).resolve().parents[2]
CONNECTIONS = 16
#: compact selects run on the event loop: sixteen of them keep it busy around the signal
SELECT = "/api/v1/select?load_n={load}&speed_mm_s=50&length_mm=500"
#: when each late request is sent after the signal [s]: before the server notices it (its
#: loop looks every 0.1 s), while idle connections drain, after they are half-closed
AFTER_S = (0.0, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6, SHUTDOWN_DRAIN_S + 0.5)


def _request(path: str) -> bytes:
    return f"GET {path} HTTP/1.1\r\nHost: test\r\n\r\n".encode()


def _responses(data: bytes) -> list[tuple[int, dict[str, str]]]:
    """The complete responses in ``data``: (status, headers in lower case) each; an
    incomplete one fails the test."""
    found = []
    while data:
        head, separator, rest = data.partition(b"\r\n\r\n")
        assert separator, f"an incomplete response head: {data[:200]!r}"
        lines = head.decode("latin-1").split("\r\n")
        headers = {
            k.strip().lower(): v.strip() for k, _, v in (x.partition(":") for x in lines[1:])
        }
        length = int(headers["content-length"])
        assert len(rest) >= length, "a response cut short"
        found.append((int(lines[0].split()[1]), headers))
        data = rest[length:]
    return found


def _until_closed(sock: socket.socket) -> tuple[bytes, str]:
    """Everything the server sends until the connection ends: (bytes, 'closed' for an end
    of stream, 'reset' for a reset)."""
    data = b""
    try:
        while chunk := sock.recv(65536):
            data += chunk
    except ConnectionResetError:
        return data, "reset"
    return data, "closed"


def _answered_once(sock: socket.socket, path: str) -> None:
    """One request and its whole answer, leaving the connection open (kept alive)."""
    sock.sendall(_request(path))
    data = b""
    while b"\r\n\r\n" not in data:
        data += sock.recv(65536)
    head, _, body = data.partition(b"\r\n\r\n")
    length = int(head.lower().split(b"content-length:")[1].split(b"\r\n")[0])
    while len(body) < length:
        body += sock.recv(65536)


def test_sigterm_answers_requests_sent_before_it_and_closes_the_rest_cleanly() -> None:
    port = free_port()
    cmd = [sys.executable, "-m", "app.cli", "--port", str(port), "--log-level", "warning"]
    proc = subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    socks: list[socket.socket] = []
    try:
        wait_until_healthy(port, proc, "app.cli")  # type: ignore[arg-type]
        socks = [socket.create_connection(("127.0.0.1", port), timeout=30) for _ in range(24)]
        for sock in socks:
            _answered_once(sock, "/api/v1/health")
        before, late = socks[:CONNECTIONS], socks[CONNECTIONS:]
        for i, sock in enumerate(before):
            sock.sendall(_request(SELECT.format(load=100 + i)))
        proc.send_signal(signal.SIGTERM)
        started = time.monotonic()

        def send_late(sock: socket.socket, after_s: float) -> None:
            time.sleep(max(0.0, started + after_s - time.monotonic()))
            # closed already: what it then reads tells how (below)
            with contextlib.suppress(BrokenPipeError, ConnectionResetError):
                sock.sendall(_request("/api/v1/health"))

        senders = [
            threading.Thread(target=send_late, args=(s, t))
            for s, t in zip(late, AFTER_S, strict=True)
        ]
        for sender in senders:
            sender.start()
        ends_before = [_until_closed(sock) for sock in before]
        for sender in senders:
            sender.join()
        ends_late = [_until_closed(sock) for sock in late]
        output, _ = proc.communicate(timeout=30)
    finally:
        for sock in socks:
            sock.close()
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 0, output
    for data, end in ends_before:
        assert end == "closed"
        assert [status for status, _ in _responses(data)] == [200]
    for (data, end), after_s in zip(ends_late, AFTER_S, strict=True):
        assert end == "closed", f"reset, sent {after_s} s after the signal"
        assert [status for status, _ in _responses(data)] in ([], [200])
