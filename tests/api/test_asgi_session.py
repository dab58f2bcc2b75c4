"""The in-thread adapter the schema fuzzing sends through (tests/asgi_session.py) answers
as the app answers through Starlette's test client: status, body and headers, for a
gzip-compressed answer, a refusal and a POST with a JSON body."""

from typing import Any

import pytest
import requests
from fastapi.testclient import TestClient

from app.main import create_app
from tests.asgi_session import InThreadASGI

APP = create_app()
BASE = "http://testserver"
QUERY = "/api/v1/select?load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10&limit=3"
#: headers that differ between two answers of the same request
VARYING = {"date", "x-request-id", "server-timing"}


@pytest.fixture(scope="module")
def in_thread() -> requests.Session:
    session = requests.Session()
    session.mount("http://", InThreadASGI(APP))
    session.trust_env = False
    return session


@pytest.mark.parametrize(
    ("method", "path", "kwargs"),
    [
        ("GET", QUERY, {"headers": {"Accept-Encoding": "gzip"}}),
        ("GET", "/api/v1/select?load_n=abc&speed_mm_s=50&length_mm=500", {}),
        ("POST", "/api/v1/select", {"json": {"load_n": 100, "speed_mm_s": 50, "length_mm": 500}}),
        ("PUT", "/api/v1/select", {}),
    ],
    ids=["gzip", "422", "post-json", "405"],
)
def test_answers_as_the_test_client_does(
    in_thread: requests.Session, method: str, path: str, kwargs: dict[str, Any]
) -> None:
    ours = in_thread.request(method, BASE + path, **kwargs)
    with TestClient(APP) as client:
        theirs = client.request(method, path, **kwargs)
    assert ours.status_code == theirs.status_code
    assert ours.content == theirs.content
    assert ours.reason == theirs.reason_phrase
    headers = {k: v for k, v in ours.headers.items() if k.lower() not in VARYING}
    assert headers == {k: v for k, v in theirs.headers.items() if k.lower() not in VARYING}


def test_a_compressed_answer_is_decoded_as_from_a_server(in_thread: requests.Session) -> None:
    answer = in_thread.get(BASE + QUERY, headers={"Accept-Encoding": "gzip"})
    assert answer.headers["content-encoding"] == "gzip"
    assert answer.json()["candidates"]
