"""Every response's two links: the share link (the page's names) and ``api_url`` (the
API's GET of the same query); and a share link's query sent to the API, refused with the
API's name of each page name it holds (both names from the field table)."""

import html
from typing import Any
from urllib.parse import parse_qsl, urlsplit

import pytest
from fastapi.testclient import TestClient

from app.contract.fields import BY_PAGE
from app.contract.inputs import ApplicationIn
from app.contract.params import api_query, api_url
from app.contract.units import DEFAULT_UNITS

#: A vertical axis with a library motor, a list, a choice, a yes-no and a curve-free
#: stepper: every kind of value a link carries.
AXIS: dict[str, Any] = {
    "load_n": 15.5,
    "moving_mass_kg": 1.25,
    "orientation": "vertical",
    "speed_mm_s": 40.0,
    "accel_mm_s2": 800.0,
    "length_mm": 350.0,
    "stroke_mm": 200.0,
    "cycles_per_day": 200.0,
    "family": ["TR-C45", "TR-304"],
    "hold_power_off": False,
    "motor": "17hs19-2004s1",
    "limit": 5,
}
IDS = "Tr12x3-bronze,Tr16x4-bronze"


def _ok(response: Any) -> Any:
    assert response.status_code == 200, response.text
    return response.json()


def _responses(client: TestClient) -> dict[str, Any]:
    """Each route's response for the axis (select in both forms, pairs, compare,
    evaluate), by name."""
    return {
        "select": _ok(client.post("/api/v1/select", json=AXIS)),
        "select-full": _ok(client.post("/api/v1/select?detail=full", json=AXIS)),
        "pairs": _ok(client.post("/api/v1/pairs", json=AXIS)),
        "pairs-ranked": _ok(client.post("/api/v1/pairs?pair_rank=motor_size", json=AXIS)),
        "compare": _ok(client.get("/api/v1/compare", params={**AXIS, "ids": IDS})),
        "evaluate": _ok(
            client.post(
                "/api/v1/evaluate",
                json={"application": AXIS, "screw": {"catalog_id": "Tr12x3-bronze"}},
            )
        ),
    }


@pytest.fixture(scope="module")
def responses(client: TestClient) -> dict[str, Any]:
    return _responses(client)


ROUTES = ["select", "select-full", "pairs", "pairs-ranked", "compare", "evaluate"]


@pytest.mark.parametrize("route", ROUTES)
def test_the_api_url_gives_the_same_answer(
    client: TestClient, responses: dict[str, Any], route: str
) -> None:
    """GET api_url: the same inputs and the same result as the request that gave it."""
    body = responses[route]
    assert body["api_url"].startswith("/api/v1/") and body["share_url"]
    again = _ok(client.get(body["api_url"]))
    assert again["inputs"] == body["inputs"]
    for key in ("candidates", "candidate", "pairs", "rank", "counts"):
        if key in body:
            assert again[key] == body[key], key


@pytest.mark.parametrize("route", ROUTES)
def test_the_share_link_given_to_the_api_names_each_api_name(
    client: TestClient, responses: dict[str, Any], route: str
) -> None:
    """The share link's query on the API's route: a 422 naming every page name it holds
    that is not the API's, with the API's name (the field table's)."""
    body = responses[route]
    path = urlsplit(body["api_url"]).path
    shared = parse_qsl(urlsplit(body["share_url"]).query)
    r = client.get(path, params=shared)
    assert r.status_code == 422, r.text
    hints = {d["field"]: d["message"] for d in r.json()["detail"]}
    page_only = [name for name, _ in shared if name in BY_PAGE and BY_PAGE[name].api != name]
    assert page_only  # load, speed, length at least
    for name in page_only:
        assert f"'{name}' is the page's name" in hints[name]
        assert f"the API's is '{BY_PAGE[name].api}'" in hints[name]


