"""The HTML side: full page vs HTMX fragment, units, inline errors, exports, catalog page.

HTML is checked through CSS selectors (BeautifulSoup + soupsieve), not snapshots.
"""

import csv
import io
import json
import math
import re
from pathlib import Path
from typing import Any
from urllib.parse import parse_qsl, quote

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient
from httpx import Response

from app.catalog import Catalog
from app.contract.fields import BY_API, BY_PAGE, FIELDS
from app.contract.inputs import ApplicationIn
from app.contract.outputs import SelectOut
from app.contract.units import DEFAULT_UNITS
from app.core.model import PASS_UTILIZATION
from app.web.advice import proposal
from app.web.export import results_csv, safe_cell
from tests.leadscrews import leadscrew_families

ROOT = Path(__file__).resolve().parents[2]
AXIS = {"load": "100", "lead": "10", "speed": "50", "length": "500"}
API_AXIS = {"load_n": 100, "lead_mm": 10, "speed_mm_s": 50, "length_mm": 500}
HX = {"HX-Request": "true"}
LBF = 4.4482216152605
INCH = 25.4
OZ_IN = 0.0070615518142260435  # N m: 4.4482216152605 N x 0.0254 m / 16 (NIST SP 811)
OZ_IN2 = 0.45359237 / 16 * 0.0254**2  # kg m²: an ounce (1/16 lb) at an inch (NIST SP 811)


def soup(response: Response) -> BeautifulSoup:
    assert response.status_code == 200, response.text[:500]
    return BeautifulSoup(response.text, "html.parser")


def candidate_ids(page: BeautifulSoup) -> list[str]:
    return [str(t["data-id"]) for t in page.select("table.candidates tbody.candidate")]


@pytest.fixture(scope="module")
def lead(catalog: Catalog) -> str:
    """The leadscrew families as the page takes them (comma-separated; the API's query
    repeats the parameter: ``lead.split(",")``), for the
    tests of a leadscrew's answer (ball screws rank beside them by default)."""
    return ",".join(leadscrew_families(catalog))


def api_select(client: TestClient, **params: Any) -> dict[str, Any]:
    body: dict[str, Any] = client.get(
        "/api/v1/select", params={**API_AXIS, **params, "detail": "full"}
    ).json()
    return body


# full page and fragment


def test_empty_selector_is_a_form_with_a_label_on_every_field(client: TestClient) -> None:
    page = soup(client.get("/"))
    form = page.select_one("form#selector[action='/'][method='get']")
    assert form is not None and form.select_one("button[type=submit]")
    assert form["hx-get"] == "/" and "delay:60ms" in str(form["hx-trigger"])
    for name in ("load", "lead", "speed", "length"):
        assert page.select_one(f"#f-{name}[name={name}]")
    for field in form.select("input:not([type=hidden]), select"):
        labelled = field.find_parent("label") or page.select_one(f"label[for='{field['id']}']")
        assert labelled, field
    for name in BY_PAGE:
        assert form.select(f"[name={name}]"), name
    assert page.select_one("#results .prompt")
    assert not page.select("table.candidates")


def test_end_fixity_offers_four_drawn_cases(client: TestClient) -> None:
    page = soup(client.get("/"))
    radios = page.select("fieldset.fixity input[type=radio][name=end_fixity]")
    assert [r["value"] for r in radios] == [
        "fixed-free",
        "simple-simple",
        "fixed-simple",
        "fixed-fixed",
    ]
    assert len(page.select("fieldset.fixity label svg.fixity-drawing")) == 4
    assert page.select_one("input[name=end_fixity][checked]")["value"] == "fixed-simple"


def test_full_page_renders_results_table_charts_and_counts(client: TestClient) -> None:
    api = api_select(client)
    page = soup(client.get("/", params=AXIS))
    assert page.select_one("html form#selector")
    assert candidate_ids(page) == [c["id"] for c in api["candidates"]]
    counts = api["counts"]
    assert page.select_one(".count-evaluated").text == str(counts["evaluated"])
    assert page.select_one(".count-passed").text == str(counts["passed"])
    assert page.select_one(".count-rejected").text == str(counts["rejected"])
    # the charts load after the table, from /charts with the same query (app.js, or the link)
    assert not page.select("script[type='application/json'][data-chart]")
    slot = page.select_one("section#charts-slot[data-src]")
    charts_url = "/charts?load=100&lead=10&speed=50&length=500"
    assert slot["data-src"] == slot.select_one("a[href]")["href"] == charts_url
    part = soup(client.get(charts_url, headers=HX))
    assert not part.select("html, h1") and part.select_one("section.charts")
    charts = part.select("script[type='application/json'][data-chart]")
    assert [c["id"] for c in charts] == [
        "fig-critical_speed",
        "fig-pv",
        "fig-torque",
        "fig-lead_sweep",
        "fig-life",
    ]
    for script in charts:
        assert part.select_one(f"#{script['data-chart']}.chart")
        assert json.loads(script.string)["data"]
    # without JavaScript the link opens them as a page, its way back to the results
    alone = soup(client.get(charts_url))
    assert len(alone.select("main script[data-chart]")) == len(charts)
    assert alone.select_one("a.back-link")["href"] == "/?load=100&lead=10&speed=50&length=500"


def test_htmx_request_gets_fragment_with_push_url_and_oob_errors(client: TestClient) -> None:
    response = client.get("/", params=AXIS, headers=HX)
    page = soup(response)
    assert not page.select("html, form#selector, h1")
    assert page.select("table.candidates tbody tr")
    assert response.headers["HX-Push-Url"] == "/?load=100&lead=10&speed=50&length=500"
    assert "HX-Request" in response.headers["Vary"]
    # the field errors come as one out-of-band element listing the fields in error: none here
    assert not page.select("span.error[hx-swap-oob]")
    assert page.select_one("#field-errors[hx-swap-oob][hidden]").select("[data-error-for]") == []
    assert page.select_one("#status[hx-swap-oob]").text.strip().endswith("candidates pass.")


def test_the_status_counts_one_passing_candidate_in_the_singular(client: TestClient) -> None:
    """20 kN at 1.5 m/s over 0.5 m: one ball screw passes."""
    response = client.get("/", params={"load": 20000, "speed": 1500, "length": 500}, headers=HX)
    status = soup(response).select_one("#status[hx-swap-oob]").text.strip()
    assert re.fullmatch(r"1 of \d+ candidates passes\.", status), status


