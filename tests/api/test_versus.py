"""GET /api/v1/versus: the best leadscrew against the best ball screw for one axis, each
the select response's own record; the peak shaft power is torque × angular speed."""

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.report.versus import KINDS, kind_families

#: a light horizontal axis both kinds pass
LIGHT = {"load_n": "100", "speed_mm_s": "50", "length_mm": "500", "stroke_mm": "200"}
#: 3 kN at 400 mm/s: every leadscrew's nut slides too fast (PV/speed), a ball screw passes
FAST = {"load_n": "3000", "speed_mm_s": "400", "length_mm": "500"}


def _select(client: TestClient, query: dict[str, str], families: list[str]) -> dict[str, Any]:
    params = [*query.items(), ("detail", "full"), *(("family", f) for f in families)]
    body = client.get("/api/v1/select", params=params)
    assert body.status_code == 200, body.text
    return body.json()


def _families(client: TestClient) -> dict[str, list[str]]:
    """Each kind's families, in catalog order, from the catalog the app serves."""
    kinds: dict[str, list[str]] = {"lead": [], "ball": []}
    for s in client.app.state.catalog.index.table.screws:  # type: ignore[attr-defined]
        if s.family_id not in kinds[s.screw_type]:
            kinds[s.screw_type].append(s.family_id)
    return kinds


def test_each_side_is_the_first_of_its_kinds_selection(client: TestClient) -> None:
    body = client.get("/api/v1/versus", params=LIGHT).json()
    assert [s["screw_type"] for s in body["sides"]] == ["lead", "ball"]
    families = _families(client)
    for side in body["sides"]:
        selected = _select(client, LIGHT, families[side["screw_type"]])
        assert side["passed"] and side["excluded_by"] == []
        assert side["candidate"] == selected["candidates"][0]
        assert side["candidate"]["screw_type"] == side["screw_type"]
    assert body["api_url"].startswith("/api/v1/versus?")
    assert body["share_url"].startswith("/versus?")
    assert "no cited, dated list price" in body["price_note"]


def test_each_kinds_families_read_off_the_series_are_those_of_every_screw(
    client: TestClient,
) -> None:
    """``kind_families`` reads each series' first screw: the families, in catalog order,
    that every screw of the catalog gives, within the families asked for."""
    catalog = client.app.state.catalog  # type: ignore[attr-defined]
    families = _families(client)
    for kind in KINDS:
        assert kind_families(catalog, kind, None) == families[kind]
    asked = [families["ball"][-1], families["lead"][0]]
    assert kind_families(catalog, "ball", asked) == [families["ball"][-1]]
    assert kind_families(catalog, "lead", asked) == [families["lead"][0]]


def test_a_kind_without_a_passing_screw_shows_its_nearest_rejected(client: TestClient) -> None:
    lead, ball = client.get("/api/v1/versus", params=FAST).json()["sides"]
    assert not lead["passed"] and ball["passed"]
    assert lead["candidate"]["passed"] is False
    failed = [f["name"] for f in lead["candidate"]["failed"] if f["kind"] == "limit"]
    labels = {c["name"]: c["label"] for c in client.get("/api/v1/checks").json()["checks"]}
    assert lead["excluded_by"] == [labels[n] for n in failed] and failed
    selected = _select(client, FAST, _families(client)["lead"])
    assert selected["candidates"] == []
    assert lead["candidate"] == selected["rejected"][0]


def test_a_family_filter_of_one_kind_leaves_the_other_empty(client: TestClient) -> None:
    ball_families = _families(client)["ball"]
    params = [*LIGHT.items(), *(("family", f) for f in ball_families)]
    lead, ball = client.get("/api/v1/versus", params=params).json()["sides"]
    assert lead["candidate"] is None and not lead["passed"]
    assert ball["candidate"]["screw_type"] == "ball"


@pytest.mark.parametrize("query", [LIGHT, FAST])
def test_peak_power_is_torque_times_angular_speed(client: TestClient, query: dict) -> None:
    """P = T ω, ω = 2π n / 60: without a move, the accelerating torque at the screw's
    speed; with one, the largest |T ω| of the segments, each at its top speed."""
    for side in client.get("/api/v1/versus", params=query).json()["sides"]:
        c = side["candidate"]
        if c["segments"]:
            expected = max(abs(s["torque_nm"]) * 2 * math.pi * s["rpm"] / 60 for s in c["segments"])
        else:
            expected = c["torque"]["total_nm"] * 2 * math.pi * c["rpm"] / 60
        assert c["peak_power_w"] == pytest.approx(expected, rel=1e-12)
        assert c["peak_power_w"] > 0


def test_bad_input_is_a_field_error(client: TestClient) -> None:
    r = client.get("/api/v1/versus", params={**LIGHT, "load_n": "-1"})
    assert r.status_code == 422
    assert any(e["field"] == "load_n" for e in r.json()["detail"])


def test_versus_is_documented(client: TestClient) -> None:
    op = client.get("/openapi.json").json()["paths"]["/api/v1/versus"]["get"]
    assert op["summary"] == "Leadscrew against ball screw for an axis"
    assert "nearest rejected" in op["description"]
