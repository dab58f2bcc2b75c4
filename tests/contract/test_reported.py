"""The output table (``app.contract.reported``): every row names a real field of a
candidate, and each number reaches every edge its row names (the output model and views,
the results table, the CSV, the compare page, the guide, the formulas table); the screw's
rotary inertia, a number declared by its row alone, checked against the seed's table."""

import csv
import io
import math
from typing import Any

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.contract.reported import BY_KEY, REPORTED
from app.contract.schemas import VIEWS, CandidateOut
from app.core.checks import BY_NAME
from app.report.formulas import FORMULAS
from app.web.export import csv_name

#: a move and a motor, so every column shows (the no-move torque column aside)
MOVE = {
    "load": "20",
    "speed": "100",
    "length": "500",
    "lead": "10",
    "stroke": "300",
    "accel": "1000",
    "moving_mass_kg": "2",
    "cycles_per_day": "100",
    "max_torque": "1",
}
STILL = {"load": "100", "speed": "50", "length": "500", "lead": "10"}
API = {"load_n": 20, "speed_mm_s": 100, "length_mm": 500, "stroke_mm": 300, "lead_mm": 10}
API |= {"accel_mm_s2": 1000, "moving_mass_kg": 2, "cycles_per_day": 100}
#: a leadscrew first (it has every leadscrew row, PV among them): the leadscrew families
LEADSCREWS = ["B", "KHD", "TR-304", "TR-C45", "VHD", "ZBX"]

#: NIST SP 811 (2008) appendix B.8: 1 in = 0.0254 m and 1 oz = 0.45359237 / 16 kg, exact.
INCH_M = 0.0254
OZ_IN2_KG_M2 = 0.45359237 / 16 * INCH_M**2


def _soup(client: TestClient, path: str, params: dict[str, str]) -> BeautifulSoup:
    response = client.get(path, params=params)
    assert response.status_code == 200
    return BeautifulSoup(response.text, "html.parser")


def _at(candidate: dict[str, Any], key: str) -> tuple[bool, Any]:
    """(whether the JSON has the field, its value); through a list, its first item's."""
    value: Any = candidate
    for name in key.split("."):
        if isinstance(value, list):
            value = value[0]
        if not isinstance(value, dict) or name not in value:
            return False, None
        value = value[name]
    return True, value


def test_keys_are_unique_and_shown_rows_are_labelled() -> None:
    assert len(BY_KEY) == len(REPORTED)
    for row in REPORTED:
        if row.column or row.compare:
            assert row.label and row.help, row.key


def test_every_row_is_a_field_of_a_full_candidate(client: TestClient) -> None:
    body = client.post("/api/v1/select?detail=full", json={**API, "family": LEADSCREWS}).json()
    candidate = body["candidates"][0]
    for row in REPORTED:
        head, _, name = row.key.partition(".")
        if head == "utilization" and name:  # a check's utilization, where it applies
            assert name in BY_NAME and name in candidate["utilization"], row.key
            continue
        found, _ = _at(candidate, row.key)
        assert found, row.key
        assert head in CandidateOut.model_fields


def test_views_take_the_rows_that_name_them() -> None:
    for row in REPORTED:
        head, _, rest = row.key.partition(".")
        for view, wanted in (("row", row.column), ("csv", row.csv)):
            if not wanted:
                continue
            part = VIEWS[view][head]
            assert part is True or head == "utilization" or part[rest] is True, (view, row.key)


@pytest.mark.parametrize(
    ("params", "shown"),
    [(MOVE, ("always", "move", "motor")), (STILL, ("always", "no_move"))],
    ids=["move-and-motor", "still"],
)
def test_the_results_table_has_a_column_per_shown_row(
    client: TestClient, params: dict[str, str], shown: tuple[str, ...]
) -> None:
    page = _soup(client, "/", params)
    headings = [a.text for a in page.select("table.candidates thead abbr.col-help")]
    assert headings == [r.label for r in REPORTED if r.column and r.shown in shown]
    first = page.select_one("table.candidates tr.main")
    assert len(first.select("td, th")) == len(headings) + 1  # and the rank