def test_history_restore_request_gets_the_full_page(client: TestClient) -> None:
    headers = {**HX, "HX-History-Restore-Request": "true"}
    page = soup(client.get("/", params=AXIS, headers=headers))
    assert page.select_one("html form#selector")


def test_share_url_reopens_the_same_results(client: TestClient) -> None:
    params = {**AXIS, "accel": "2000", "end_fixity": "fixed-fixed", "limit": "5"}
    pushed = client.get("/", params=params, headers=HX).headers["HX-Push-Url"]
    assert pushed.startswith("/?") and "end_fixity=fixed-fixed" in pushed
    first = soup(client.get("/", params=params))
    again = soup(client.get(pushed))
    assert candidate_ids(again) == candidate_ids(first)
    assert len(candidate_ids(again)) == 5
    assert again.select_one("a.share-link")["href"] == pushed
    assert again.select_one("button.copy-link")["data-url"] == pushed


@pytest.mark.parametrize(
    "path",
    [
        "/",
        "/?load=100&lead=10&speed=50&length=500",
        "/?load=abc&speed=1&length=1",
        "/catalog",
        "/catalog/ZBX8000",
        "/detail?load=100&lead=10&speed=50&length=500&id=B6000-L10-TFE",
        "/custom?outer_diameter_mm=10&root_diameter_mm=8&lead_mm=2&friction_dynamic=0.15"
        "&friction_static=0.2&load=100&speed=50&length=500",
    ],
    ids=["empty", "results", "error", "catalog", "catalog-series", "detail", "custom"],
)
def test_no_inline_script_style_or_handler(
    client: TestClient, path: str, request: pytest.FixtureRequest
) -> None:
    """The CSP (script-src 'self'; style-src 'self') would block any of these."""
    page = request.getfixturevalue("catalog_page") if path == "/catalog" else soup(client.get(path))
    for script in page.select("script"):
        assert script.get("src") or script.get("type") == "application/json", script
    assert not page.select("style, [style]")
    handlers = [a for tag in page.find_all(True) for a in tag.attrs if a.startswith("on")]
    assert handlers == []


# units


@pytest.mark.parametrize(
    ("params", "unit_text"),
    [
        ({"load": "22.4809", "force_unit": "lbf"}, "lbf"),
        ({"load": "10.19716", "force_unit": "kgf"}, "kgf"),
        (
            {"lead": "0.393701", "speed": "1.968504", "length": "19.68504", "length_unit": "in"},
            "in",
        ),
    ],
    ids=["lbf", "kgf", "inch"],
)
def test_same_axis_in_other_units_gives_same_candidates(
    client: TestClient, params: dict[str, str], unit_text: str
) -> None:
    metric = soup(client.get("/", params=AXIS))
    other = soup(client.get("/", params={**AXIS, **params}))
    assert candidate_ids(other) == candidate_ids(metric)
    assert unit_text in other.select_one("dl.inputs").text


def test_table_values_follow_the_display_units(client: TestClient, lead: str) -> None:
    # the length check's value: a leadscrew's (a ball screw's maker gives no maximum length)
    api = api_select(client, family=lead.split(","))["candidates"][0]
    params = {
        **AXIS,
        "family": lead,
        "lead": "0.393701",
        "speed": "1.968504",
        "length": "19.68504",
        "length_unit": "in",
        "torque_unit": "oz_in",
    }
    page = soup(client.get("/", params=params))
    head = page.select_one("table.candidates thead").text
    assert "oz in" in head and "in" in head and "mm" not in head
    row = page.select_one("tbody.candidate")
    torque = float(row.select_one(".torque-peak").text)
    assert math.isclose(torque, api["torque"]["peak_motor_nm"] / OZ_IN, rel_tol=1e-3)
    assert math.isclose(float(row.select_one(".lead").text), 10 / INCH, rel_tol=1e-3)
    detail = soup(client.get("/detail", params={**params, "id": api["id"]}, headers=HX))
    detail_values = [dd.text for dd in detail.select("li.check[data-check=length] .check-value")]
    assert detail_values == ["19.69 in"]


def test_switching_units_converts_the_typed_values(client: TestClient) -> None:
    params = {**AXIS, "force_unit": "lbf", "from_force_unit": "N", "from_length_unit": "mm"}
    page = soup(client.get("/", params=params))
    assert page.select_one("#f-load")["value"] == "22.48"
    assert page.select_one("input[name=typed_load]")["value"] == "100|N"
    assert page.select_one("#f-length")["value"] == "500"
    assert page.select_one("input[name=from_force_unit]")["value"] == "lbf"
    assert candidate_ids(page) == candidate_ids(soup(client.get("/", params=AXIS)))


def test_switching_units_swaps_converted_fields_out_of_band(client: TestClient) -> None:
    params = {**AXIS, "length_unit": "in", "from_length_unit": "mm"}
    response = client.get("/", params=params, headers=HX)
    page = soup(response)
    assert page.select_one("#w-length[hx-swap-oob] #f-length")["value"] == "19.69"
    assert page.select_one("#w-speed[hx-swap-oob] label .unit").text == "in/s"
    entered = page.select_one("#entered-units[hx-swap-oob] input[name=from_length_unit]")
    assert entered["value"] == "in"
    assert not page.select("#w-load")  # force fields did not change units
    assert "length_unit=in" in response.headers["HX-Push-Url"]


# inline errors


def test_bad_number_is_shown_inline_and_kept(client: TestClient) -> None:
    page = soup(client.get("/", params={**AXIS, "load": "12x"}))
    field = page.select_one("#f-load")
    assert field["value"] == "12x"
    assert field["aria-invalid"] == "true"
    assert "e-load" in field["aria-describedby"].split()
    assert page.select_one("#e-load").text == "Enter a number."
    assert not page.select("table.candidates")
    assert page.select_one("#results .notice.invalid")


@pytest.mark.parametrize(
    ("text", "message"),
    [("nan", "Enter a number."), ("inf", "Enter a number."), ("-1e400", "Enter a finite number.")],
)
def test_non_finite_numbers_are_refused(client: TestClient, text: str, message: str) -> None:
    """'nan' and 'inf' are not number text (as in the API's query); 1e400 overflows."""
    page = soup(client.get("/", params={**AXIS, "length": text}))
    assert page.select_one("#e-length").text == message
    assert page.select_one("#f-length")["value"] == text


