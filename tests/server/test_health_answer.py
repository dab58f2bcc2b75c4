"""The health check is answered by the HTTP protocol as soon as its head is parsed, with
the app's own answer, so it never waits behind the app's work (issue 31, item 2: 64
clients pulling the 1.4 MB catalog page made its p99 1.05 s).

A real uvicorn server with the app's protocol (``app.server.protocol``) serves the app
behind a gate: once the gate is shut every request that enters the app waits there. The
health check asked then is still answered, byte for byte as the app answered it (the
date aside); a request that the app must see (a query, a body, a request still in
progress ahead of it on the same connection) waits at the gate as before.
"""

import asyncio
import socket
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass

import pytest
import uvicorn
from fastapi import FastAPI

from app.server.overload import ASGIApp, Receive, Scope, Send
from app.server.protocol import BoundedHttpToolsProtocol
from deploy.local import free_port
from tests.server.test_shutdown import _responses

HEALTH = "/api/v1/health"
#: how long a request the gate holds is watched for an answer that must not come
HELD_S = 0.5


class Gate:
    """The app, or, while ``shut`` is set, a wait before it (the app blocked)."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app
        self.shut = threading.Event()
        self.entered: list[str] = []

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] == "http":
            self.entered.append(scope["path"])
            while self.shut.is_set():
                await asyncio.sleep(0.01)
        await self.app(scope, receive, send)


@dataclass
class Served:
    port: int
    gate: Gate


@pytest.fixture
def served(app: FastAPI) -> Iterator[Served]:
    gate = Gate(app)
    port = free_port()
    config = uvicorn.Config(
        gate,
        host="127.0.0.1",
        port=port,
        http=BoundedHttpToolsProtocol,
        loop="asyncio",
        log_level="warning",
    )
    server = uvicorn.Server(config)
    thread = threading.Thread(target=server.run)
    thread.start()
    try:
        deadline = time.monotonic() + 30
        while not server.started:
            assert thread.is_alive() and time.monotonic() < deadline, "server did not start"
            time.sleep(0.02)
        yield Served(port, gate)
    finally:
        gate.shut.clear()
        server.should_exit = True
        thread.join(timeout=30)


def _connect(port: int) -> socket.socket:
    return socket.create_connection(("127.0.0.1", port), timeout=10)


def _read(sock: socket.socket, responses: int, head_only: bool = False) -> bytes:
    """Read until ``responses`` whole responses (Content-Length bodies) have arrived."""
    data = b""
    while True:
        try:
            if len(_responses(data)) == responses:
                return data
        except AssertionError:  # one still incomplete
            pass
        if head_only and data.endswith(b"\r\n\r\n"):
            return data
        chunk = sock.recv(65536)
        assert chunk, f"closed after {data[:300]!r}"
        data += chunk


def _ask(port: int, head: str) -> bytes:
    with _connect(port) as sock:
        sock.sendall(f"{head}\r\nHost: test\r\n\r\n".encode())
        return _read(sock, 1, head_only=head.startswith("HEAD"))


def _without_date(response: bytes) -> bytes:
    return b"\r\n".join(line for line in response.split(b"\r\n") if not line.startswith(b"date:"))


def _unanswered(sock: socket.socket) -> bool:
    """Nothing arrives on ``sock`` within ``HELD_S``."""
    sock.settimeout(HELD_S)
    try:
        return not sock.recv(65536)
    except TimeoutError:
        return True
    finally:
        sock.settimeout(10)


def test_health_is_answered_while_the_app_is_blocked_as_the_app_answered_it(
    served: Served,
) -> None:
    first = _ask(served.port, f"GET {HEALTH} HTTP/1.1")  # through the app, and recorded
    assert served.gate.entered == [HEALTH]
    served.gate.shut.set()
    with _connect(served.port) as held:
        held.sendall(b"GET /api/v1/checks HTTP/1.1\r\nHost: test\r\n\r\n")
        again = _ask(served.port, f"GET {HEALTH} HTTP/1.1")
        head = _ask(served.port, f"HEAD {HEALTH} HTTP/1.1")
        closing = _ask(served.port, f"GET {HEALTH} HTTP/1.1\r\nConnection: close")
        assert _unanswered(held)  # the app is blocked indeed
        served.gate.shut.clear()
        assert _read(held, 1).startswith(b"HTTP/1.1 200 ")
    assert served.gate.entered == [HEALTH, "/api/v1/checks"]  # the app saw no other
    assert first.startswith(b"HTTP/1.1 200 OK\r\n")
    assert b'"status":"ok"' in first and b"content-security-policy: " in first
    assert _without_date(again) == _without_date(first)
    assert _without_date(head) == _without_date(first).partition(b"\r\n\r\n")[0] + b"\r\n\r\n"
    closed_head, _, closed_body = closing.partition(b"\r\n\r\n")
    assert closed_head.endswith(b"\r\nconnection: close")
    assert _without_date(closed_head.removesuffix(b"\r\nconnection: close") + b"\r\n\r\n"
                         + closed_body) == _without_date(first)  # fmt: skip


def test_health_keeps_its_turn_behind_a_request_in_progress(served: Served) -> None:
    """Pipelined behind a request the app holds, the health check is answered after it,
    never before (HTTP/1.1 answers in the order asked)."""
    _ask(served.port, f"GET {HEALTH} HTTP/1.1")
    served.gate.shut.set()
    with _connect(served.port) as sock:
        sock.sendall(
            f"GET /api/v1/checks HTTP/1.1\r\nHost: test\r\n\r\n"
            f"GET {HEALTH} HTTP/1.1\r\nHost: test\r\n\r\n".encode()
        )
        assert _unanswered(sock)
        served.gate.shut.clear()
        answers = _responses(_read(sock, 2))
    assert [status for status, _ in answers] == [200, 200]
    assert answers[0][1]["content-length"] != answers[1][1]["content-length"]


@pytest.mark.parametrize(
    "request_head",
    [
        pytest.param(f"GET {HEALTH}?probe=1 HTTP/1.1", id="query"),
        pytest.param(f"GET {HEALTH} HTTP/1.1\r\nContent-Length: 2\r\n\r\n{{}}", id="body"),
        pytest.param(f"POST {HEALTH} HTTP/1.1\r\nContent-Length: 0", id="post"),
    ],
)
def test_a_health_request_the_app_must_judge_goes_through_the_app(
    served: Served, request_head: str
) -> None:
    """A query (too long a one is 414), a body (too large a one is 413) or another method
    (405): the app decides, so the request waits at the gate like any other."""
    _ask(served.port, f"GET {HEALTH} HTTP/1.1")
    served.gate.shut.set()
    with _connect(served.port) as sock:
        head, _, body = request_head.partition("\r\n\r\n")
        sock.sendall(f"{head}\r\nHost: test\r\n\r\n{body}".encode())
        assert _unanswered(sock)
        served.gate.shut.clear()
        _read(sock, 1)
    assert served.gate.entered == [HEALTH, HEALTH]


def test_the_first_health_check_goes_through_the_app(served: Served) -> None:
    """Nothing is answered for the app before the app has answered once."""
    served.gate.shut.set()
    with _connect(served.port) as sock:
        sock.sendall(f"GET {HEALTH} HTTP/1.1\r\nHost: test\r\n\r\n".encode())
        assert _unanswered(sock)
        served.gate.shut.clear()
        assert _read(sock, 1).startswith(b"HTTP/1.1 200 ")


def test_a_first_head_is_not_kept_as_the_answer(served: Served) -> None:
    """A HEAD's answer has no body: the first GET is the one kept, and answers in full."""
    head = _ask(served.port, f"HEAD {HEALTH} HTTP/1.1")
    first = _ask(served.port, f"GET {HEALTH} HTTP/1.1")
    served.gate.shut.set()
    again = _ask(served.port, f"GET {HEALTH} HTTP/1.1")
    assert served.gate.entered == [HEALTH, HEALTH]
    assert _without_date(again) == _without_date(first)
    assert _without_date(head) == _without_date(first).partition(b"\r\n\r\n")[0] + b"\r\n\r\n"