def test_the_csv_compare_guide_and_formulas_carry_their_rows(client: TestClient) -> None:
    header = next(csv.reader(io.StringIO(client.get("/export.csv", params=MOVE).text)))
    api = {k: str(v) for k, v in API.items()}
    passing = client.get("/api/v1/select", params=api).json()["candidates"]
    ids = ",".join(c["id"] for c in passing[:3])
    compared = client.get("/api/v1/compare", params={**api, "ids": ids}).json()["candidates"]
    page = _soup(client, "/compare", {**MOVE, "ids": ids})
    rows = {tr["data-row"] for tr in page.select("table.compare tbody tr")}
    guide = {div["data-column"] for div in _soup(client, "/guide", {}).select("[data-column]")}
    for row in REPORTED:
        if row.csv:
            name = csv_name(row.key)
            assert any(h.split(" [")[0] in (name, f"{name}_min") for h in header) or any(
                h.startswith(f"{name}.") for h in header
            ), row.key
        if row.compare:
            has_value = any(_at(c, row.key)[1] is not None for c in compared)
            assert (row.key in rows) == has_value, row.key
        assert (row.key in guide) == row.column, row.key
        assert (row.key in FORMULAS) == (row.formula is not None), row.key


def test_the_screw_inertia_is_the_seed_tables_per_inch_times_the_length(
    client: TestClient,
) -> None:
    """Seed screw inertia table, B6000: 1.06e-7 kg m² per inch (catalog/b-series.toml;
    the printed exponent corrected by the catalog notes' OCR rule); over a 500 mm screw:
    1.06e-7 / 0.0254 x 0.5 = 2.0866e-6 kg m². Its row alone declares it: the field, the
    page's column, the CSV's column and the formula."""
    assert BY_KEY["screw_inertia_kg_m2"].source is not None
    assert "screw_inertia_kg_m2" not in CandidateOut.__base__.model_fields
    params = {**STILL, "family": "B"}
    body = client.get(
        "/api/v1/select",
        params={
            "load_n": 100,
            "speed_mm_s": 50,
            "length_mm": 500,
            "lead_mm": 10,
            "family": "B",
            "detail": "full",
        },
    ).json()
    b6000 = next(c for c in body["candidates"] if c["series"] == "B6000")
    expected_kg_m2 = 1.06e-7 / INCH_M * 0.5
    assert b6000["screw_inertia_kg_m2"] == pytest.approx(expected_kg_m2, rel=1e-9)
    # within 0.5-1.0 of a solid rod at the OD (the catalog notes' check; 303 stainless,
    # 8000 kg/m³): J = rho pi d^4 L / 32, the mass moment of a solid cylinder
    rod_kg_m2 = 8000 * math.pi * (b6000["outer_diameter_mm"] / 1000) ** 4 * 0.5 / 32
    assert 0.5 < b6000["screw_inertia_kg_m2"] / rod_kg_m2 < 1.0
    assert FORMULAS["screw_inertia_kg_m2"]["formula"] == "J = (J/L) x L"
    # the CSV in oz in² (the torque switch sets the inertia unit)
    rows = list(
        csv.DictReader(
            io.StringIO(client.get("/export.csv", params={**params, "torque_unit": "oz_in"}).text)
        )
    )
    cell = next(r for r in rows if r["series"] == "B6000" and r["id"] == b6000["id"])
    assert float(cell["screw_inertia [oz in²]"]) == pytest.approx(
        expected_kg_m2 / OZ_IN2_KG_M2, rel=1e-9
    )
    page = _soup(client, "/", params)
    shown = page.select_one(
        f'tbody.candidate[data-id="{b6000["id"]}"] td[data-label^="Screw inertia"]'
    )
    assert float(shown.text) == pytest.approx(expected_kg_m2, rel=1e-3)