def test_a_page_name_in_a_body_is_refused_with_the_api_name(client: TestClient) -> None:
    body = {**AXIS, "speed": 40.0}
    del body["speed_mm_s"]
    r = client.post("/api/v1/select", json=body)
    assert r.status_code == 422
    hints = {d["field"]: d["message"] for d in r.json()["detail"]}
    assert "'speed' is the page's name" in hints["speed"]
    assert "'speed_mm_s'" in hints["speed"] and "mm/s" in hints["speed"]
    nested = client.post(
        "/api/v1/evaluate",
        json={"application": {**AXIS, "length": 350}, "screw": {"catalog_id": "Tr12x3-bronze"}},
    )
    assert nested.status_code == 422
    messages = {d["field"]: d["message"] for d in nested.json()["detail"]}
    assert "'length_mm'" in messages["application.length"]


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ("force_unit", "a page's setting"),
        ("speed_mm", "did you mean 'speed_mm_s'"),
        ("screw_type", "'screw_type' is not an input this route reads"),
    ],
    ids=["unit-switch", "misspelled", "unknown"],
)
def test_other_unread_names_say_what_the_api_reads(
    client: TestClient, name: str, words: str
) -> None:
    assert name in DEFAULT_UNITS or name not in BY_PAGE
    r = client.get("/api/v1/select", params={**AXIS, name: "lbf"})
    assert r.status_code == 422
    (message,) = [d["message"] for d in r.json()["detail"] if d["field"] == name]
    assert words in message
    assert message.count("API name") <= 1  # said once


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ("nut", "the API's is 'nut_material' (Nut material)"),
        ("outer_diameter", "did you mean 'outer_diameter_mm'"),
        ("load_n", "'load_n' is not an input this route reads"),
    ],
    ids=["page-name", "misspelled", "an-application-name"],
)
def test_an_unread_name_in_a_screw_says_what_the_screw_reads(
    client: TestClient, name: str, words: str
) -> None:
    """The screw's names are its model's, not the application's: the custom page's
    ``nut`` is the API's ``nut_material``, and ``load_n`` belongs in the application."""
    screw = {"outer_diameter_mm": 12, "root_diameter_mm": 8.5, "lead_mm": 3}
    screw |= {"friction_dynamic": 0.13, "friction_static": 0.16, name: 1}
    r = client.post("/api/v1/evaluate", json={"application": AXIS, "screw": screw})
    assert r.status_code == 422
    (message,) = [d["message"] for d in r.json()["detail"] if d["field"] == f"screw.{name}"]
    assert words in message


def test_a_custom_screws_share_url_is_its_page_with_the_same_answer(client: TestClient) -> None:
    """A custom geometry has no query form in the API (no ``api_url``), but a page of its
    own: its ``share_url`` opens /custom with the screw and the application, which gives
    the same verdict."""
    screw = {"outer_diameter_mm": 12.7, "root_diameter_mm": 9.906, "lead_mm": 10.0}
    screw |= {"friction_dynamic": 0.15, "friction_static": 0.2}
    body = _ok(client.post("/api/v1/evaluate", json={"application": AXIS, "screw": screw}))
    assert body["api_url"] is None
    share = body["share_url"]
    assert share.startswith("/custom?material=steel&outer_diameter_mm=12.7&root_diameter_mm=9.906")
    page = client.get(share)
    assert page.status_code == 200
    verdict = body["candidate"]["verdict"]
    assert verdict["text"].startswith("Governed by Motor torque-speed curve at ")
    # the five of the screw and the motor, and the stepper supply its model curve is in range at
    assert verdict["summary"].startswith("Passes the 6 limits that ran")
    assert verdict["summary"] in html.unescape(page.text)


def test_the_api_query_is_the_share_link_s_under_the_api_s_names() -> None:
    """Required fields and non-defaults, numbers exact, a list repeated, the motor's id as
    the library writes it; the route's own names after them, encoded but for the
    separators ':' and ',' (``share_link.LINK_SAFE``)."""
    inputs = ApplicationIn(load_n=100, speed_mm_s=50, length_mm=500, family="B, TR-C45")
    assert api_query(inputs) == "load_n=100&speed_mm_s=50&length_mm=500&family=B&family=TR-C45"
    inputs = ApplicationIn(load_n=0.1, speed_mm_s=5, length_mm=90, motor=" ANY")
    assert api_url("compare", inputs, [("ids", "a,b")]) == (
        "/api/v1/compare?load_n=0.1&speed_mm_s=5&length_mm=90&motor=any&ids=a,b"
    )


def test_the_api_link_of_a_cycle_carries_its_moves(client: TestClient) -> None:
    """A cycle of moves (app.contract.cycle's text) reaches the API link as it is."""
    moves = "300:100:1000:1000:0.2:2:0:auto;-300:100:1000:1000:0.2:0.5:0:auto"
    query = "load_n=0&speed_mm_s=100&length_mm=500&moves=" + moves
    body = client.get("/api/v1/select?" + query).json()
    again = client.get(body["api_url"]).json()
    # readable as typed: only the ';' between the moves is encoded
    assert "&moves=" + moves.replace(";", "%3B") in body["api_url"]
    assert "&moves=" + moves.replace(";", "%3B") in body["share_url"]
    assert [c["id"] for c in again["candidates"]] == [c["id"] for c in body["candidates"]]
    assert again["candidates"][0]["torque"] == body["candidates"][0]["torque"]
