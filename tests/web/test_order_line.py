"""The ordering line reaches every edge from its one row of the output table: the API's
JSON (select, evaluate, a custom screw), the CSV, the compare page and the report."""

import csv
import io

from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.catalog import Catalog
from app.catalog.ordering import ordering_basis, ordering_line

API_AXIS = {"load_n": "100", "speed_mm_s": "50", "length_mm": "500", "limit": "5"}
PAGE_AXIS = {"load": "100", "speed": "50", "length": "500", "limit": "5"}


def _select(client: TestClient) -> list[dict[str, object]]:
    """The full select's candidates: the line (a few hundred bytes a candidate) is in the
    full form, the CSV, compare and report, not in the compact select."""
    return client.get("/api/v1/select", params={**API_AXIS, "detail": "full"}).json()["candidates"]


def test_the_api_gives_each_candidate_its_line(client: TestClient, catalog: Catalog) -> None:
    found = _select(client)
    assert found
    for c in found:
        assert c["order_line"] == ordering_line(catalog.by_id[str(c["id"])], 0.5)
    full = client.get("/api/v1/select", params={**API_AXIS, "detail": "full"}).json()
    for c in full["candidates"]:
        assert c["order_basis"] == ordering_basis(catalog.by_id[c["id"]])


def test_evaluate_gives_the_line_of_a_catalog_screw_and_of_a_custom_one(
    client: TestClient,
) -> None:
    app = {"load_n": 100, "speed_mm_s": 50, "length_mm": 300}
    body = {"application": app, "screw": {"catalog_id": "Tr16x8(P4)-bronze"}}
    tr = client.post("/api/v1/evaluate", json=body).json()["candidate"]
    assert tr["order_line"].startswith("Trapezoidal leadscrew Tr16x8(P4)-7e right-hand")
    assert "nut Tr16x8(P4)-7H" in tr["order_line"]
    custom = {
        "outer_diameter_mm": 12.7,
        "root_diameter_mm": 9.906,
        "lead_mm": 10.0,
        "friction_dynamic": 0.15,
        "friction_static": 0.2,
    }
    own = client.post("/api/v1/evaluate", json={"application": app, "screw": custom}).json()
    line = own["candidate"]["order_line"]
    assert line.startswith(
        "Leadscrew to your geometry: outer diameter 12.7 mm, root diameter 9.906 mm, lead 10 mm"
    )
    assert "300 mm between the supports" in line and "Confirm" not in line


def test_the_csv_carries_the_line(client: TestClient) -> None:
    rows = list(csv.DictReader(io.StringIO(client.get("/export.csv", params=PAGE_AXIS).text)))
    lines = {c["id"]: c["order_line"] for c in _select(client)}
    passed = [r for r in rows if r["status"] == "passed"]
    assert passed and {r["id"]: r["order_line"] for r in passed} == lines


def test_the_compare_page_has_a_row_of_lines(client: TestClient) -> None:
    found = _select(client)[:2]
    ids = [str(c["id"]) for c in found]
    page = client.get("/compare", params=[*PAGE_AXIS.items(), *(("ids", i) for i in ids)])
    table = BeautifulSoup(page.text, "html.parser").select_one("table.compare")
    cells = table.select_one("tr[data-row=order_line]").select("td")
    assert [td.text.strip() for td in cells] == [c["order_line"] for c in found]


def test_the_report_shows_the_line_with_a_copy_button(client: TestClient) -> None:
    top = _select(client)[0]
    page = BeautifulSoup(
        client.get("/report", params={**PAGE_AXIS, "id": top["id"]}).text, "html.parser"
    )
    block = page.select_one(".order")
    assert block.select_one("code.order-line").text == top["order_line"]
    button = block.select_one("button.copy-order")
    # without JavaScript the button stays hidden and the line is plain text to select
    assert button["type"] == "button" and button.has_attr("hidden")
    assert block.select_one(".order-basis").text.strip()
