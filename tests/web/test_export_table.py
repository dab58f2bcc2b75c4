"""The CSV: one table, a row per candidate, a column per check's utilization and per input."""

import csv
import io

from fastapi.testclient import TestClient

from app.core.checks import REGISTRY
from app.web.export import UTILIZATION_UNIT

AXIS = {"load": "100", "speed": "50", "length": "500", "limit": "5"}
API_AXIS = {"load_n": "100", "speed_mm_s": "50", "length_mm": "500", "limit": "5"}


def _table(text: str) -> list[dict[str, str]]:
    """The CSV's one table, by heading."""
    return list(csv.DictReader(io.StringIO(text)))


def test_each_candidate_row_carries_every_checks_utilization(client: TestClient) -> None:
    rows = _table(client.get("/export.csv", params=AXIS).text)
    # the full form: every number at full precision (the compact one has 6 figures)
    api = client.get("/api/v1/select", params={**API_AXIS, "detail": "full"}).json()
    header = list(rows[0])
    for check in REGISTRY:
        assert f"utilization.{check.name} [{UTILIZATION_UNIT}]" in header
    passed = [r for r in rows if r["status"] == "passed"]
    assert [r["id"] for r in passed] == [c["id"] for c in api["candidates"]]
    for row, candidate in zip(passed, api["candidates"], strict=True):
        for check in REGISTRY:
            cell = row[f"utilization.{check.name} [{UTILIZATION_UNIT}]"]
            value = candidate["utilization"].get(check.name)
            if value is None:
                assert cell == ""
            else:  # written to 10 significant figures
                assert abs(float(cell) - value) <= 1e-9 * abs(value)


def test_the_csv_header_names_units(client: TestClient) -> None:
    header = _table(client.get("/export.csv", params={**AXIS, "length_unit": "in"}).text)[0]
    assert "lead [in]" in header and "torque.total [N m]" in header
    assert "input:load [N]" in header and "input:length [in]" in header


def test_every_row_carries_every_input_in_display_units(client: TestClient) -> None:
    """One table: each row stands alone when filtered, with the axis it was judged for."""
    params = {**AXIS, "length_unit": "in", "force_unit": "lbf", "load": "22.5"}
    rows = _table(client.get("/export.csv", params=params).text)
    assert len(rows) > 1
    assert {r["input:load [lbf]"] for r in rows} == {"22.5"}
    assert {float(r["input:length [in]"]) for r in rows} == {500.0}
    assert {r["input:end_fixity"] for r in rows} == {"fixed-simple"}


def test_the_governing_check_is_named_by_its_label_beside_its_id(client: TestClient) -> None:
    """The id in ``governing_check``, the words the page shows in a column of their own."""
    rows = _table(client.get("/export.csv", params=AXIS).text)
    labels = {check.name: check.label for check in REGISTRY}
    passed = [r for r in rows if r["status"] == "passed"]
    assert passed
    for row in passed:
        assert row["verdict.governs_label"] == labels[row["governing_check"]]


def test_a_move_gives_each_row_its_peak_and_rms_torque(client: TestClient) -> None:
    """With a move, the CSV carries the peak and the RMS motor torque the results table
    shows, each the API's for that screw."""
    move = {"stroke": "300", "accel": "1000", "moving_mass_kg": "5"}
    rows = _table(client.get("/export.csv", params={**AXIS, **move}).text)
    api_move = {"stroke_mm": "300", "accel_mm_s2": "1000", "moving_mass_kg": "5"}
    api = client.get("/api/v1/select", params={**API_AXIS, **api_move, "detail": "full"}).json()
    passed = [r for r in rows if r["status"] == "passed"]
    assert passed and len(passed) == len(api["candidates"])
    for row, candidate in zip(passed, api["candidates"], strict=True):
        for key in ("rms_nm", "peak_motor_nm"):
            cell = float(row[f"torque.{key.removesuffix('_nm')} [N m]"])
            assert abs(cell - candidate["torque"][key]) <= 1e-9 * candidate["torque"][key]