def test_bad_number_in_htmx_request_updates_error_span_only(client: TestClient) -> None:
    response = client.get("/", params={**AXIS, "load": "12x"}, headers=HX)
    page = soup(response)
    assert response.headers["HX-Push-Url"] == "false"
    listed = page.select("#field-errors[hx-swap-oob] [data-error-for]")
    assert {item["data-error-for"]: item.text for item in listed} == {"load": "Enter a number."}
    assert not page.select("input#f-load")  # the field being typed in is not replaced


def test_bounds_are_stated_in_display_units(client: TestClient) -> None:
    page = soup(client.get("/", params={**AXIS, "load": "300000", "force_unit": "lbf"}))
    assert page.select_one("#e-load").text == "Must be at most 224808 lbf."
    page = soup(client.get("/", params={**AXIS, "critical_speed_safety_factor": "2"}))
    assert page.select_one("#e-critical_speed_safety_factor").text == "Must be at most 1."
    assert page.select_one("details.advanced[open]")


def test_missing_required_fields_are_named(client: TestClient) -> None:
    page = soup(client.get("/", params={"load": "100"}))
    assert page.select_one("#e-speed").text == "Required."
    assert page.select_one("#e-length").text == "Required."
    assert page.select_one("#f-load")["value"] == "100"


def test_cross_field_error_names_the_fields_in_page_words(client: TestClient) -> None:
    """Shown under the field the model names, or above the results when it names none."""
    page = soup(client.get("/", params={**AXIS, "required_life_years": "3"}))
    messages = [e.text for e in page.select("#e-form, #e-required_life_years") if e.text]
    assert len(messages) == 1
    assert messages[0].lower().endswith("needs stroke.")
    assert "_" not in messages[0]
    # with a stroke, a duty in either form: cycles or hours a day
    page = soup(client.get("/", params={**AXIS, "stroke": "100", "required_life_years": "3"}))
    messages = [e.text for e in page.select("#e-form, #e-required_life_years") if e.text]
    assert messages == ["Needs cycles per day or hours per day."]


# advanced options


def test_advanced_opens_only_for_non_default_values(client: TestClient) -> None:
    defaults = {**AXIS, "orientation": "horizontal", "compression": "true", "accel": ""}
    assert not soup(client.get("/", params=defaults)).select("details.advanced[open]")
    page = soup(client.get("/", params={**AXIS, "compression": "false", "vacuum": "true"}))
    assert page.select_one("details.advanced[open]")
    # only the groups holding a set value are drawn open
    opened = {d.summary.contents[0].strip() for d in page.select("details.group[open]")}
    shut = {d.summary.contents[0].strip() for d in page.select("details.group:not([open])")}
    assert {
        page.select_one(f"details.group:has({f})").summary.contents[0].strip()
        for f in ("#f-compression", "#f-vacuum")
    } == opened
    assert "Motor and move" in shut and "Safety factors" in shut
    assert page.select_one("#f-compression option[selected]")["value"] == "false"
    assert page.select_one("#f-vacuum[checked]")
    assert "tension" in page.select_one("dl.inputs").text.lower()


def test_the_moving_mass_orientation_and_load_direction_are_up_front(
    client: TestClient,
) -> None:
    """Asked beside the load, outside Advanced: a vertical 5 kg axis keeps Advanced shut,
    and every motor input sits in the one motor group."""
    query = {**AXIS, "moving_mass_kg": "5", "orientation": "vertical", "load_direction": "fixed"}
    page = soup(client.get("/", params=query))
    up_front = [w["id"] for w in page.select("fieldset.axis div.field[id^=w-]")]
    assert up_front[:4] == ["w-load", "w-load_direction", "w-moving_mass_kg", "w-orientation"]
    assert not page.select("details.advanced #f-moving_mass_kg, details.advanced #f-orientation")
    assert not page.select("details.advanced[open]")
    assert page.select_one("#f-orientation option[selected]")["value"] == "vertical"
    motor = next(
        fs for fs in page.select("details.group fieldset") if fs.legend.text == "Motor and move"
    )
    assert motor.select_one("#f-max_torque") and motor.select_one("#f-motor_curve")


# detail, rejected, no pass


def detail_url(query: str, cid: str) -> str:
    return f"/detail?{query}&id={cid}"


def test_results_link_each_detail_instead_of_embedding_it(client: TestClient) -> None:
    """The checks load when a detail is opened (app.js asks its link's URL as a fragment),
    or open as a page without JS; the rejected list loads the same way, from /rejected."""
    api = api_select(client)
    page = soup(client.get("/", params=AXIS, headers=HX))
    query = "load=100&lead=10&speed=50&length=500"
    assert not page.select("li.check, ol.checks, dl.facts")
    bodies = page.select("table.candidates tbody.candidate")
    for n, (body, c) in enumerate(zip(bodies, api["candidates"], strict=True), start=1):
        details = body.select_one("tr.detail-row details.detail")
        assert details["id"] == f"detail-{n}"
        assert details.select_one("summary").text == f"Detail of {c['id']}"
        assert details.select_one(".detail-body.pending a[href]")["href"] == detail_url(
            query, c["id"]
        )
    assert not page.select("li.rejected-candidate")
    link = page.select_one("details.rejected > .rejected-body.pending > a[href]")
    assert link["href"] == f"/rejected?{query}"
    part = soup(client.get(link["href"], headers=HX))
    assert not part.select("html, h1")
    rejected = part.select("div.rejected-body:not(.pending) li.rejected-candidate")
    assert len(rejected) == len(api["rejected"])
    for item in rejected:
        details = item.select_one("details.detail")
        assert details.select_one(".detail-body a")["href"] == detail_url(query, item["data-id"])
    alone = soup(client.get(link["href"]))
    assert len(alone.select("main li.rejected-candidate")) == len(rejected)


