"""The 'nothing passes' advice on the page and through the API: every Apply link makes a
screw pass with the stated margin, proposals never land on a limit, and an axis no
leadscrew can do is said to be so, with why."""

from typing import Any
from urllib.parse import parse_qsl

import numpy as np
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient
from hypothesis import given, settings
from hypothesis import strategies as st

from app.catalog import Catalog
from app.contract.form import parse_inputs, parse_units
from app.core.remedy import MARGIN
from app.core.selection import screen


def _best_after(link: str, catalog: Catalog) -> float:
    """The lowest governing utilisation among the screws passing at the link's inputs
    (inf when none passes), read as the page reads the link."""
    values = dict(parse_qsl(link.split("?", 1)[1]))
    units = parse_units(values)
    inputs, errors = parse_inputs(values, units)
    assert inputs is not None, errors
    s = screen(inputs.to_core(catalog.motors), catalog.index)
    return float(s.max_utilization[s.passed].min()) if np.any(s.passed) else float("inf")


@settings(max_examples=20)
@given(
    load=st.sampled_from(["300", "3000", "10000", "40000"]),
    speed=st.sampled_from(["200", "500", "1500", "3000"]),
    length=st.sampled_from(["800", "1500", "3000"]),
    fixity=st.sampled_from(["fixed-free", "fixed-simple", "fixed-fixed"]),
    length_unit=st.sampled_from(["mm", "in"]),
)
def test_every_apply_link_passes_with_the_margin(
    client: TestClient,
    catalog: Catalog,
    load: str,
    speed: str,
    length: str,
    fixity: str,
    length_unit: str,
) -> None:
    params: dict[str, Any] = {"load": load, "speed": speed, "length": length,
                              "end_fixity": fixity}  # fmt: skip
    if length_unit == "in":  # the same axis typed in inches
        params.update(length_unit="in", length=f"{float(length) / 25.4:.6g}",
                      speed=f"{float(speed) / 25.4:.6g}")  # fmt: skip
    page = BeautifulSoup(client.get("/", params=params).text, "html.parser")
    notice = page.select_one(".notice.no-pass")
    if notice is None:
        return
    links = [a["href"] for a in notice.select("ul.remedies a.apply")]
    assert bool(links) != bool(notice.select(".impossible"))
    for link in links:
        assert _best_after(link, catalog) <= 1.0 / (1.0 + MARGIN), link


def test_an_impossible_axis_through_the_api_and_the_page(client: TestClient) -> None:
    """400 deg C: every nut's temperature rating excludes it and no input change helps."""
    hot = {"load_n": 100, "speed_mm_s": 50, "length_mm": 300, "ambient_c": 400}
    api = client.get("/api/v1/select", params=hot).json()
    assert api["counts"]["passed"] == 0
    assert api["summary"]["remedies"] == []
    why = api["summary"]["impossible"]
    assert why.startswith("No screw in the catalog can do this within the accepted inputs")
    assert "rated for this temperature" in why
    page = BeautifulSoup(
        client.get("/?load=100&speed=50&length=300&ambient_c=400").text, "html.parser"
    )
    notice = page.select_one(".notice.no-pass")
    assert notice.select_one(".impossible").text.strip() == why
    assert not notice.select("a.apply")


def test_a_fast_long_axis_gets_remedies_over_several_dimensions(client: TestClient) -> None:
    """2 m fixed-free at 400 mm/s: critical speed excludes all; the remedies include a
    change of the mounting, and a shorter screw together with a lower speed."""
    params = {"load": "100", "speed": "400", "length": "2000", "end_fixity": "fixed-free"}
    page = BeautifulSoup(client.get("/", params=params).text, "html.parser")
    items = page.select(".no-pass ul.remedies li")
    assert items
    fields = [li["data-fields"].split() for li in items]
    assert any("end_fixity" in f for f in fields)
    assert any({"length", "speed"} <= set(f) for f in fields)  # shorter AND slower
    for li in items:
        assert "then pass, the best at" in li.text
