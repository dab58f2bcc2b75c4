"""The /versus page: the best leadscrew and the best ball screw side by side, each cell
the API's select number for that screw; a kind with no passing screw shows its nearest
rejected one and what excludes it; the results page links to it when both kinds are on
offer."""

from typing import Any

from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

#: a light axis with a move: both kinds pass
LIGHT = {
    "load": "100", "speed": "50", "length": "500", "stroke": "200", "cycles_per_day": "1000",
    "required_life_years": "5",
}  # fmt: skip
LIGHT_API = {
    "load_n": "100", "speed_mm_s": "50", "length_mm": "500", "stroke_mm": "200",
    "cycles_per_day": "1000", "required_life_years": "5",
}  # fmt: skip
#: 3 kN at 400 mm/s: no leadscrew's nut takes the sliding speed, a ball screw passes
FAST = {"load": "3000", "speed": "400", "length": "500"}


def _page(client: TestClient, query: dict[str, str]) -> BeautifulSoup:
    response = client.get("/versus", params=query)
    assert response.status_code == 200, response.text
    return BeautifulSoup(response.text, "html.parser")


def _rows(page: BeautifulSoup) -> dict[str, list[str]]:
    return {
        tr["data-row"]: [td.contents[0].strip() for td in tr.select("td")]
        for tr in page.select("table.versus tbody tr")
    }


def _api_select(client: TestClient, ids: list[str]) -> list[dict[str, Any]]:
    """The API's select records of ``ids`` for the same axis (each kind's family)."""
    out = []
    for i in ids:
        screw = client.app.state.catalog.index  # type: ignore[attr-defined]
        family = screw.table.screws[screw.positions[i]].family_id
        body = client.get(
            "/api/v1/select", params={**LIGHT_API, "family": family, "detail": "full"}
        )
        out.append(next(c for c in body.json()["candidates"] if c["id"] == i))
    return out


def test_both_columns_carry_the_apis_select_numbers(client: TestClient) -> None:
    page = _page(client, LIGHT)
    heads = page.select("table.versus thead th.cid")
    assert [h["data-kind"] for h in heads] == ["lead", "ball"]
    ids = [h.contents[2].strip() for h in heads]
    api = _api_select(client, ids)
    rows = _rows(page)
    assert rows["screw_type"] == ["lead", "ball"]
    assert rows["efficiency"] == [f"{c['efficiency'] * 100:.0f} %" for c in api]
    assert [float(v) for v in rows["lead_mm"]] == [c["lead_mm"] for c in api]
    assert [float(v) for v in rows["rpm"]] == [round(c["rpm"]) for c in api]
    assert [float(v) for v in rows["peak_power_w"]] == [
        float(f"{c['peak_power_w']:.4g}") for c in api
    ]
    assert [float(v) for v in rows["torque.peak_motor_nm"]] == [
        float(f"{c['torque']['peak_motor_nm']:.4g}") for c in api
    ]
    # life: the leadscrew's wear band in years, the ball nut's L10 (its check's capacity)
    lead_years = "–".join(f"{v:.3g}" for v in api[0]["life"]["years"])
    l10 = next(k["limit"] for k in api[1]["checks"] if k["name"] == "ball_life")
    assert rows["life"] == [f"{lead_years} years (wear)", f"{l10:.3g} years (L10)"]
    assert rows["accuracy.lead_error_mm"] == [
        "—" if (e := c["accuracy"]["lead_error_mm"]) is None else f"{e:.3g}" for c in api
    ]
    assert rows["accuracy.lead_error_mm"][1] != "—"  # a ball screw's grade gives one
    for cell, c in zip(rows["accuracy.backlash_mm"], api, strict=True):
        assert [float(v) for v in cell.split("–")] == [
            float(f"{v:.3g}") for v in c["accuracy"]["backlash_mm"]
        ]
    # the ball screw's rolling thread is the more efficient (the best mark says so)
    ball_efficiency = page.select_one('tr[data-row="efficiency"] td:nth-of-type(2)')
    assert "best" in ball_efficiency["class"]
    assert api[1]["efficiency"] > api[0]["efficiency"]


def test_notes_are_cited_and_no_price_is_shown(client: TestClient) -> None:
    page = _page(client, LIGHT)
    notes = page.select(".versus-notes li")
    assert notes and all(n.select_one("cite").text.count("https://") == 1 for n in notes)
    assert "No price band" in page.select_one(".price-note").text