def test_detail_fragment_and_page(client: TestClient) -> None:
    chosen = api_select(client)["candidates"][1]
    cid = chosen["id"]
    params = {**AXIS, "force_unit": "lbf", "load": "22.4809", "id": cid}
    response = client.get("/detail", params=params, headers=HX)
    fragment = soup(response)
    assert "HX-Request" in response.headers["Vary"]
    assert not fragment.select("html, h1, form")
    assert fragment.select_one("div.detail-body:not(.pending) dl.facts")
    assert fragment.select("div.detail-body ol.checks li.check")
    assert "lbf" in fragment.select_one("li.check[data-check=buckling] .check-limit").text
    full = soup(client.get("/detail", params=params))
    assert full.select_one("html head title").text.startswith(cid)
    assert full.select_one("main h1").text == f"Detail of {cid}"
    # the verdict's one-line summary: "every check" only when no check was skipped
    assert full.select_one("main .verdict").text == chosen["verdict"]["summary"]
    assert ("every check" in chosen["verdict"]["summary"]) == (not chosen["verdict"]["skipped"])
    back = full.select_one("main a.back-link")["href"]
    assert back == "/?load=22.4809&lead=10&speed=50&length=500&force_unit=lbf"
    # the same detail; each check's heading sits one level under its section (h2 under
    # the page's h1, h4 under a result's h3)
    assert full.select("main div.detail-body h2.check-name")
    page_body = str(full.select_one("main div.detail-body"))
    assert re.sub(r"(</?)h2\b", r"\1h4", page_body) == str(fragment.select_one("div.detail-body"))
    assert not full.select("form#selector")


def test_detail_breaks_the_inertia_torque_into_screw_mass_and_rotor(client: TestClient) -> None:
    """ZBX8000-L10 at 2 m/s^2 with a rotor of 82e-7 kg m^2, typed in oz in² as torques
    are in oz in (82e-7 / OZ_IN2 = 0.448333 oz in²): J_motor alpha = 82e-7 x 2 pi x 2 /
    0.01 = 0.0103 N m = 1.459 oz in, beside the screw's and the mass's."""
    move = {"accel": "2000", "moving_mass_kg": "5", "motor_inertia": f"{82e-7 / OZ_IN2:.9g}"}
    params = {**AXIS, **move, "torque_unit": "oz_in", "id": "ZBX8000-L10"}
    detail = soup(client.get("/detail", params=params, headers=HX))
    rotor_nm = 82e-7 * 2 * math.pi * 2.0 / 0.010
    assert float(detail.select_one(".inertia-motor").text) == pytest.approx(
        rotor_nm / OZ_IN, rel=1e-3
    )
    api = client.get(
        "/api/v1/select",
        params={
            **API_AXIS,
            "accel_mm_s2": 2000,
            "moving_mass_kg": 5,
            "motor_inertia_kg_m2": 82e-7,
            "detail": "full",
        },
    ).json()
    screened = api["candidates"] + api["rejected"]
    torque = next(c for c in screened if c["id"] == "ZBX8000-L10")["torque"]
    assert torque["inertia_motor_nm"] == pytest.approx(rotor_nm, rel=1e-9)
    for name, part in (("screw", "inertia_screw_nm"), ("mass", "inertia_mass_nm")):
        shown = float(detail.select_one(f".inertia-{name}").text)
        assert shown == pytest.approx(torque[part] / OZ_IN, rel=1e-3)
    assert api["formulas"]["torque.inertia_motor_nm"]["formula"].startswith("T = J_motor alpha")


def test_detail_at_no_axial_load_says_pv_sets_no_speed_limit(client: TestClient) -> None:
    """No thrust on the nut: PV is 0 whatever the speed, so the line gives the load the
    nut allows at this speed and says there is no speed limit (never "nan mm/s")."""
    api = api_select(client, load_n=0)
    c = api["candidates"][0]
    assert c["pv"]["max_speed_mm_s"] is None and c["pv"]["max_load_n"] > 0
    detail = soup(client.get("/detail", params={**AXIS, "load": "0", "id": c["id"]}, headers=HX))
    pv = next(div.dd.text for div in detail.select("dl.facts > div") if div.dt.text == "PV")
    assert "no PV speed limit at this load (no thrust on the nut)" in pv
    assert f"at most {c['pv']['max_load_n']:.4g} N at this speed" in pv
    assert "nan" not in detail.text.lower()


def test_detail_says_where_the_pv_is_judged(client: TestClient) -> None:
    """100 N at 50 mm/s with no move: the PV is judged at the axis's own thrust and speed,
    and the line says so, so that "at this speed" and "at this load" after it name them."""
    c = next(c for c in api_select(client)["candidates"] if c["pv"] is not None)
    assert (c["pv"]["judged_thrust_n"], c["pv"]["judged_speed_mm_s"]) == (100.0, 50.0)
    detail = soup(client.get("/detail", params={**AXIS, "id": c["id"]}, headers=HX))
    pv = next(div.dd for div in detail.select("dl.facts > div") if div.dt.text == "PV")
    assert pv.select_one(".pv-judged").text == "100 N and 50 mm/s"


def test_detail_of_a_rejected_candidate_names_its_failures_and_fix(client: TestClient) -> None:
    c = api_select(client)["rejected"][0]
    page = soup(client.get("/detail", params={**AXIS, "id": c["id"]}))
    failing = [k["name"] for k in c["checks"] if not k["passed"]]
    assert [li["data-check"] for li in page.select("li.check.fail")] == failing
    assert page.select_one("main .verdict").text.startswith("Rejected: fails")
    assert page.select_one("main > p.fix").text == f"Fix: {c['fix']}"


@pytest.mark.parametrize(
    ("params", "status", "text"),
    [
        ({**AXIS, "id": "NO-SUCH-SCREW"}, 404, "no candidate &#39;NO-SUCH-SCREW&#39;"),
        (AXIS, 404, "no candidate id given"),
        ({**AXIS, "load": "-1", "id": "B6000-L10-TFE"}, 422, "Axial load"),
    ],
    ids=["unknown-id", "no-id", "invalid-input"],
)
def test_detail_errors_are_html_pages(
    client: TestClient, params: dict[str, str], status: int, text: str
) -> None:
    for headers in ({}, HX):
        response = client.get("/detail", params=params, headers=headers)
        assert response.status_code == status
        assert response.headers["content-type"].startswith("text/html")
        assert text in response.text


