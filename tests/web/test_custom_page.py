"""The page of one's own screw (/custom), its exports, the catalog grouped by family,
and the robust, assumed-limit and warning marks of the selector's results."""

import csv
import io
import json
from urllib.parse import parse_qsl

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.catalog import Catalog
from app.contract.fields import FIELDS
from app.contract.screws import CustomScrewIn, MaterialIn
from app.web.screw_form import BY_NAME, MATERIAL_FIELDS, SCREW_FIELDS

SCREW = (
    "outer_diameter_mm=10&root_diameter_mm=8&lead_mm=2&friction_dynamic=0.15&friction_static=0.2"
)
AXIS = "load=100&speed=50&length=500"
QUERY = f"{SCREW}&pv_limit_mpa_m_s=3&{AXIS}"
HX = {"HX-Request": "true"}


def soup(text: str) -> BeautifulSoup:
    return BeautifulSoup(text, "html.parser")


def api_evaluate(client: TestClient, screw: dict[str, object]) -> dict[str, object]:
    body = {"application": {"load_n": 100, "speed_mm_s": 50, "length_mm": 500}, "screw": screw}
    response = client.post("/api/v1/evaluate", json=body)
    assert response.status_code == 200, response.text
    result: dict[str, object] = response.json()
    return result


def test_screw_fields_are_the_api_models_fields() -> None:
    names = [f.name for f in SCREW_FIELDS]
    assert names == [n for n in CustomScrewIn.model_fields if n not in ("material", "nut_material")]
    assert [f.name for f in MATERIAL_FIELDS] == list(MaterialIn.model_fields)
    assert (BY_NAME["outer_diameter_mm"].label, BY_NAME["outer_diameter_mm"].unit) == (
        "Outer diameter",
        "mm",
    )


def test_empty_page_has_a_labelled_field_for_every_screw_and_application_input(
    client: TestClient,
) -> None:
    page = soup(client.get("/custom").text)
    for field in (*SCREW_FIELDS, *MATERIAL_FIELDS):
        assert page.select_one(f"label[for=f-{field.name}]"), field.name
    assert page.select_one("select#f-material")
    for name in ("load", "speed", "length", "end_fixity", "moving_mass_kg"):
        assert page.select_one(f"[name={name}]"), name
    assert page.select_one("p.prompt")


def test_custom_screw_shows_the_api_answer_with_user_provenance(client: TestClient) -> None:
    response = client.get(f"/custom?{QUERY}")
    page = soup(response.text)
    api = api_evaluate(
        client,
        {
            "outer_diameter_mm": 10,
            "root_diameter_mm": 8,
            "lead_mm": 2,
            "friction_dynamic": 0.15,
            "friction_static": 0.2,
            "pv_limit_mpa_m_s": 3,
        },
    )["candidate"]
    assert isinstance(api, dict)
    checks = [li["data-check"] for li in page.select("ol.checks li.check")]
    assert checks == [k["name"] for k in api["checks"]]
    governing = page.select_one(f"li.check[data-check={api['governing_check']}] .tag")
    assert governing is not None and governing.text == "governing"
    assert page.select_one(".custom-verdict .governing")
    kinds = {s["data-value"]: s.select_one(".kind") for s in page.select("ul.sources li")}
    assert kinds["root_diameter"].text == kinds["pv_limit"].text == "user"
    assert [f["id"] for f in page.select(".chart")] == [
        "chart-critical_speed",
        "chart-pv",
        "chart-torque",
    ]


def test_share_link_carries_the_whole_screw_and_reopens_the_same(client: TestClient) -> None:
    page = soup(
        client.get(
            f"/custom?{QUERY}&material=custom&youngs_modulus_pa=1.9e11&density_kg_m3=7900"
        ).text
    )
    link = page.select_one("a.share-link")["href"]
    shared = dict(parse_qsl(link.split("?", 1)[1]))
    assert shared["material"] == "custom" and float(shared["youngs_modulus_pa"]) == 1.9e11
    assert shared["pv_limit_mpa_m_s"] == "3" and shared["load"] == "100"
    again = soup(client.get(link).text)
    assert again.select_one("a.share-link")["href"] == link
    assert again.select_one(".check-value").text == page.select_one(".check-value").text


