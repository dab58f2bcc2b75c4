"""The compact select (the default ``detail``): numbers to 6 significant figures and no
null values, each number the full form's to 6 figures (its size: test_select_detail.py)."""

from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.contract.schemas import VIEWS
from tests.compact_form import assert_compact_of, null_keys
from tests.machine_axes import X, Z

API = "/api/v1/select"
#: bench/web.py's default request.
DEFAULT = {"load_n": 100, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10}
QUERIES: dict[str, dict[str, Any]] = {
    "default": DEFAULT,
    "ball": {"load_n": 300, "speed_mm_s": 200, "length_mm": 800, "family": "HIWIN-ROLLED"},
    "vertical": {
        "load_n": 50,
        "speed_mm_s": 30,
        "length_mm": 400,
        "orientation": "vertical",
        "moving_mass_kg": 5,
        "hold_power_off": True,
    },
    "move-with-motor": {
        "load_n": 20,
        "speed_mm_s": 100,
        "length_mm": 500,
        "stroke_mm": 300,
        "accel_mm_s2": 1000,
        "cycles_per_day": 100,
        "motor": "17hs19-2004s1",
    },
    "nothing-passes": {"load_n": 900_000, "speed_mm_s": 90_000, "length_mm": 90_000},
}


def _select(client: TestClient, query: dict[str, Any], **extra: str) -> dict[str, Any]:
    response = client.get(API, params={**query, **extra})
    assert response.status_code == 200, response.text
    return dict(response.json())


@pytest.mark.parametrize("query", QUERIES.values(), ids=QUERIES.keys())
def test_each_compact_number_is_the_full_forms_to_6_figures(
    client: TestClient, query: dict[str, Any]
) -> None:
    """Candidate by candidate, the compact form is the full form's view with each number
    to 6 significant figures (relative 5e-6) and each null left out: no key missing that
    the full form gives a value, none present that it gives as null."""
    compact = _select(client, query)
    full = _select(client, query, detail="full")
    for group, view in (("candidates", "summary"), ("rejected", "rejected")):
        full_by_id = {c["id"]: c for c in full[group]}
        assert [c["id"] for c in compact[group]] == list(full_by_id), group
        for c in compact[group]:
            assert_compact_of(c, full_by_id[c["id"]], VIEWS[view], f"{group}:{c['id']}")
    assert compact["candidates"] or compact["rejected"]


def test_the_queries_reach_what_the_compact_form_leaves_out(client: TestClient) -> None:
    """The queries above are varied enough to mean something: ball screws and lead
    screws, a move (peak torque, life) and none, a motor (its use) and none, a check
    that did not run (a null utilisation in the full form)."""
    full = [_select(client, q, detail="full")["candidates"] for q in QUERIES.values()]
    every = [c for group in full for c in group]
    assert {c["screw_type"] for c in every} == {"ball", "lead"}
    assert {c["torque"]["peak_nm"] is None for c in every} == {True, False}
    assert {c["life"] is None for c in every} == {True, False}
    assert {c["motor_use"] is None for c in every} == {True, False}
    assert any(v is None for c in every for v in c["utilization"].values())


@pytest.mark.parametrize("query", QUERIES.values(), ids=QUERIES.keys())
def test_no_compact_candidate_has_a_null_value(client: TestClient, query: dict[str, Any]) -> None:
    body = _select(client, query)
    for group in ("candidates", "rejected"):
        assert null_keys(body[group], group) == []


def test_the_machines_candidates_are_compact_too(client: TestClient) -> None:
    """POST /api/v1/machine gives each axis' candidates and its choice in the same compact
    form: no null value, and the choice is the axis' candidate of the same id."""
    axes = [
        {"name": "Z", "inputs": Z, "frame_kg": 0.3, "motor_kg": 0.4},
        {"name": "X", "inputs": X, "frame_kg": 0.5, "motor_kg": 0.4},
    ]
    response = client.post("/api/v1/machine", json={"axes": axes})
    assert response.status_code == 200, response.text
    for axis in response.json()["axes"]:
        assert axis["candidates"] and axis["chosen"], axis["name"]
        assert null_keys([axis["chosen"], *axis["candidates"]], axis["name"]) == []
        same = next(c for c in axis["candidates"] if c["id"] == axis["chosen"]["id"])
        assert same == axis["chosen"]


def test_a_life_without_a_duty_is_left_out_and_with_one_gives_its_years(
    client: TestClient,
) -> None:
    """The summary shows a life as years at the duty. Without a stroke and cycles a day
    there are no years: a lead screw's wear life (in the full form, as travel) is left out
    of the compact form, not given as an empty object; with a duty it gives its band of
    years, low end first."""
    for c in _select(client, DEFAULT)["candidates"]:
        assert "life" not in c, c["id"]
    full = _select(client, DEFAULT, detail="full")["candidates"]
    assert any(c["screw_type"] == "lead" and c["life"] is not None for c in full)
    with_duty = _select(client, QUERIES["move-with-motor"])["candidates"]
    years = [c["life"]["years"] for c in with_duty if "life" in c]
    assert years and all(0 < low <= high for low, high in years)