def test_detail_lists_every_check_with_formula_and_provenance(client: TestClient) -> None:
    api = api_select(client)["candidates"][0]
    page = soup(client.get("/detail", params={**AXIS, "id": api["id"]}, headers=HX))
    checks = page.select("div.detail-body li.check")
    assert [c["data-check"] for c in checks] == [k["name"] for k in api["checks"]]
    for item, check in zip(checks, api["checks"], strict=True):
        assert item.select_one(".formula code").text == check["formula"]
        assert item.select_one(".message").text == check["message"]
        kinds = [k.text for k in item.select("ul.sources .kind")]
        assert kinds == [api["provenance"][s]["kind"] for s in check["sources"]]
        sources = [s.text for s in item.select("ul.sources .source")]
        assert sources == [api["provenance"][s]["source"] for s in check["sources"]]


def test_rejected_are_grouped_by_failing_check_with_fixes(client: TestClient) -> None:
    api = api_select(client)
    page = soup(client.get("/", params=AXIS))
    link = page.select_one("details.rejected:not([open]) .rejected-body a[href]")
    section = soup(client.get(link["href"], headers=HX))
    groups = section.select("section.reject-group")
    assert {g["data-check"] for g in groups} == {c["governing_check"] for c in api["rejected"]}
    shown = [li["data-id"] for li in section.select("li.rejected-candidate")]
    assert sorted(shown) == sorted(c["id"] for c in api["rejected"])
    for item in section.select("li.rejected-candidate"):
        assert item.select_one(".fix").text.startswith("Fix:")


def test_no_passing_candidate_lists_verified_remedies_with_apply_links(
    client: TestClient, lead: str
) -> None:
    # no leadscrew passes 10 kN at 500 mm/s over 3 m (a 50 x 40 ball screw does)
    params = {"load": "10000", "speed": "500", "length": "3000", "family": lead}
    api = client.get(
        "/api/v1/select",
        params={"load_n": 10000, "speed_mm_s": 500, "length_mm": 3000, "detail": "full",
                "family": lead.split(",")},
    ).json()  # fmt: skip
    page = soup(client.get("/", params=params))
    assert api["counts"]["passed"] == 0
    notice = page.select_one(".notice.no-pass[role=region]")
    most = api["summary"]["most_excluding_check"]
    label = next(k["label"] for k in api["rejected"][0]["checks"] if k["name"] == most)
    assert notice.select_one(".verdict strong").text == label
    assert most not in notice.text  # internal names never reach the reader
    remedies = notice.select("ul.remedies li")
    assert len(remedies) == len(api["summary"]["remedies"]) >= 1
    for li, remedy in zip(remedies, api["summary"]["remedies"], strict=True):
        fields = [BY_API[k] for k in remedy["inputs"]]
        assert li["data-fields"].split() == [f.page for f in fields]
        # 1 / 1.05 within the rounding a check passes by (a change exactly 5 % past)
        assert remedy["utilization"] <= PASS_UTILIZATION / 1.05 and remedy["passing"] >= 1
        query = dict(parse_qsl(li.select_one("a.apply")["href"].split("?", 1)[1]))
        for field in fields:
            value, current = remedy["inputs"][field.api], float(params[field.page])
            shown = float(query[field.page])
            # rounded towards the side that clears, to 3 figures
            assert shown <= value if value < current else shown >= value
            assert shown == pytest.approx(value, rel=0.01)
        unchanged = {k: v for k, v in params.items() if k not in li["data-fields"].split()}
        assert {k: v for k, v in query.items() if k not in li["data-fields"].split()} == unchanged
    best = api["rejected"][0]
    failed = [k for k in best["checks"] if not k["passed"]]
    items = notice.select("ul.failed-fixes li")
    assert [li.strong.text for li in items] == [k["label"] + "." for k in failed]
    assert items[0].text.endswith(failed[0]["fix"])
    assert not page.select("table.candidates")
    assert "nearest rejected" in page.select_one("#charts-heading").text


def test_apply_all_makes_every_change_and_the_nearest_screw_passes(
    client: TestClient, lead: str
) -> None:
    params = {"load": "3000", "speed": "500", "length": "3000", "family": lead}
    page = soup(client.get("/", params=params))
    link = page.select_one("a.apply-all") or page.select_one("a.apply")
    assert link is not None
    href = link["href"]
    nearest = page.select_one(".no-pass .verdict .cid").text
    after = soup(client.get(href))
    assert not after.select(".no-pass")
    assert nearest in candidate_ids(after)


#: No load clears self-locking here (the 800 kg weight alone is too much): the core's
#: target would be a negative load.
HEAVY_VERTICAL = {"load": "0", "speed": "50", "length": "500", "moving_mass_kg": "800",
                  "orientation": "vertical"}  # fmt: skip


def test_an_infeasible_change_is_not_offered_but_said(client: TestClient, lead: str) -> None:
    """The nearest screw would need a load below zero: the page answers, offers no change
    and says that no accepted load admits it; the API proposes nothing out of bounds."""
    page = client.get("/", params={**HEAVY_VERTICAL, "family": lead})
    assert page.status_code == 200
    notice = soup(page).select_one(".notice.no-pass")
    assert notice is not None and not notice.select("ul.input-changes li")
    api = client.get("/api/v1/select", params={"load_n": 0, "speed_mm_s": 50, "length_mm": 500,
                     "moving_mass_kg": 800, "orientation": "vertical",
                     "family": lead.split(",")}).json()  # fmt: skip
    assert api["summary"]["input_change"] == {}
    # Tr40x7 bronze, nearest, is held to MISUMI's thrust and its sliding speed: neither a
    # load nor a speed within the accepted inputs admits it; each named by its form label.
    load, speed = (
        next(f.label.lower() for f in FIELDS if f.core == k) for k in ("load_n", "speed_m_s")
    )
    assert re.search(
        rf"No {load}( and {speed})? within the accepted inputs admits it\.",
        api["summary"]["message"],
    )
    assert not re.search(r" -\d", api["summary"]["message"])


@pytest.mark.parametrize(
    "params",
    [
        {"length": "3000", "speed": "500", "load": "10000"},
        {"length": "3000", "speed": "500", "load": "10000", "length_unit": "in"},
    ],
    ids=["metric", "inch"],
)
def test_every_apply_link_is_accepted(
    client: TestClient, lead: str, params: dict[str, str]
) -> None:
    """Each proposed change lies within its field's bounds: every Apply link renders a page
    without an input error, and carries the proposal as shown (3 figures), in any unit
    (the leadscrews: a ball screw passes this axis)."""
    params = {**params, "family": lead}
    page = soup(client.get("/", params=params))
    assert page.select("a.apply")
    for link in page.select("a.apply, a.apply-all"):
        changed = set(parse_qsl(link["href"].split("?", 1)[1])) - set(params.items())
        numbers = [v for k, v in changed if k != "end_fixity"]
        assert changed and all(float(v) == float(f"{float(v):.3g}") for v in numbers)
        after = client.get(link["href"])
        assert after.status_code == 200, link["href"]
        assert not soup(after).select(".error:not(:empty)"), link["href"]