def test_root_above_outer_is_an_inline_error_and_the_text_is_kept(client: TestClient) -> None:
    bad = QUERY.replace("root_diameter_mm=8", "root_diameter_mm=12")
    page = soup(client.get(f"/custom?{bad}").text)
    assert page.select_one("#e-root_diameter_mm").text == "Must be smaller than outer diameter."
    assert page.select_one("#f-root_diameter_mm")["value"] == "12"
    assert page.select_one("#f-root_diameter_mm")["aria-invalid"] == "true"
    assert page.select_one(".notice.invalid")


def test_bad_text_and_own_material_errors_are_per_field(client: TestClient) -> None:
    query = f"{AXIS}&{SCREW.replace('lead_mm=2', 'lead_mm=abc')}&material=custom&density_kg_m3=0.1"
    page = soup(client.get(f"/custom?{query}").text)
    assert page.select_one("#e-lead_mm").text == "Enter a number."
    assert page.select_one("#e-youngs_modulus_pa").text == "Required."
    assert page.select_one("#e-density_kg_m3").text.startswith("Must be at least 1")
    assert page.select_one("#f-lead_mm")["value"] == "abc"


def test_htmx_request_gets_results_and_out_of_band_errors(client: TestClient) -> None:
    """The errors of an answer come as one hidden out-of-band list of the fields in error,
    as the selector's do (app.js shows each once its field has been left or the form
    submitted), not as a swap per field."""
    response = client.get(f"/custom?{QUERY}", headers=HX)
    assert response.headers["HX-Push-Url"].startswith("/custom?")
    page = soup(response.text)
    assert page.select_one("#field-errors[hx-swap-oob][hidden]").select("[data-error-for]") == []
    assert page.select("span.error[hx-swap-oob]") == []
    query = QUERY.replace("lead_mm=2", "lead_mm=x").replace(
        "root_diameter_mm=8", "root_diameter_mm=12"
    )
    bad = client.get(f"/custom?{query}", headers=HX)
    assert bad.headers["HX-Push-Url"] == "false"
    listed = soup(bad.text).select("#field-errors[hx-swap-oob] [data-error-for]")
    assert {item["data-error-for"]: item.text for item in listed} == {
        "lead_mm": "Enter a number.",
        "root_diameter_mm": "Must be smaller than outer diameter.",
    }


def test_the_screw_summary_names_each_value_by_its_label(client: TestClient) -> None:
    page = soup(client.get(f"/custom?{QUERY}&drag_torque_nm=0.01").text)
    rows = {div.dt.get_text(): div.dd.get_text() for div in page.select("dl.screw-inputs > div")}
    assert rows == {
        "Screw material": "steel",
        "Outer diameter": "10 mm",
        "Root (minor) diameter": "8 mm",
        "Lead": "2 mm",
        "Running friction coefficient": "0.15",
        "Static friction coefficient": "0.2",
        "Nut drag torque": "0.01 N m",
        "Nut PV limit": "3 MPa m/s",
    }
    shown = page.select_one("main").get_text(" ")
    assert not [f.name for f in BY_NAME.values() if f.name in shown]


def test_exports_of_the_custom_screw(client: TestClient) -> None:
    rows = list(csv.DictReader(io.StringIO(client.get(f"/custom/export.csv?{QUERY}").text)))
    assert len(rows) == 1  # one table, the screw's row
    assert rows[0]["id"] == "custom" and rows[0]["status"] in ("passed", "rejected")
    assert rows[0]["screw:outer_diameter_mm [mm]"] == "10"
    assert rows[0]["input:load [N]"] == "100.0"
    body = client.get(f"/custom/export.json?{QUERY}").json()
    assert body["candidate"]["id"] == "custom" and body["inputs"]["load_n"] == 100


def test_exports_with_bad_input_are_422(client: TestClient) -> None:
    bad = QUERY.replace("root_diameter_mm=8", "root_diameter_mm=12")
    for path in ("/custom/export.csv", "/custom/export.json"):
        response = client.get(f"{path}?{bad}")
        assert response.status_code == 422
        assert "Root (minor) diameter" in response.text
    assert client.get("/custom/export.csv").status_code == 422


