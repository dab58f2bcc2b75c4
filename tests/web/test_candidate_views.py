"""The forms of a candidate (``VIEWS`` of ``CandidateOut``) and the numbers the row and
the summary show besides the breakdown: the nut's material, the motor's peak and RMS
torque over the move (without a stroke: null in the full form, absent in the compact
one), the share of the motor used, and the column the ranking orders."""

import csv
import io
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
from tests.compact_form import RELATIVE
from tests.motor_library import MOTORS

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


def _forms(client: TestClient, params: dict[str, Any]) -> list[tuple[list[Any], float]]:
    """The compact select's candidates, its numbers to 6 significant figures (within
    ``RELATIVE`` of the core's), and the full form's, the core's numbers exactly."""
    return [
        (_compact(client, params), RELATIVE),
        (_compact(client, {**params, "detail": "full"}), 0.0),
    ]


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
        assert c["nut_material"] in {
            "polyacetal",
            "bronze",
            "acetal",
            "PTFE-filled polymer",
            "steel",
        }
    any_lead = {k: v for k, v in AXIS.items() if k != "lead_mm"}
    bronze = _compact(client, {**any_lead, "nut_material": "bronze"})
    assert {c["nut_material"] for c in bronze} == {"bronze"}


@pytest.mark.parametrize("params", [AXIS, MOVE], ids=["no-stroke", "move"])
def test_motor_peak_and_rms_torque_are_the_cores(
    client: TestClient, catalog: Catalog, params: dict[str, Any]
) -> None:
    app = ApplicationIn.model_validate(params).to_core(MOTORS)
    for candidates, rel in _forms(client, params):
        for c in candidates:
            row = catalog.index.row(catalog.index.positions[c["id"]])
            motion = evaluate(app, row, catalog.index.table.reach).motion
            if motion is None:
                assert "stroke_mm" not in params
                # null in the full form, left out of the compact one
                assert c["torque"].get("peak_nm") is None and c["torque"].get("rms_nm") is None
            else:
                assert (c["torque"]["peak_nm"], c["torque"]["rms_nm"]) == pytest.approx(
                    (motion.peak_nm, motion.rms_nm), rel=rel, abs=0.0
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
    heads = [a.get_text() for a in page.select("table.candidates thead abbr.col-help")]
    # the peak torque, the one the drive-torque check judges, with or without a stroke
    assert "Peak torque" in heads and ("RMS torque" in heads) == move
    assert "Torque" not in heads and "Motor used" not in heads
    for row in rows:
        material = catalog.by_id[row["data-id"]].nut_material
        assert row.select_one(".nut-material").get_text() == f"{material} nut"
        assert row.select_one(".torque-peak") is not None
        assert (row.select_one(".torque-rms") is not None) == move
        assert row.select_one(".motor-use") is None


#: A move of 300 mm and a motor of 0.4 N m (about 57 oz in), ranked by its margin, at
#: every lead (ten candidates pass).
MOTOR_PAGE = {
    "load": 50,
    "speed": 200,
    "length": 500,
    "stroke": 300,
    "accel": 2000,
    "moving_mass_kg": 5,
    "max_torque": 56.6,
    "torque_unit": "oz_in",
    "rank_by": "motor_margin",
}
OZ_IN = 0.0070615518142260435  # N m: 4.4482216152605 N x 0.0254 m / 16 (NIST SP 811)


def test_the_table_shows_the_cores_peak_rms_and_motor_use_in_the_display_unit(
    client: TestClient, catalog: Catalog
) -> None:
    page = BeautifulSoup(client.get("/", params=MOTOR_PAGE).text, "html.parser")
    app = ApplicationIn.model_validate(
        {**MOVE, "max_torque_nm": 56.6 * OZ_IN, "rank_by": "motor_margin"}
    ).to_core(MOTORS)
    rows = page.select("tbody.candidate")
    assert rows
    used = []
    for row in rows:
        record = evaluate(app, catalog.index.row(catalog.index.positions[row["data-id"]]))
        peak_nm = record.quantities.torque.peak_torque_nm
        assert record.motion is not None
        peak = float(row.select_one(".torque-peak").get_text())
        assert peak == pytest.approx(peak_nm / OZ_IN, rel=1e-3)
        assert peak_nm >= record.motion.peak_nm - 1e-12  # the segments' peak, rotor and all
        rms = float(row.select_one(".torque-rms").get_text())
        assert rms == pytest.approx(record.motion.rms_nm / OZ_IN, rel=1e-3)
        # the only motor check here is the drive torque: peak x safety factor / the motor's
        share = peak_nm * app.torque_safety_factor / (56.6 * OZ_IN)
        cell = row.select_one(".motor-use").get_text()
        assert cell == f"{share * 100:.0f} %"
        used.append(share)
    assert len(used) > 1 and used == sorted(used)
    ranked = page.select("table.candidates thead th.ranked")
    assert [th.select_one("abbr").get_text() for th in ranked] == ["Motor used"]


@pytest.mark.parametrize(
    ("rank_by", "heading", "mark"),
    [
        ("torque", "Peak torque", "ranked by peak"),
        ("size", "OD", "ranked"),
        ("life", "Life", "ranked"),
        ("margin", "Governing", "ranked"),
    ],
)
def test_the_ranked_column_is_marked(
    client: TestClient, rank_by: str, heading: str, mark: str
) -> None:
    query = {"load": 50, "speed": 200, "length": 500, "rank_by": rank_by}
    page = BeautifulSoup(client.get("/", params=query).text, "html.parser")
    ranked = page.select("table.candidates thead th.ranked")
    assert [th.select_one("abbr").get_text() for th in ranked] == [heading]
    assert ranked[0].select_one(".rank-mark").get_text() == mark


@pytest.mark.parametrize(
    ("rank_by", "heading", "mark", "cell"),
    [
        ("torque", "Peak torque", "ranked by peak", ".torque-peak"),
        ("rms", "RMS torque", "ranked", ".torque-rms"),
    ],
)
def test_under_a_move_the_torque_rankings_order_the_column_they_mark(
    client: TestClient, rank_by: str, heading: str, mark: str, cell: str
) -> None:
    """Lowest torque orders by the peak motor torque the column shows (not the
    accelerating torque on its second line), lowest RMS torque by the RMS column; the
    mark and the caption say which (warned screws last, each part sorted)."""
    query = {**MOTOR_PAGE, "rank_by": rank_by}
    page = BeautifulSoup(client.get("/", params=query).text, "html.parser")
    (ranked,) = page.select("table.candidates thead th.ranked")
    assert ranked.select_one("abbr").get_text() == heading
    assert ranked.select_one(".rank-mark").get_text() == mark
    caption = page.select_one("table.candidates caption").get_text()
    assert caption.startswith(
        "Ranked by lowest " + ("torque." if rank_by == "torque" else "RMS torque.")
    )
    order = [
        (row.select_one("span.mark.warned") is not None, float(row.select_one(cell).text))
        for row in page.select("tbody.candidate")
    ]
    assert len(order) > 1 and order == sorted(order)


def test_the_compact_select_gives_the_peak_torque_and_the_motor_use(
    client: TestClient, catalog: Catalog
) -> None:
    motor_nm = 0.4
    app = ApplicationIn.model_validate({**MOVE, "max_torque_nm": motor_nm}).to_core(MOTORS)
    for candidates, rel in _forms(client, {**MOVE, "max_torque_nm": motor_nm}):
        for c in candidates:
            record = evaluate(app, catalog.index.row(catalog.index.positions[c["id"]]))
            peak_nm = record.quantities.torque.peak_torque_nm
            assert c["torque"]["peak_motor_nm"] == pytest.approx(peak_nm, rel=rel, abs=0.0)
            share = peak_nm * app.torque_safety_factor / motor_nm
            assert c["motor_use"] == pytest.approx(share, rel=max(rel, 1e-12))
    # no motor: null in the full form, left out of the compact one
    assert all("motor_use" not in c for c in _compact(client, MOVE))
    exported = client.get("/export.csv", params=MOTOR_PAGE).text
    rows = list(csv.DictReader(io.StringIO(exported)))
    any_lead = {k: v for k, v in MOVE.items() if k != "lead_mm"}
    full = {**any_lead, "max_torque_nm": 56.6 * OZ_IN, "detail": "full"}
    listed = {c["id"]: c for c in _compact(client, full)}
    passed = [r for r in rows if r["status"] == "passed"]
    assert [r["id"] for r in passed] == list(listed)
    for r in passed:
        assert float(r["motor_use"]) == pytest.approx(listed[r["id"]]["motor_use"], rel=1e-9)
        peak = listed[r["id"]]["torque"]["peak_motor_nm"]
        assert float(r["torque.peak_motor [oz in]"]) == pytest.approx(peak / OZ_IN, rel=1e-9)


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
    header, *rows = full.split("\r\n")[:-1]
    assert rows and sum(h.startswith("input:") for h in header.split(",")) == len(FIELDS)


def test_the_screw_type_shows_in_the_table_and_the_compare(
    client: TestClient, catalog: Catalog
) -> None:
    """Leadscrews and ball screws rank together: each row's Type column and its id cell's
    tag say which it is (a ball screw carries no TFE-coating tag, and a preloaded ball nut
    is 'preloaded', not 'anti-backlash'); the compare page has the Type row."""
    query = {"load": 100, "speed": 50, "length": 500}
    page = BeautifulSoup(client.get("/", params=query).text, "html.parser")
    heads = [th.get_text(" ", strip=True) for th in page.select("table.candidates thead th")]
    column = heads.index("Type")
    seen = set()
    for row in page.select("tbody.candidate"):
        spec = catalog.by_id[row["data-id"]]
        seen.add(spec.screw_type)
        cells = row.select_one("tr").find_all(["th", "td"], recursive=False)
        assert cells[column].get_text(strip=True) == spec.screw_type
        tags = [t.get_text() for t in row.select("th.screw .tag")]
        if spec.screw_type == "ball":
            assert "ball screw" in tags and not row.select("th.screw .coating")
            assert ("preloaded" in tags) == spec.anti_backlash and "anti-backlash" not in tags
        else:
            assert row.select_one("th.screw .coating") and "ball screw" not in tags
    assert seen == {"ball", "lead"}
    ball = next(s.id for s in catalog.screws if s.screw_type == "ball")
    lead = next(s.id for s in catalog.screws if s.screw_type == "lead")
    compare = client.get("/compare", params={**query, "ids": f"{ball},{lead}"})
    assert compare.status_code == 200
    table = BeautifulSoup(compare.text, "html.parser")
    row = next(tr for tr in table.select("tr") if tr.th and tr.th.get_text(strip=True) == "Type")
    assert [td.get_text(strip=True) for td in row.find_all("td")] == ["ball", "lead"]