def test_no_proposed_change_shortens_the_screw_below_its_stroke(client: TestClient) -> None:
    """22.48 lbf at 50 in/s on a 500 in screw with a 200 in stroke, the seed's families and
    the ISO ones: nothing passes, and the screws an input change can admit have seed nuts,
    whose length the catalog does not give (no stroke-travel check judges them). A
    shorter screw and a lower load admit them, but a 52.7 in screw is shorter than the
    200 in stroke, which the form refuses: no such change is offered, and the page
    answers (it answered 500 when its Apply link could not be built)."""
    params = {"load": "22.48", "speed": "50", "length": "500", "stroke": "200",
              "cycles_per_day": "1000", "force_unit": "lbf", "length_unit": "in",
              "family": "B,KHD,TR-304,TR-C45,VHD,ZBX"}  # fmt: skip
    response = client.get("/", params=params)
    assert response.status_code == 200
    api = client.get("/api/v1/select", params={
        "load_n": 100, "speed_mm_s": 1270, "length_mm": 12700, "stroke_mm": 5080,
        "cycles_per_day": 1000, "family": params["family"].split(",")}).json()  # fmt: skip
    assert api["counts"]["passed"] == 0
    offered = [r["inputs"] for r in api["summary"]["remedies"]]
    offered += [c["inputs"] for c in api["summary"]["changes"]]
    for inputs in offered:
        assert inputs.get("length_mm", 12700) >= inputs.get("stroke_mm", 5080), inputs
    for link in soup(response).select("a.apply, a.apply-all"):
        assert client.get(link["href"]).status_code == 200, link["href"]


def test_a_proposal_rounded_past_its_bound_is_held_at_the_bound() -> None:
    """A target just above the slowest accepted speed (0.001 mm/s), shown in in/s and
    rounded down to 3 figures, would fall below it: the proposal stops at the bound, which
    still clears (the target lies above it)."""
    inputs = ApplicationIn(load_n=100, speed_mm_s=100, length_mm=500)
    target = 1.0001e-3
    value = proposal(inputs, "speed_mm_s", target, {**DEFAULT_UNITS, "length_unit": "in"})
    assert value == BY_API["speed_mm_s"].bounds[0]
    assert value <= target


@pytest.mark.parametrize("record", ["50|evil", "50|", "|N", "50|lbf|x", "x|N"])
def test_a_bad_typed_record_is_ignored(client: TestClient, record: str) -> None:
    """The typed record is page state: one naming no unit (or no number) of the field's
    quantity is ignored, and the shown number is converted instead of failing the page."""
    params = {**AXIS, "load": "100", "typed_load": record, "from_force_unit": "N",
              "force_unit": "lbf"}  # fmt: skip
    response = client.get("/", params=params)
    assert response.status_code == 200
    assert soup(response).select_one("#f-load")["value"] == "22.48"


@pytest.mark.parametrize(
    "typed",
    [
        {"length": "3937.0078", "length_unit": "in"},  # 6 figures (3937.01 in) exceed 100 m
        {"load": "100.4824", "force_unit": "lbf"},
        {"load": "100.4824", "speed": "50.00004"},
    ],
    ids=["length-at-bound", "load-lbf", "many-figures"],
)
def test_every_link_of_a_result_reproduces_it(client: TestClient, typed: dict[str, str]) -> None:
    """The share, detail and export links carry the typed numbers exactly: each answers,
    and the share link shows the same candidates as the page it came from."""
    page = soup(client.get("/", params={**AXIS, **typed}))
    share = page.select_one("a.share-link")["href"]
    again = soup(client.get(share))
    assert candidate_ids(again) == candidate_ids(page)
    verdict = ".counts, .no-pass .verdict"
    assert again.select_one(verdict).text == page.select_one(verdict).text
    links = [a["href"] for a in page.select("a.export, a.detail-link")]
    assert len(links) >= 2
    for href in links:
        assert client.get(href).status_code == 200, href


# exports


def test_csv_numbers_carry_ten_significant_figures_at_most(client: TestClient) -> None:
    text = client.get("/export.csv", params={**AXIS, "length_unit": "in", "force_unit": "lbf"}).text
    numbers = re.findall(r"(?<![\w.])-?\d+\.\d+(?:e-?\d+)?", text)
    assert numbers
    for number in numbers:
        digits = number.lstrip("-").split("e")[0].replace(".", "").lstrip("0")
        assert len(digits) <= 10, number
    rows = csv_candidates(text)  # 50 in/s on a 10 in lead: no screw is made so, no candidate
    assert [r["status"] for r in rows] == ["none"] and rows[0]["id"] == ""
    assert rows[0]["input:accel [in/s²]"] == "39.37007874"  # not 39.37007874015748


def csv_candidates(text: str) -> list[dict[str, str]]:
    """The rows of a CSV export, its one table, by heading."""
    assert "\r\n\r\n" not in text  # one table: no blank row splits it
    return list(csv.DictReader(io.StringIO(text)))


def test_csv_export_has_a_row_per_candidate_in_display_units(client: TestClient) -> None:
    api = api_select(client)
    response = client.get("/export.csv", params={**AXIS, "torque_unit": "lb_in"})
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("text/csv")
    assert "attachment" in response.headers["content-disposition"]
    rows = csv_candidates(response.text)
    passed = [r for r in rows if r["status"] == "passed"]
    assert [r["id"] for r in passed] == [c["id"] for c in api["candidates"]]
    assert [r["rank"] for r in passed] == [str(i + 1) for i in range(len(passed))]
    assert len(rows) == len(api["candidates"]) + len(api["rejected"])
    total = float(passed[0]["torque.total [lb in]"])
    expected = api["candidates"][0]["torque"]["total_nm"] / 0.112984829027617
    assert math.isclose(total, expected, rel_tol=1e-9)  # written to 10 significant figures
    peak = float(passed[0]["torque.peak_motor [lb in]"])
    expected_peak = api["candidates"][0]["torque"]["peak_motor_nm"] / 0.112984829027617
    assert math.isclose(peak, expected_peak, rel_tol=1e-9)
    assert {r["motor_use"] for r in rows} == {""}  # no motor given


