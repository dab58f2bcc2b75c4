"""The forms of a candidate (``VIEWS`` of ``CandidateOut``) and the numbers the row and
the summary show besides the breakdown: the nut's material, and the motor's peak and RMS
torque over the move (null without a stroke)."""

from typing import Any

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.catalog import Catalog
from app.contract.fields import FIELDS
from app.contract.schemas import VIEWS, ApplicationIn, CandidateOut, CandidateSummaryOut
from app.core.evaluate import evaluate
from app.report.service import run_selection
from app.web.export import results_csv

AXIS = {"load_n": 100, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10}
#: A move of 300 mm with 5 kg accelerated at 2 m/s^2: every candidate has a motion.
MOVE = {
    **AXIS,
    "load_n": 50,
    "speed_mm_s": 200,
    "stroke_mm": 300,
    "accel_mm_s2": 2000,
    "moving_mass_kg": 5,
}


def _compact(client: TestClient, params: dict[str, Any]) -> list[dict[str, Any]]:
    response = client.get("/api/v1/select", params=params)
    assert response.status_code == 200, response.text
    candidates: list[dict[str, Any]] = response.json()["candidates"]
    assert candidates
    return candidates


def test_views_name_fields_of_the_one_model() -> None:
    fields = set(CandidateOut.model_fields)
    for name in ("row", "summary", "rejected"):
        assert set(VIEWS[name]) < fields, name
    assert set(VIEWS["full"]) == fields
    assert set(CandidateSummaryOut.model_fields) == set(VIEWS["summary"])


def test_the_compact_select_gives_the_catalog_nut_material(
    client: TestClient, catalog: Catalog
) -> None:
    for c in _compact(client, AXIS):
        assert c["nut_material"] == catalog.by_id[c["id"]].nut_material
        assert c["nut_material"] in {"polyacetal", "bronze", "acetal", "PTFE-filled polymer"}
    any_lead = {k: v for k, v in AXIS.items() if k != "lead_mm"}
    bronze = _compact(client, {**any_lead, "nut_material": "bronze"})
    assert {c["nut_material"] for c in bronze} == {"bronze"}


@pytest.mark.parametrize("params", [AXIS, MOVE], ids=["no-stroke", "move"])
def test_motor_peak_and_rms_torque_are_the_cores(
    client: TestClient, catalog: Catalog, params: dict[str, Any]
) -> None:
    app = ApplicationIn.model_validate(params).to_core()
    for c in _compact(client, params):
        row = catalog.index.row(catalog.index.positions[c["id"]])
        motion = evaluate(app, row, catalog.index.table.reach).motion
        if motion is None:
            assert "stroke_mm" not in params
            assert c["torque"]["peak_nm"] is None and c["torque"]["rms_nm"] is None
        else:
            assert (c["torque"]["peak_nm"], c["torque"]["rms_nm"]) == (
                motion.peak_nm,
                motion.rms_nm,
            )
            assert c["torque"]["peak_nm"] >= c["torque"]["rms_nm"] > 0


@pytest.mark.parametrize("move", [False, True], ids=["no-stroke", "move"])
def test_the_results_table_shows_the_nut_and_the_motor_torque(
    client: TestClient, catalog: Catalog, move: bool
) -> None:
    query = {"load": 50, "speed": 200, "length": 500, "lead": 10}
    if move:
        query |= {"stroke": 300, "accel": 2000, "moving_mass_kg": 5}
    page = BeautifulSoup(client.get("/", params=query).text, "html.parser")
    rows = page.select("tbody.candidate")
    assert rows
    for row in rows:
        material = catalog.by_id[row["data-id"]].nut_material
        assert row.select_one(".nut-material").get_text() == f"{material} nut"
        motor = row.select_one(".motor-torque")
        assert (motor is not None) == move
        if motor is not None:
            assert motor.get_text().startswith("motor peak ") and " · RMS " in motor.get_text()


@pytest.mark.parametrize(
    "params",
    [AXIS, MOVE, {"load_n": 5000, "speed_mm_s": 800, "length_mm": 2000}],
    ids=["passing", "move", "nothing-passes"],
)
def test_the_csv_view_writes_the_csv_of_the_full_form(
    catalog: Catalog, params: dict[str, Any]
) -> None:
    inputs = ApplicationIn.model_validate(params)
    units = {"force_unit": "lbf", "length_unit": "in", "torque_unit": "oz_in"}
    full = results_csv(run_selection(inputs, catalog, units), units)
    assert results_csv(run_selection(inputs, catalog, units, view="csv"), units) == full
    assert full.count("\r\n") > len(FIELDS) + 3
