"""The thrust bearing at the edges (issue 29, item 10): a library support unit or typed
ratings through the API, field-level 422s for an unknown unit and for a span from the
thrust bearing longer than the screw, and the page's inline error."""

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from tests.api.calls import check, evaluate

BASE = {"load_n": 1500.0, "speed_mm_s": 50.0, "length_mm": 500.0}


def test_a_library_unit_rates_the_thrust_bearing(client: TestClient) -> None:
    """THK FK12 (permissible static load 3.25 kN, THK Support Unit catalog 513-2E) over
    the static safety factor 2: 1625 N allowed against the peak thrust 1500 + 20 kg x
    5 m/s^2 = 1600 N."""
    c = evaluate(
        client, "ZBX8000-L10", **BASE, moving_mass_kg=20.0, accel_mm_s2=5000.0,
        support_id="thk-fk12",
    )  # fmt: skip
    bearing = check(c, "support_static")
    assert bearing["passed"]
    assert bearing["value"] == pytest.approx(1600.0)
    assert bearing["limit"] == pytest.approx(1625.0)
    assert "support unit thk-fk12" in bearing["message"]


def test_typed_ratings_override_the_library(client: TestClient) -> None:
    c = evaluate(client, "ZBX8000-L10", **BASE, support_id="thk-fk12", support_static_n=2000.0)
    assert check(c, "support_static")["limit"] == pytest.approx(1000.0)  # 2000 / 2


@pytest.mark.parametrize(
    ("change", "field", "words"),
    [
        ({"support_id": "nk-99"}, "support_id", "unknown support unit 'nk-99'"),
        ({"bearing_to_nut_mm": 600.0}, "bearing_to_nut_mm", "at most the screw length"),
        ({"support_static_safety_factor": 0.5}, "support_static_safety_factor", ""),
    ],
)
def test_bad_support_input_is_a_field_level_422(
    client: TestClient, change: dict[str, object], field: str, words: str
) -> None:
    r = client.get("/api/v1/select", params={**BASE, **change})
    assert r.status_code == 422, r.text
    detail = {d["field"]: d["message"] for d in r.json()["detail"]}
    assert words in detail[field]


def test_the_page_names_an_unknown_unit_inline(client: TestClient) -> None:
    page = client.get("/", params={"load": 100, "speed": 50, "length": 500, "support_id": "x1"})
    assert page.status_code == 200
    soup = BeautifulSoup(page.text, "html.parser")
    error = soup.select_one("#e-support_id")
    assert error is not None and "Unknown support unit 'x1'" in error.text
    options = [o["value"] for o in soup.select("datalist option")]
    assert "thk-fk12" in options
