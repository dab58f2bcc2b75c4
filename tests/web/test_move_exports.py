"""The CSV and the printed report carry the cycle: its moves as a table of inputs in the
display units, and the energy per cycle of each candidate."""

import csv
import io

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

LBF = 4.4482216152605  # N (NIST SP 811)
LB = 0.45359237  # kg (NIST SP 811)
#: out 300 mm and back against 10 N of friction each way ('opposes'), 2.5 kg out, 0.5 back
TEXT = "300:250:2500:2500:0.2:2.5:10:opposes;-300:250:2500:1500:0.2:0.5:10:opposes"
LINK = {"load": "10", "speed": "250", "length": "500", "moves": TEXT, "force_unit": "lbf"}
#: the work on a load that opposes the motion both ways: 10 N x 0.3 m x 2 moves
LOAD_WORK_J = 10 * 0.3 * 2


def test_the_csv_carries_the_moves_and_the_energy(client: TestClient) -> None:
    rows = list(csv.DictReader(io.StringIO(client.get("/export.csv", params=LINK).text)))
    passed = [r for r in rows if r["status"] == "passed"]
    assert passed
    for row in passed:
        assert float(row["move:1.dist [mm]"]) == 300 and float(row["move:2.dist [mm]"]) == -300
        assert float(row["move:2.decel [mm/s²]"]) == 1500
        assert float(row["move:1.mass [lb]"]) == pytest.approx(2.5 / LB, rel=1e-9)
        assert float(row["move:2.load [lbf]"]) == pytest.approx(10 / LBF, rel=1e-9)
        assert row["move:1.dir"] == "opposes"
        assert float(row["cycle_load_work_j [J]"]) == pytest.approx(LOAD_WORK_J, rel=1e-9)
        work = float(row["cycle_motor_work_j [J]"])
        losses = float(row["cycle_thread_loss_j [J]"]) + float(row["cycle_drag_loss_j [J]"])
        assert work >= LOAD_WORK_J + losses - float(row["cycle_regen_j [J]"]) - 1e-9
    assert not any(h.startswith("move:3.") for h in rows[0])


def test_a_csv_without_moves_has_no_move_columns(client: TestClient) -> None:
    link = {k: v for k, v in LINK.items() if k != "moves"}
    header = next(csv.reader(io.StringIO(client.get("/export.csv", params=link).text)))
    assert not any(h.startswith("move:") for h in header)


def test_the_report_carries_the_moves_and_the_energy(client: TestClient) -> None:
    response = client.get("/report", params=LINK)
    assert response.status_code == 200
    html = BeautifulSoup(response.text, "html.parser")
    table = html.select_one("table.report-moves")
    assert table is not None
    heads = [th.text.strip() for th in table.select("thead th")]
    assert "Load lbf" in heads and "Distance mm" in heads
    cells = [[td.text for td in tr.select("td")] for tr in table.select("tbody tr")]
    assert [row[0] for row in cells] == ["300", "-300"]
    assert float(cells[1][6]) == pytest.approx(10 / LBF, rel=1e-5)
    assert cells[0][7] == "opposes"
    energy = {
        div.select_one("dt").text: div.select_one("dd").text for div in html.select("dl.energy div")
    }
    assert energy["Work on the load per cycle"] == "6 J"
    assert set(energy) >= {"Motor work per cycle", "Braking energy per cycle"}


def test_a_report_without_moves_has_no_moves_table(client: TestClient) -> None:
    link = {k: v for k, v in LINK.items() if k != "moves"}
    html = BeautifulSoup(client.get("/report", params=link).text, "html.parser")
    assert html.select_one("table.report-moves") is None


@pytest.mark.parametrize("path", ["/export.csv", "/custom/export.csv"])
def test_a_bad_move_in_an_export_link_is_named_as_its_control_is(
    client: TestClient, path: str
) -> None:
    """The 422 of an export names a move's value as the table labels it ("Move 2 load
    direction"), not by its query name (``m1_dir``)."""
    screw = {"outer_diameter_mm": "10", "root_diameter_mm": "8", "lead_mm": "2",
             "friction_dynamic": "0.15", "friction_static": "0.2"}  # fmt: skip
    bad = TEXT.replace("0.5:10:opposes", "0.5:10:sideways")
    response = client.get(
        path, params={**screw, **LINK, "moves": bad} if "custom" in path else {**LINK, "moves": bad}
    )
    assert response.status_code == 422
    items = [li.text for li in BeautifulSoup(response.text, "html.parser").select("li")]
    assert items == ["Move 2 load direction: Input should be 'auto', 'opposes' or 'fixed'."]