def test_selector_links_to_the_custom_page_and_each_detail_tries_its_screw(
    client: TestClient,
) -> None:
    assert soup(client.get("/").text).select_one("a.custom-link[href='/custom']")
    detail = soup(client.get("/detail?load=14&speed=20&length=200&id=B4000-L2").text)
    link = detail.select_one(".try-custom a")["href"]
    values = dict(parse_qsl(link.split("?", 1)[1]))
    assert values["outer_diameter_mm"] == "6.35" and values["lead_mm"] == "2"
    assert values["load"] == "14"
    tried = soup(client.get(link).text)
    assert tried.select_one(".custom-verdict")
    assert tried.select_one("#f-friction_static")["value"] == values["friction_static"]


def test_a_detail_reached_through_the_selectors_filters_tries_its_screw_alone(
    client: TestClient,
) -> None:
    """The selector's own choices (a result limit, a lead, a family, a ranking) choose
    among the catalog's screws: the page of one's own screw refuses them ('limit' is not
    read on this page) and would show no verdict. The link leaves them out and gives the
    verdict of the same screw: Tr16x4-ptfe, 10 kg and 100 N lifted 300 mm 500 times a day
    for 5 years, held by a 1 N m brake, passes on both pages."""
    axis = "load=100&orientation=vertical&moving_mass_kg=10&speed=50&length=400&stroke=300"
    axis += "&cycles_per_day=500&required_life_years=5&brake_torque=1"
    chosen = "&limit=5&lead=4&family=TR-304&rank_by=size"
    detail = soup(client.get(f"/detail?{axis}{chosen}&id=Tr16x4-ptfe").text)
    link = detail.select_one(".try-custom a")["href"]
    names = {name for name, _ in parse_qsl(link.split("?", 1)[1])}
    assert not names & {"limit", "lead", "family", "rank_by"}
    tried = client.get(link).text
    assert "not read on this page" not in tried
    assert soup(tried).select_one(".custom-verdict").text.strip().startswith("Passes")


def test_a_ball_screw_is_not_offered_to_the_page_of_ones_own_sliding_screw(
    client: TestClient,
) -> None:
    """The page of one's own screw judges a sliding nut: a ball screw tried there lost
    its ball nut and was judged as a leadscrew (R12-04B1-RSIT: a PV of 20,769 psi ft/min
    and a failed life). Its detail offers no such link; a leadscrew's does."""
    axis = "load=50&speed=200&length=500&stroke=300&accel=2000&moving_mass_kg=5"
    ball = soup(client.get(f"/detail?{axis}&id=R10-02.5T2-RSIT").text)
    assert ball.select_one("dl.facts") and not ball.select_one(".try-custom")
    assert soup(client.get(f"/detail?{axis}&id=Tr8x8(P2)-ptfe").text).select_one(".try-custom")


def test_a_seed_nuts_try_link_says_its_ratings_stay_behind(client: TestClient) -> None:
    """B4000-L12-TFE passes with a 3-year life on its seed nut's wear rating. The page of
    one's own screw takes its geometry, friction and PV limit, not the nut's design load
    or wear: the link says so, and there the life's fix names what to give, not a series
    to choose. An ISO nut (Tr16x4-ptfe) is one of that page's nut materials: its link
    takes the nut along."""
    axis = "load=10&moving_mass_kg=0.5&speed=150&length=350&accel=3000&stroke=300"
    axis += "&cycles_per_day=500&required_life_years=3"
    detail = soup(client.get(f"/detail?{axis}&id=B4000-L12-TFE").text)
    note = detail.select_one(".try-custom .unit").text
    assert "does not judge its design load or life" in note
    tried = soup(client.get(detail.select_one(".try-custom a")["href"]).text)
    fix = tried.select_one("li.check[data-check='life'] .fix").text
    assert "Give the nut a material whose wear is rated" in fix and "series" not in fix
    iso = soup(client.get(f"/detail?{axis}&id=Tr16x4-ptfe").text)
    assert "friction and nut on the page" in iso.select_one(".try-custom .unit").text


# the selector's marks


