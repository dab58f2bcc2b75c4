"""/docs: every operation titled and described by hand, and every worked request it
offers (the Z axis of a 3D printer, the pick-and-place with a library motor) valid: each
example body posted from the OpenAPI schema, each GET's example link followed, a 200."""

import re
from typing import Any

import pytest
from bs4 import BeautifulSoup
from fastapi import FastAPI
from fastapi.testclient import TestClient

from app.api.examples import PICK_AND_PLACE


def _operations(app: FastAPI) -> list[tuple[str, str, dict[str, Any]]]:
    return [
        (method, path, op)
        for path, ops in app.openapi()["paths"].items()
        if path.startswith("/api/v1")
        for method, op in ops.items()
    ]


def _auto_title(path: str, app: FastAPI) -> set[str]:
    """The titles FastAPI would make from the route functions' names ('Select Post')."""
    names = {r.name for r in app.routes if getattr(r, "path", None) == path}  # type: ignore[attr-defined]
    return {name.replace("_", " ").title() for name in names}


def test_every_operation_has_a_title_and_a_description(app: FastAPI) -> None:
    operations = _operations(app)
    assert len(operations) >= 13
    titles = [op["summary"] for _, _, op in operations]
    assert len(set(titles)) == len(titles)  # no two operations share a title
    for method, path, op in operations:
        assert op["summary"] not in _auto_title(path, app), (method, path)
        assert len(op.get("description", "")) > 40, (method, path)


def _body_examples(app: FastAPI) -> list[tuple[str, str, Any]]:
    found = []
    for _, path, op in _operations(app):
        content = op.get("requestBody", {}).get("content", {}).get("application/json", {})
        for name, example in content.get("examples", {}).items():
            found.append((path, name, example))
    return found


def test_the_posts_offer_both_worked_axes(app: FastAPI) -> None:
    examples = _body_examples(app)
    assert {p for p, _, _ in examples} == {"/api/v1/select", "/api/v1/pairs", "/api/v1/evaluate"}
    for path in ("/api/v1/select", "/api/v1/pairs", "/api/v1/evaluate"):
        assert {n for p, n, _ in examples if p == path} == {"z_axis", "pick_and_place"}
    # the pick-and-place as the issue states it: no process load, a 1.5 kg head, 300 mm/s,
    # 500 mm screw, 10 000 mm/s², 400 mm stroke, 20 000 cycles a day, the 17HS19-2004S1
    assert PICK_AND_PLACE == {
        "load_n": 0, "moving_mass_kg": 1.5, "speed_mm_s": 300, "length_mm": 500,
        "accel_mm_s2": 10000, "stroke_mm": 400, "cycles_per_day": 20000,
        "motor": "17hs19-2004s1",
    }  # fmt: skip


def test_every_body_example_is_answered(app: FastAPI, client: TestClient) -> None:
    examples = _body_examples(app)
    assert len(examples) == 6
    for path, name, example in examples:
        assert example["summary"] and example["description"]
        r = client.post(path, json=example["value"])
        assert r.status_code == 200, (path, name, r.text)
        body = r.json()
        assert body["api_url"] and client.get(body["api_url"]).status_code == 200
        if path.endswith("select"):
            assert body["counts"]["passed"] > 0, (path, name)  # a worked example that works
        if path.endswith("evaluate"):
            assert body["candidate"]["passed"], (path, name)


def test_every_get_example_link_is_answered(app: FastAPI, client: TestClient) -> None:
    links = [
        (path, link)
        for method, path, op in _operations(app)
        if method == "get"
        for link in re.findall(r"\]\((/api/v1/[^)\s]+)\)", op.get("description", ""))
    ]
    assert {p for p, _ in links} == {
        "/api/v1/select", "/api/v1/pairs", "/api/v1/compare", "/api/v1/evaluate", "/api/v1/versus",
    }  # fmt: skip
    for path, link in links:
        assert link.startswith(path + "?")
        r = client.get(link)
        assert r.status_code == 200, (link, r.text)


@pytest.mark.parametrize("name", ["z_axis", "pick_and_place"])
def test_a_pair_rank_by_default_is_the_page_s(app: FastAPI, client: TestClient, name: str) -> None:
    """For the same inputs, the top pair of /pairs is the top pair of the page (its
    share_url: the same axis with the motor "any"), in the same ranking."""
    (example,) = [e for p, n, e in _body_examples(app) if p.endswith("pairs") and n == name]
    body = client.post("/api/v1/pairs", json=example["value"]).json()
    assert body["pairs"]
    page = BeautifulSoup(client.get(body["share_url"]).text, "html.parser")
    rows = page.select("table.pairs tr.pair")
    assert rows
    top = (body["pairs"][0]["screw_id"], body["pairs"][0]["motor"])
    assert (rows[0]["data-screw"], rows[0]["data-motor"]) == top
    (caption,) = page.select("table.pairs caption")
    assert body["ranked_by"] in caption.text
    asked = client.post(f"/api/v1/pairs?pair_rank={body['rank']}", json=example["value"])
    assert asked.json()["pairs"] == body["pairs"]


def test_each_select_parameter_describes_what_the_api_reads(client: TestClient) -> None:
    """The descriptions came from the page's help: "empty or “any” for every lead" and
    "comma-separated" families, both answered with a 422 by the API. Now a description
    names no empty box and no comma list, and each word it quotes for "no value" (“any”,
    “none”) is one the API accepts."""
    schema = client.get("/openapi.json").json()
    axis = {"load_n": 50, "speed_mm_s": 50, "length_mm": 500, "limit": 1}
    quoted = 0
    for param in schema["paths"]["/api/v1/select"]["get"]["parameters"]:
        text = param.get("description", "")
        assert "empty" not in text and "comma-separated" not in text, (param["name"], text)
        for word in re.findall(r"“(\w+)”", text):
            answer = client.get("/api/v1/select", params={**axis, param["name"]: word})
            assert answer.status_code == 200, (param["name"], word, answer.text)
            quoted += 1
    assert quoted >= 2
    repeated = client.get("/api/v1/select", params={**axis, "family": ["B", "ZBX"]})
    assert repeated.status_code == 200