def test_csv_cells_cannot_start_a_formula(client: TestClient) -> None:
    result = api_select(client)
    hostile = {**result["candidates"][0], "id": "=HYPERLINK(1)", "series": "@SUM(A1)"}
    hostile["fix"] = "-2+3"
    typed = SelectOut.model_validate({**result, "candidates": [hostile], "rejected": []})
    text = results_csv(typed, _METRIC)
    row = csv_candidates(text)[0]
    assert (row["id"], row["series"], row["fix"]) == ("'=HYPERLINK(1)", "'@SUM(A1)", "'-2+3")
    assert safe_cell("+1") == "'+1" and safe_cell(-1.0) == -1.0


_METRIC = {"force_unit": "N", "length_unit": "mm", "torque_unit": "N_m"}


def test_json_export_is_the_api_selection(client: TestClient) -> None:
    response = client.get("/export.json", params={**AXIS, "force_unit": "lbf", "load": "22.4809"})
    assert response.status_code == 200
    assert "attachment" in response.headers["content-disposition"]
    body = response.json()
    api = api_select(client)
    assert math.isclose(body["inputs"]["load_n"], 100.0, rel_tol=1e-5)
    assert [c["id"] for c in body["candidates"]] == [c["id"] for c in api["candidates"]]
    assert body["counts"] == api["counts"]


def test_export_with_bad_input_is_a_422_page(client: TestClient) -> None:
    response = client.get("/export.csv", params={**AXIS, "load": "-1"})
    assert response.status_code == 422
    assert "Axial load" in response.text
    assert re.search(r"Must be (more than|at least) [\d.]+ N\.", response.text)


def test_export_links_carry_the_share_query(client: TestClient) -> None:
    page = soup(client.get("/", params={**AXIS, "force_unit": "lbf", "load": "22.4809"}))
    links = [a["href"] for a in page.select(".share a.export")]
    query = page.select_one("a.share-link")["href"].removeprefix("/?")
    assert links == [f"/export.csv?{query}", f"/export.json?{query}"]


# catalog page


def test_catalog_page_lists_every_series_with_provenance(
    catalog_page: BeautifulSoup, series_bodies: dict[str, BeautifulSoup], catalog: Catalog
) -> None:
    """Each series is a <details> on the page whose body (loaded when opened, or its link's
    page) holds every field of the series with its provenance kind and source."""
    page = catalog_page
    sections = page.select("details.series")
    assert [s["data-series"] for s in sections] == list(catalog.series)
    assert not page.select("table.series-fields")  # loaded when opened, not before
    for section in sections:
        series = catalog.series[section["data-series"]]
        link = section.select_one(".series-body.pending a.series-link")
        assert link["href"] == "/catalog/" + quote(series.id)
        rows = series_bodies[series.id].select("table.series-fields tbody tr")
        assert [r["data-field"] for r in rows] == list(series.fields)
        for row in rows:
            field = series.fields[row["data-field"]]
            assert row.select_one(".kind").text == field.provenance.kind
            assert row.select_one(".source").text == field.provenance.source
    root = series_bodies["ZBX8000"].select_one("tr[data-field=root_diameter]")
    value = catalog.series["ZBX8000"].fields["root_diameter"].value
    assert float(root.select("td")[0].text) == pytest.approx(value * 1e3, rel=1e-3)
    assert root.select("td")[1].text == "mm"


# static assets


def test_plotly_css_matches_the_bundles_style_rules() -> None:
    """static/css/plotly-4.1.1.css holds exactly the rules Plotly would inject.

    Plotly.js skips injecting its <style> when an element with id plotly.js-style-global
    has class no-inline-styles; the page's <link> is that element, so style-src 'self' holds.
    """
    bundle = (ROOT / "static/vendor/plotly-basic-4.1.1.min.js").read_text()
    start = bundle.index("pM={") + 3
    rules = bundle[start : bundle.index("};for(Ng in pM)", start) + 1]
    pairs = re.findall(r'"([^"]+)":(\'[^\']*\'|"[^"]*")', rules)
    expected = [
        re.sub(r"^,", " ,", key)
        .replace("X", ".js-plotly-plot .plotly")
        .replace("Y", ".plotly-notifier")
        + "{"
        + value[1:-1]
        + "}"
        for key, value in pairs
    ]
    css = (ROOT / "static/css/plotly-4.1.1.css").read_text()
    assert [line for line in css.splitlines() if "{" in line] == expected


def test_fixes_and_proposals_follow_the_chosen_units(client: TestClient) -> None:
    params = {"load": "674", "speed": "19.7", "length": "118", "force_unit": "lbf",
              "family": "B,ZBX,KHD,VHD"}  # fmt: skip
    page = soup(client.get("/", params={**params, "length_unit": "in"}))
    notice = page.select_one(".notice.no-pass")
    proposals = [p.text for p in notice.select("ul.remedies li:first-child .proposed")]
    api = client.get(
        "/api/v1/select",
        params={"load_n": 674 * 4.4482216152605, "speed_mm_s": 19.7 * 25.4,
                "length_mm": 118 * 25.4, "family": ["B", "ZBX", "KHD", "VHD"],
                "detail": "full"},
    ).json()  # fmt: skip
    units = {"load_n": " lbf", "speed_mm_s": " in/s", "length_mm": " in"}
    assert [p.rsplit(" ", 1)[1] for p in proposals] == [
        units[name].strip() for name in api["summary"]["remedies"][0]["inputs"]
    ]
    fixes = notice.select_one("ul.failed-fixes").text
    assert " in" in fixes and "lbf" in fixes and " mm" not in fixes and " N " not in fixes
    assert "(lbf, in, in/s, N m, lb)" in page.select_one(".footnote").text


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ("critical_speed_safety_factor", ("0.8 allows 80 %", "1 or below", "smaller is safer")),
        ("buckling_safety_factor", ("0.5 allows half", "1 or below", "smaller is safer")),
        ("torque_safety_factor", ("1.5 asks for 50 % reserve", "1 or more", "larger is safer")),
    ],
)
def test_safety_factor_help_states_its_convention(
    client: TestClient, name: str, words: tuple[str, ...]
) -> None:
    hint = soup(client.get("/")).select_one(f"#h-{name}").text
    assert all(word in hint for word in words), hint