def test_governing_check_says_robust_or_marginal_and_assumed(client: TestClient) -> None:
    robust = soup(client.get("/detail?load=14&speed=20&length=200&id=B4000-L2").text)
    governing = robust.select_one("li.check:has(.tag)")
    assert governing.select_one(".mark.robust") and governing.select_one(".mark.assumed")
    marginal = soup(client.get("/detail?load=20&speed=20&length=200&id=B4000-L2").text)
    mark = marginal.select_one("li.check:has(.tag) .mark.marginal")
    assert mark is not None and "PV limit" in mark.text  # in words, never the catalog key
    assert "pv_limit_mpa_m_s" not in mark.text
    assert not marginal.select(".mark.robust")


def test_warnings_are_listed_beside_the_candidate(client: TestClient) -> None:
    axis = "load=20&speed=200&length=300&lead=10&coating=none&family=B"
    page = soup(client.get(f"/?{axis}").text)
    cell = page.select_one("tbody.candidate td[data-label=Governing]")
    assert cell.select_one(".mark.warned").text == "Traverse speed"
    detail = soup(client.get(f"/detail?{axis}&id=B4000-L10").text)
    assert [li["data-check"] for li in detail.select("ul.warnings li")] == ["traverse_speed"]
    # failed advice is badged as advice; a failed limit (its PV here) as a fail
    badge = detail.select_one("li.check[data-check=traverse_speed] .badge")
    assert badge.text == "advice" and "warn" in badge["class"]
    assert detail.select_one("li.check[data-check=pv] .badge").text == "fail"


# the catalog


def test_catalog_groups_series_by_family_with_a_comparison_table(
    catalog_page: BeautifulSoup, catalog: Catalog
) -> None:
    page = catalog_page
    sections = page.select("section.family")
    families = list(dict.fromkeys(s.family for s in catalog.series.values()))
    assert [s["data-family"] for s in sections] == families
    for section in sections:
        series = [s for s in catalog.series.values() if s.family == section["data-family"]]
        assert section.select_one("h2").text.startswith(series[0].family_name)
        rows = section.select("table.family-compare tbody tr")
        assert [r["data-series"] for r in rows] == [s.id for s in series]
        details = section.select("details.series")
        assert [d["data-series"] for d in details] == [s.id for s in series]
    row = page.select_one("tr[data-series=ZBX8000]")
    assert row.select_one("td[data-field=outer_diameter]").text.startswith("12.7 mm")
    assert row.select_one("td[data-field=design_load] .kind")
    assert row.select_one("td.variants").text == "uncoated, tfe"
    assert "nut: polyacetal" in row.select_one("td.materials").text
    iso = page.select_one("section[data-family=TR-C45] tbody tr")
    assert iso.select_one("td[data-field=design_load]").text == "—"
    assert iso.select_one("td.variants").text == "bronze, acetal, ptfe"


def test_catalog_regions_have_unique_labels(
    catalog_page: BeautifulSoup, series_bodies: dict[str, BeautifulSoup]
) -> None:
    """Unique on the catalog page with every series opened (each body loaded into it)."""
    page = catalog_page
    regions = page.select("[role=region]")
    regions += [r for body in series_bodies.values() for r in body.select("[role=region]")]
    labels = [r.get("aria-label") or r.get("aria-labelledby") for r in regions]
    assert all(labels) and len(set(labels)) == len(labels)
    captions = [c.text for c in page.select("caption")]
    assert len(set(captions)) == len(captions)


def test_custom_page_leaves_out_the_catalog_filters(client: TestClient) -> None:
    """Lead, coating, family, nut material and the ranking only choose among catalog
    screws: the /custom form does not offer them, the selector does."""
    custom = soup(client.get("/custom").text)
    selector = soup(client.get("/").text)
    for field in FIELDS:
        named = f'[name="{field.page}"]'  # radio buttons share the name, not an id
        assert selector.select_one(named) is not None, field.page
        assert (custom.select_one(named) is not None) == (not field.catalog_only), field.page


