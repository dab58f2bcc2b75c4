"""The acceleration's unit (issue 34, item 5): mm/s², m/s², g (the standard acceleration
of gravity, g_n = 9.80665 m/s² exactly: CGPM 1901, NIST SP 811 B.8) and in/s², through
the unit table, converted at the edge only; share links keep the choice and reproduce
the same answer."""

from urllib.parse import parse_qsl

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.contract.form import parse_units
from app.contract.units import DEFAULT_UNITS, display_system, to_api

BASE = "load=50&speed=200&length=500&stroke=300&moving_mass_kg=5"
#: 2 m/s² in each unit the page offers (2 / 9.80665 g; 2000 / 25.4 in/s²)
TWO_M_S2 = {
    "mm_s2": "2000",
    "m_s2": "2",
    "g": "0.203943242595",
    "in_s2": "78.7401574803",
}


def soup(text: str) -> BeautifulSoup:
    return BeautifulSoup(text, "html.parser")


@pytest.mark.parametrize(
    ("choice", "symbol", "mm_s2"),
    [
        ("mm_s2", "mm/s²", 1.0),
        ("m_s2", "m/s²", 1000.0),
        ("g", "g", 9806.65),
        ("in_s2", "in/s²", 25.4),
    ],
)
def test_each_choice_is_its_unit_exactly(choice: str, symbol: str, mm_s2: float) -> None:
    units = {**DEFAULT_UNITS, "accel_unit": choice}
    assert display_system(units)["accel"] == (symbol, mm_s2)
    assert to_api(1.0, "accel", units) == mm_s2


def test_a_page_in_inches_takes_in_s2_unless_it_names_another() -> None:
    assert parse_units({"length_unit": "in"})["accel_unit"] == "in_s2"
    assert parse_units({"length_unit": "in", "accel_unit": "g"})["accel_unit"] == "g"
    assert parse_units({"accel_unit": "furlongs"})["accel_unit"] == "mm_s2"


def _peaks(page: BeautifulSoup) -> list[tuple[str, str]]:
    rows = page.select("tbody.candidate")
    return [(r.select_one(".cid").text, r.select_one(".torque-peak").text) for r in rows]


def test_every_unit_gives_the_same_answer_and_its_link_keeps_it(client: TestClient) -> None:
    answers = {}
    for choice, typed in TWO_M_S2.items():
        page = soup(client.get(f"/?{BASE}&accel={typed}&accel_unit={choice}").text)
        label = page.select_one("label[for=f-accel]").get_text(" ", strip=True)
        assert label.endswith(display_system({**DEFAULT_UNITS, "accel_unit": choice})["accel"][0])
        answers[choice] = _peaks(page)
        link = page.select_one("a.share-link")["href"]
        params = dict(parse_qsl(link.split("?", 1)[1]))
        assert (params.get("accel_unit", "mm_s2"), params["accel"]) == (choice, typed)
        assert _peaks(soup(client.get(link).text)) == answers[choice]
    assert answers["mm_s2"] and all(a == answers["mm_s2"] for a in answers.values())


def test_switching_the_unit_converts_the_typed_number(client: TestClient) -> None:
    query = f"/?{BASE}&accel=2000&from_accel_unit=mm_s2&accel_unit=g"
    page = soup(client.get(query).text)
    assert float(page.select_one("#f-accel")["value"]) == pytest.approx(2 / 9.80665, rel=1e-4)