def test_results_columns_say_what_they_mean_in_plain_words(client: TestClient) -> None:
    page = soup(client.get("/", params=AXIS))
    heads = {a.text: a["title"] for a in page.select("table.candidates thead abbr.col-help")}
    assert "motor off" in heads["Holds the load?"]
    assert "above 1× passes" in heads["Critical speed margin"]
    table = page.select_one("table.candidates").text
    assert "seed" not in table and "physics" not in table
    api = api_select(client)
    for body, c in zip(page.select("tbody.candidate"), api["candidates"], strict=True):
        cell = body.select_one("td.backdrive").text
        assert ("Self-locking" in cell) == c["self_locking"]
        assert ("only at full friction" in cell) == (
            c["self_locking"] and not c["self_locking_with_margin"]
        )
        if not c["self_locking_with_margin"]:  # a brake only where there is a load to hold
            held = c["holding_torque"]["brake_nm"] > 0
            assert ("brake ≥" in cell) == held and ("no load to hold" in cell) != held


def test_a_screw_self_locking_only_at_full_friction_shows_its_brake(client: TestClient) -> None:
    """Tr14x6(P3) with a bronze nut lifting 50 lbf and 10 lb: its lead angle (8.7 deg) is
    below the static friction angle (9.4 deg at mu_s 0.16) but above the angle at half of
    it, the friction a hold may count on. Its holding cell says so and gives the brake,
    as its verdict does ("back-drives: a brake of ... holds it power-off"), and does not
    say plainly that it self-locks."""
    params = {"load": "222.4", "moving_mass_kg": "4.536", "orientation": "vertical"}
    params |= {"speed": "50.8", "length": "609.6", "family": "TR-C45", "lead": "6"}
    params |= {"hold_power_off": "false"}  # the motor holds it: the screw still passes
    api = client.get("/api/v1/select", params={
        "load_n": "222.4", "moving_mass_kg": "4.536", "orientation": "vertical",
        "speed_mm_s": "50.8", "length_mm": "609.6", "family": "TR-C45", "lead_mm": "6",
        "hold_power_off": "false", "detail": "full",
    }).json()  # fmt: skip
    bronze = next(c for c in api["candidates"] if c["id"] == "Tr14x6(P3)-bronze")
    assert bronze["self_locking"] and not bronze["self_locking_with_margin"]
    assert bronze["holding_torque"]["brake_nm"] > 0
    page = soup(client.get("/", params=params))
    body = next(b for b in page.select("tbody.candidate") if "Tr14x6(P3)-bronze" in b.text)
    cell = body.select_one("td.backdrive").text
    assert "Self-locking only at full friction" in cell and "brake ≥" in cell, cell
    detail = soup(client.get("/detail", params={**params, "id": "Tr14x6(P3)-bronze"})).text
    assert "It self-locks only at its full static friction" in detail


def test_moving_mass_follows_the_force_unit(client: TestClient) -> None:
    """10 kg typed with newtons shows as 22.05 lb after switching to pound-force
    (1 lb = 0.45359237 kg exactly), and the label says lb."""
    params = {**AXIS, "moving_mass_kg": "10", "force_unit": "lbf", "from_force_unit": "N"}
    page = soup(client.get("/", params=params))
    field = page.select_one("#f-moving_mass_kg")
    assert field is not None and float(str(field["value"])) == pytest.approx(22.05, abs=0.01)
    assert "lb" in page.select_one("#w-moving_mass_kg label").text


def test_the_motor_field_suggests_every_library_motor_and_any(
    client: TestClient, catalog: Catalog
) -> None:
    page = soup(client.get("/", params=AXIS))
    field = page.select_one("#f-motor")
    options = page.select(f"datalist#{field['list']} option")
    assert [o["value"] for o in options] == [*catalog.motors, "any"]
    assert [o.text for o in options[:-1]] == [m.name for m in catalog.motors.values()]


def test_a_ball_screws_detail_shows_no_nut_pv_and_its_l10_life_as_one_value(
    client: TestClient,
) -> None:
    """A ball nut has no plain nut's PV or traverse band: its detail leaves those rows out
    (it showed a PV beside "not applicable to a ball screw"). Its L10 life is one value,
    shown once ("3,180 km", not "3,180–3,180 km"), and without a stroke the life says what
    it needs, not that the nut is not rated."""
    axis = {"load": "100", "speed": "50", "length": "500", "id": "R08-02.5T2-RSIT"}
    with_stroke = soup(client.get("/detail", params={**axis, "stroke": "200"}, headers=HX))
    terms = [dt.text for dt in with_stroke.select("dl.facts dt")]
    assert "PV" not in terms and "Traverse limit" not in terms and "Critical speed" in terms
    life = with_stroke.select_one("dl.facts dd.life").text
    assert life.startswith("3,180 km of travel (318 million cm)"), life
    assert "–" not in life.split(".")[0]
    without = soup(client.get("/detail", params=axis, headers=HX))
    assert without.select_one("dl.facts dd.life").text == (
        "not worked out: a ball nut's L10 life needs a stroke and a thrust on the nut"
    )
    # a plain nut keeps both rows and its life band
    plain = soup(client.get("/detail", params={**axis, "id": "B6000-L10-TFE"}, headers=HX))
    plain_terms = [dt.text for dt in plain.select("dl.facts dt")]
    assert "PV" in plain_terms and "Traverse limit" in plain_terms


def test_a_traverse_limit_not_given_shows_no_unit(client: TestClient) -> None:
    """Tr30x6-ptfe's series gives no traverse speed: its detail says so, where it showed
    '— in/s', a unit beside a missing value."""
    axis = {"load": "180", "speed": "1", "length": "32", "length_unit": "in", "id": "Tr30x6-ptfe"}
    page = soup(client.get("/detail", params=axis, headers=HX))
    row = next(div for div in page.select("dl.facts div") if div.dt.text == "Traverse limit")
    assert row.dd.text == "not given"
    given = soup(client.get("/detail", params={**axis, "id": "B4000-L8-TFE"}, headers=HX))
    row = next(div for div in given.select("dl.facts div") if div.dt.text == "Traverse limit")
    assert row.dd.text.endswith(" in/s")
