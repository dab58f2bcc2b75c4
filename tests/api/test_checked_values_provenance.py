"""Every value a check that ran reads is in the candidate's provenance, with its kind and
a source: where the screw lacks the value, the provenance says so (and what the check
then does), so no value the engineer reads a result from stands without one."""

from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.core.checks import BY_NAME
from tests.api.calls import evaluate

#: A Tr20x4 of one's own in C45 with no nut material: no rated life, no wear rate.
OWN_SCREW = {
    "outer_diameter_mm": 20, "root_diameter_mm": 15.5, "lead_mm": 4, "pitch_mm": 4,
    "thread_half_angle_deg": 15, "friction_dynamic": 0.13, "friction_static": 0.16,
    "material": "c45-steel",
}  # fmt: skip
AXIS = {"load_n": 100, "speed_mm_s": 20, "length_mm": 300}
DUTY = {"stroke_mm": 200, "cycles_per_day": 100, "required_life_years": 2}


def _unsourced(candidate: dict[str, Any]) -> list[tuple[str, str]]:
    """(check, value) for each value a check that ran reads with no provenance."""
    provenance = candidate["provenance"]
    missing = []
    for result in candidate["checks"]:
        check = BY_NAME[result["name"]]
        read = (*check.sources, *([check.capacity_given] if check.capacity_given else []))
        for key in read:
            p = provenance.get(key)
            if p is None or not p["kind"] or not p["source"].strip():
                missing.append((check.name, key))
    return missing


@pytest.mark.parametrize(
    ("screw", "axis"),
    [
        ("Tr20x4-acetal", {**AXIS, "vacuum": True}),
        ("R16-10K3-FSCDIN", {**AXIS, "vacuum": True}),
        (OWN_SCREW, {**AXIS, **DUTY}),
        ("R32-10K5-FSC", {**AXIS, "positioning_tolerance_mm": 0.05}),
    ],
    ids=["iso-nut-in-vacuum", "ball-nut-in-vacuum", "own-screw-unrated-life", "preloaded-nut"],
)
def test_every_value_a_check_reads_has_its_provenance(
    client: TestClient, screw: str | dict[str, Any], axis: dict[str, Any]
) -> None:
    c = evaluate(client, screw, **axis)
    assert _unsourced(c) == []


def test_a_nut_without_outgassing_data_says_the_vacuum_check_warns(client: TestClient) -> None:
    """The vacuum check judges a nut without outgassing data (it warns): the provenance
    says the data is missing, not that the value is not checked."""
    for screw in ("Tr20x4-acetal", "R16-10K3-FSCDIN"):
        c = evaluate(client, screw, **AXIS, vacuum=True)
        vacuum = next(k for k in c["checks"] if k["name"] == "vacuum")
        assert not vacuum["passed"]
        source = c["provenance"]["outgassing"]["source"]
        assert "no outgassing data" in source and "not checked" not in source


@pytest.mark.parametrize(
    ("screw", "axis"),
    [("Tr16x4-ptfe", {**AXIS, **DUTY}), ("Tr20x4-acetal", AXIS), (OWN_SCREW, {**AXIS, **DUTY})],
    ids=["ptfe-nut-no-pressure-table", "acetal-nut", "own-screw"],
)
def test_no_value_a_check_ran_on_says_it_is_not_checked(
    client: TestClient, screw: str | dict[str, Any], axis: dict[str, Any]
) -> None:
    """A value the screw lacks says so, and not that it is "not checked" where a check
    that ran reads it: Tr16x4-ptfe has no pressure-speed table, and its nut contact
    pressure check runs on its maximum pressure and PV limit without one."""
    c = evaluate(client, screw, **axis)
    said = [
        (result["name"], key, c["provenance"][key]["source"])
        for result in c["checks"]
        for key in BY_NAME[result["name"]].sources
        if key in c["provenance"] and "not checked" in c["provenance"][key]["source"]
    ]
    assert said == []