def test_share_link_writes_each_typed_number_exactly(client: TestClient) -> None:
    """The numbers no unit switch sets (the flank half-angle in degrees, the friction, the
    own material's modulus in Pa and its density) went into the link to 6 figures: typed
    14.0362435 deg, 0.1234567, 70123456789 Pa and 2700.123 kg/m^3 came back as 14.0362,
    0.123457, 7.01235e+10 and 2700.12, another screw. Each is written as typed."""
    typed = {
        "thread_half_angle_deg": "14.0362435",
        "friction_dynamic": "0.1234567",
        "youngs_modulus_pa": "70123456789",
        "density_kg_m3": "2700.123",
    }
    query = (
        "outer_diameter_mm=20&root_diameter_mm=13&lead_mm=12&friction_static=0.2&material=custom&"
        + "&".join(f"{name}={text}" for name, text in typed.items())
        + f"&{AXIS}"
    )
    link = soup(client.get(f"/custom?{query}").text).select_one("a.share-link")["href"]
    shared = dict(parse_qsl(link.split("?", 1)[1]))
    assert {name: shared[name] for name in typed} == typed


def test_a_unit_switch_redraws_the_screw_fields_in_the_htmx_answer(client: TestClient) -> None:
    """The form answers a unit switch by HTMX: the answer redrew every converted field
    the selector has, its catalog-only lead among them, which this page has not (a 500);
    it redraws this page's application fields and the screw's, each number and unit in
    the new units, so that the next answer reads them in the units they show."""
    query = f"{QUERY}&drag_torque_nm=0.05"
    for switch, name, value, unit in (
        ("from_length_unit=mm&length_unit=in", "outer_diameter_mm", "0.3937007874015748", "in"),
        ("from_torque_unit=N_m&torque_unit=oz_in", "drag_torque_nm", "7.080596633061748", "oz in"),
    ):
        response = client.get(f"/custom?{query}&{switch}", headers=HX)
        assert response.status_code == 200, switch
        html = soup(response.text)
        redrawn = html.select_one(f'#w-{name}[hx-swap-oob="true"]')
        assert redrawn is not None, switch
        assert redrawn.select_one(f'input[name="{name}"]')["value"] == value  # type: ignore[index]
        assert redrawn.select_one("label .unit").get_text() == unit  # type: ignore[union-attr]
        assert html.select_one("#w-lead") is None


def test_the_pv_chart_marks_the_thrust_the_pv_check_judges(client: TestClient) -> None:
    """A 12 x 9.5 mm screw of 6 mm lead with a 0.2 MPa m/s PV limit lifting 60 N and
    8 kg at 60 mm/s, accelerating at 2 m/s^2: the PV check judges the peak thrust at the
    top speed, 60 + 8 x 9.80665 + 8 x 2 = 154.45 N (the API's peak_axial_load_n), and
    its PV is 2.059 times the limit; the PV-limited load at 60 mm/s is 75 N. The cross
    stood at the running load, 138.45 N (1.846 times the 75 N line); it now stands at
    154.45 N, 2.059 times the line: the check's utilization."""
    screw = {
        "outer_diameter_mm": 12, "root_diameter_mm": 9.5, "lead_mm": 6,
        "friction_dynamic": 0.15, "friction_static": 0.2, "pv_limit_mpa_m_s": 0.2,
    }  # fmt: skip
    axis = {
        "load": 60, "moving_mass_kg": 8, "orientation": "vertical", "speed": 60,
        "length": 500, "accel": 2000, "stroke": 300,
    }  # fmt: skip
    page = soup(client.get("/custom", params={**screw, **axis}).text)
    figure = json.loads(page.select_one("script#fig-pv").text)
    line, cross = figure["data"]
    body = {
        "application": {
            "load_n": 60, "moving_mass_kg": 8, "orientation": "vertical", "speed_mm_s": 60,
            "length_mm": 500, "accel_mm_s2": 2000, "stroke_mm": 300,
        },
        "screw": screw,
    }  # fmt: skip
    c = client.post("/api/v1/evaluate", params={"detail": "full"}, json=body).json()["candidate"]
    assert cross["x"] == [60.0]
    assert cross["y"] == [pytest.approx(c["peak_axial_load_n"], rel=1e-4)]
    assert c["peak_axial_load_n"] == pytest.approx(154.4532)
    at_cross = line["y"][line["x"].index(60.0)]
    assert at_cross == pytest.approx(c["pv"]["max_load_n"], rel=1e-4) == 75.0
    assert cross["y"][0] / at_cross == pytest.approx(c["utilization"]["pv"], rel=1e-4)
