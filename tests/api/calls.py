"""One candidate through the API, for the tests that work its figures by hand."""

from typing import Any

from fastapi.testclient import TestClient

API = "/api/v1"


def evaluate(client: TestClient, screw: str | dict[str, Any], **application: Any) -> Any:
    """POST /evaluate: ``screw`` a catalog id or a custom screw; the candidate."""
    target = {"catalog_id": screw} if isinstance(screw, str) else screw
    body = {"application": application, "screw": target}
    response = client.post(f"{API}/evaluate", json=body)
    assert response.status_code == 200, response.text
    return response.json()["candidate"]


def check(candidate: dict[str, Any], name: str) -> dict[str, Any]:
    """The candidate's check ``name`` (StopIteration when it has none)."""
    return next(c for c in candidate["checks"] if c["name"] == name)


def names(candidate: dict[str, Any]) -> set[str]:
    """The names of the candidate's checks."""
    return {c["name"] for c in candidate["checks"]}