def test_a_kind_that_fails_shows_its_nearest_rejected_and_why(client: TestClient) -> None:
    page = _page(client, FAST)
    lead, ball = page.select(".versus-status li")
    api = client.get(
        "/api/v1/versus", params={"load_n": "3000", "speed_mm_s": "400", "length_mm": "500"}
    ).json()["sides"]
    nearest = api[0]["candidate"]["id"]
    assert "no leadscrew passes" in lead.text and nearest in lead.text
    assert all(label in lead.text for label in api[0]["excluded_by"])
    assert f"{api[1]['candidate']['id']} passes" in ball.text
    head = page.select_one('table.versus thead th[data-kind="lead"]')
    assert nearest in head.text and "nearest rejected" in head.text


def test_the_results_page_links_to_it_when_both_kinds_are_offered(client: TestClient) -> None:
    link = BeautifulSoup(client.get("/", params=LIGHT).text, "html.parser").select_one(
        "a.versus-link"
    )
    assert link.text == "Leadscrew against ball screw"
    assert link["href"].startswith("/versus?")
    # one kind's families only: no link
    page = BeautifulSoup(client.get("/", params={**LIGHT, "family": "B"}).text, "html.parser")
    assert page.select_one("a.versus-link") is None


def test_bad_input_is_a_422_page(client: TestClient) -> None:
    assert client.get("/versus", params={**LIGHT, "load": "-1"}).status_code == 422


def test_a_vertical_axis_says_which_kind_holds_with_the_power_off(client: TestClient) -> None:
    """A 5 kg vertical load without a brake: the leadscrew's thread self-locks, a ball
    screw back-drives (its efficiency too high to lock) and needs the brake its fix names."""
    query = {"load": "50", "moving_mass_kg": "5", "speed": "50", "length": "400"}
    page = _page(client, {**query, "orientation": "vertical"})
    api_query = {"load_n": "50", "moving_mass_kg": "5", "speed_mm_s": "50", "length_mm": "400"}
    lead, ball = client.get(
        "/api/v1/versus", params={**api_query, "orientation": "vertical"}
    ).json()["sides"]
    assert (lead["candidate"]["holds_by"], lead["candidate"]["holds_power_off"]) == ("thread", True)
    assert ball["candidate"]["holds_power_off"] is False
    assert _rows(page)["holds_power_off"] == ["yes: the thread self-locks", "no: a brake is needed"]
    assert "brake" in page.select(".versus-status li")[1].text


def test_a_kind_no_filter_admits_is_blamed_on_the_filters_not_the_families(
    client: TestClient,
) -> None:
    """A bronze nut asked for, no family given: no ball screw is eligible. The page said
    "the catalog offers none for these families", naming a filter that was not set."""
    page = client.get("/versus?load=3000&speed=300&length=1500&nut_material=bronze").text
    ball = BeautifulSoup(page, "html.parser").select_one("li[data-kind=ball]").text
    assert "for these families" not in ball
    assert "the filters (families, nut material, coating, lead)" in ball


def test_the_travel_is_in_the_pages_unit(client: TestClient) -> None:
    """Without a duty the life row gives the travel in the page's unit: miles on an
    inch page."""
    query = {"load": "20", "speed": "2", "length": "20", "length_unit": "in"}
    life = _rows(_page(client, query))["life"]
    assert all(" mi travelled" in cell or cell.endswith("(L10)") or cell == "—" for cell in life)
    assert any(" mi travelled" in cell for cell in life), life


def test_a_back_driving_screw_not_asked_to_hold_still_has_a_load_to_hold(
    client: TestClient,
) -> None:
    """A 1 kg vertical Z axis that does not ask to hold with the power off: B4000-L8-TFE
    back-drives and needs a brake of 0.01671 N m (0.0111 N m to hold, times the brake's
    service factor 1.5), at least 0.0168 N m rounded up, as its own holding row says; the
    power-off row said "nothing to hold"."""
    query = {
        "load": "0", "moving_mass_kg": "1", "orientation": "vertical", "lead": "8",
        "speed": "12", "length": "350", "accel": "200", "stroke": "200",
        "hold_power_off": "false",
    }  # fmt: skip
    rows = _rows(_page(client, query))
    assert rows["holding_torque.brake_to_fit_nm"][0].startswith("brake ≥ 0.0168")
    assert rows["holds_power_off"][0] == "no: a brake is needed"


def test_a_ball_nut_s_l10_is_one_figure_named_as_the_table_names_it(client: TestClient) -> None:
    """Without a required life a ball nut's life is its L10 band of one value: the row
    read '3,670,000–3,670,000 years (l10)' where the results table reads one figure, L10."""
    query = {
        "load": "0", "moving_mass_kg": "1.5", "speed": "300", "length": "500",
        "accel": "10000", "stroke": "400", "cycles_per_day": "20000",
        "motor": "17hs19-2004s1",
    }  # fmt: skip
    ball = _rows(_page(client, query))["life"][1]
    assert ball.endswith(" years (L10)")
    assert "–" not in ball
