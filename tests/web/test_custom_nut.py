"""The custom screw with the catalog's nut materials (issue 34, item 3): the same nut data
the catalog's ISO trapezoidal families use, with their provenance; the catalog row's
"Try this screw with other values" link giving the same checks and the same answer on
/custom; and the summary that names the checks a screw's missing values stopped."""

from typing import Any
from urllib.parse import parse_qsl

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.catalog import Catalog
from app.core.units import to_si
from app.web.screw_form import BY_NAME

#: an axis with a duty, a motor torque and a temperature, so the nut checks all apply
AXIS = (
    "load=500&speed=20&length=400&stroke=300&cycles_per_day=100&required_life_years=5"
    "&max_torque=2&ambient_c=40&lubrication=greased"
)
#: Tr12x3 (ISO 2904 preferred size: d = 12 mm, P = 3 mm, d3 = 8.5 mm) in C45 steel
TR12X3 = (
    "outer_diameter_mm=12&root_diameter_mm=8.5&lead_mm=3&thread_half_angle_deg=15"
    "&friction_dynamic=0.13&friction_static=0.16&material=c45-steel"
)
#: Tr12x3's thread as the API's custom screw takes it (mm; its default flank angle and
#: material)
TR12X3_API = {
    "outer_diameter_mm": 12,
    "root_diameter_mm": 8.5,
    "lead_mm": 3,
    "friction_dynamic": 0.13,
    "friction_static": 0.16,
}


def soup(text: str) -> BeautifulSoup:
    return BeautifulSoup(text, "html.parser")


def test_the_bronze_nut_is_the_catalogs_with_its_cited_limits(catalog: Catalog) -> None:
    """Shigley, Mechanical Engineering Design, Table 8-4 (after Rothbart): steel on
    bronze 1600 psi (11 MPa) up to 10 ft/min, 150 psi (1.0 MPa) from 50 ft/min;
    Bimeccanica's sliding-speed limit of 25 m/min = 0.4167 m/s."""
    bronze = catalog.nut_materials["bronze"]
    table = bronze.limits["bearing_pressure_table"]
    assert table[0] == (0.05, pytest.approx(to_si(1600.0, "psi"), rel=0.01))
    assert table[-1] == (0.25, pytest.approx(to_si(150.0, "psi"), rel=0.05))
    assert bronze.limits["max_sliding_speed_m_s"] == pytest.approx(25.0 / 60.0, rel=1e-3)
    assert bronze.provenance["bearing_pressure"].kind == "handbook"
    assert "Shigley Table 8-4" in bronze.provenance["bearing_pressure"].source
    assert bronze.thrust_table is not None and bronze.provenance["dynamic_thrust"].kind == "vendor"
    # the same values the catalog's own bronze candidates carry
    row = catalog.by_id["Tr12x3-bronze"]
    assert table == row.bearing_pressure_table
    assert bronze.limits["wear_rate_m2_n"] == row.wear_rate_m2_n


def test_seed_nuts_rated_by_their_maker_are_not_material_presets(catalog: Catalog) -> None:
    assert set(catalog.nut_materials) == {"bronze", "acetal", "ptfe"}


def _checks(client: TestClient, screw: dict[str, object]) -> dict[str, float | None]:
    body = {
        "application": {
            "load_n": 500,
            "speed_mm_s": 20,
            "length_mm": 400,
            "stroke_mm": 300,
            "cycles_per_day": 100,
            "required_life_years": 5,
            "max_torque_nm": 2,
            "ambient_c": 40,
            "lubrication": "greased",
        },
        "screw": screw,
    }
    response = client.post("/api/v1/evaluate", json=body)
    assert response.status_code == 200, response.text
    utilization: dict[str, float | None] = response.json()["candidate"]["utilization"]
    return utilization


@pytest.mark.parametrize("cid", ["Tr12x3-bronze", "Tr12x3-acetal", "Tr20x4-ptfe"])
def test_try_this_screw_gives_the_catalog_rows_checks_and_answer(
    client: TestClient, cid: str
) -> None:
    detail = soup(client.get(f"/detail?{AXIS}&id={cid}").text)
    link = detail.select_one(".try-custom a")["href"]
    values = dict(parse_qsl(link.split("?", 1)[1]))
    assert values["nut"] == cid.split("-")[1]
    screw: dict[str, object] = {k: float(v) for k, v in values.items() if k in BY_NAME}
    screw.update(material=values["material"], nut_material=values["nut"])
    catalog_checks = _checks(client, {"catalog_id": cid})
    custom_checks = _checks(client, screw)
    assert list(custom_checks) == list(catalog_checks)
    for name, used in catalog_checks.items():
        expected = None if used is None else pytest.approx(used, rel=1e-6)
        assert custom_checks[name] == expected, name
    # the page the link opens says the same
    page = soup(client.get(link).text)
    shown = [li["data-check"] for li in page.select("li.check")]
    assert shown == list(catalog_checks)
    catalog_verdict = detail.select_one(".verdict").text.removeprefix("Rejected: ")
    custom_verdict = " ".join(page.select_one(".custom-verdict").text.split())
    assert custom_verdict.lower().startswith(catalog_verdict.lower())


def test_a_bronze_nut_gives_the_custom_screw_the_nut_checks(client: TestClient) -> None:
    bare = soup(client.get(f"/custom?{TR12X3}&{AXIS}").text)
    nut = soup(client.get(f"/custom?{TR12X3}&nut=bronze&pitch_mm=3&{AXIS}").text)
    bare_checks = {li["data-check"] for li in bare.select("li.check")}
    nut_checks = {li["data-check"] for li in nut.select("li.check")}
    added = {"bearing_pressure", "max_sliding_speed", "design_load", "wear_life", "temperature"}
    assert added <= nut_checks and not added & bare_checks
    # the nut's limits are listed with their provenance
    limits = nut.select_one("table.nut-limits")
    assert "bronze" in limits.caption.text
    assert limits.select_one("td .kind-handbook") and limits.select_one("td .kind-vendor")


def test_skipped_checks_are_named_with_the_missing_values(client: TestClient) -> None:
    bare = soup(client.get(f"/custom?{TR12X3}&{AXIS}").text)
    verdict = " ".join(bare.select_one(".custom-verdict").text.split())
    assert "every check" not in verdict
    assert "Not checked:" in verdict
    assert "Nut contact pressure (no allowed contact pressure" in verdict
    no_thread = soup(client.get(f"/custom?{TR12X3}&nut=bronze&{AXIS}").text)
    verdict = " ".join(no_thread.select_one(".custom-verdict").text.split())
    assert "Nut contact pressure (no pitch)" in verdict


def test_the_api_refuses_an_unknown_nut_and_a_pitch_that_does_not_divide_the_lead(
    client: TestClient,
) -> None:
    screw = dict(TR12X3_API)
    app = {"load_n": 100, "speed_mm_s": 20, "length_mm": 400}
    unknown = client.post(
        "/api/v1/evaluate",
        json={"application": app, "screw": {**screw, "nut_material": "unobtainium"}},
    )
    assert unknown.status_code == 422
    assert unknown.json()["detail"][0]["field"] == "screw.nut_material"
    odd = client.post(
        "/api/v1/evaluate", json={"application": app, "screw": {**screw, "pitch_mm": 2}}
    )
    assert odd.status_code == 422
    assert "pitch_mm" in odd.text
    page = soup(client.get(f"/custom?{TR12X3}&nut=unobtainium&load=100&speed=20&length=400").text)
    assert page.select_one("#e-nut").text.strip()


@pytest.mark.parametrize(
    ("screw", "words"),
    [
        # d2 = 0.5 - 1 / 2 = 0 mm: the lead angle was 90 deg and the root stress NaN
        ({"outer_diameter_mm": 0.5, "root_diameter_mm": 0.475, "lead_mm": 1, "pitch_mm": 1},
         "d - P/2 = 0 mm is not above the root diameter 0.475 mm"),
        # ten starts of P 4 on d 10: at d2 = 8 mm, tan(lambda) = 40 / (8 pi) = 1.592 and the
        # thread drives only below 0.99 cos(14.5 deg) / 1.592 = 0.602; the mean of the
        # diameters (8.75 mm) allows 0.659
        ({"outer_diameter_mm": 10, "root_diameter_mm": 7.5, "lead_mm": 40, "pitch_mm": 4},
         "d - P/2 = 8 mm, with this lead (57.9 deg lead angle) the thread cannot be driven "
         "at friction 0.63: it must be below 0.602"),
    ],
    ids=["pitch-line-below-the-root", "undrivable-at-d2"],
)  # fmt: skip
def test_a_pitch_whose_flanks_do_not_fit_the_screw_is_refused(
    client: TestClient, screw: dict[str, float], words: str
) -> None:
    """With a pitch, the torque and the nut's pressure read the basic profile's pitch
    diameter d2 = d - P/2 (ISO 2904): a pitch that puts it at or below the root, or a lead
    too steep to drive there, is refused on the pitch."""
    body = {"load_n": 100, "speed_mm_s": 20, "length_mm": 400}
    full = {**screw, "friction_dynamic": 0.63, "friction_static": 0.2}
    response = client.post("/api/v1/evaluate", json={"application": body, "screw": full})
    assert response.status_code == 422, response.text
    (error,) = response.json()["detail"]
    assert error["field"] == "screw.pitch_mm" and words in error["message"]


def test_the_applications_nut_length_sets_the_custom_nuts(client: TestClient) -> None:
    """The nut length is the family's 2 x d (24 mm for Tr12) unless the application's
    nut length sets another: the contact pressure falls as 1 / L (engaged turns L / P)."""
    screw = {**TR12X3_API, "pitch_mm": 3, "thread_half_angle_deg": 15, "nut_material": "bronze"}
    app = {"load_n": 500, "speed_mm_s": 20, "length_mm": 400}

    def used(**extra: float) -> float:
        body = {"application": {**app, **extra}, "screw": screw}
        response = client.post("/api/v1/evaluate", json=body)
        assert response.status_code == 200, response.text
        return float(response.json()["candidate"]["utilization"]["bearing_pressure"])

    assert used(nut_length_mm=30) == pytest.approx(used() * 24 / 30, rel=1e-6)
    assert used(nut_length_mm=24) == pytest.approx(used(), rel=1e-12)


def test_the_api_lists_the_nut_materials_with_their_provenance(
    client: TestClient, catalog: Catalog
) -> None:
    response = client.get("/api/v1/nut-materials")
    assert response.status_code == 200
    listed = {n["key"]: n for n in response.json()["nut_materials"]}
    assert set(listed) == set(catalog.nut_materials)
    bronze = {v["label"]: v for v in listed["bronze"]["values"]}
    pressure = bronze["Allowed contact pressure by sliding speed"]
    assert pressure["value"].startswith("0.05 m/s: 11 MPa")  # Shigley Table 8-4
    assert pressure["provenance"]["kind"] == "handbook"
    assert bronze["Maximum sliding speed"]["provenance"]["kind"] == "vendor"


def test_a_screw_without_a_nut_has_no_play_given_not_zero(client: TestClient) -> None:
    """A screw of one's own without a catalog nut has no axial play given: the API says
    null (it said 0-0 mm, a perfect nut), and the anti-backlash check says the play is
    not given. The catalog's bronze nut brings its play, 0.05-0.3 mm (assumed for the ISO
    fit 7H/7e)."""
    screw = dict(TR12X3_API)
    app = {"load_n": 100, "speed_mm_s": 20, "length_mm": 400, "require_anti_backlash": True}

    def candidate(**extra: str) -> dict[str, Any]:
        body = {"application": app, "screw": {**screw, **extra}}
        response = client.post("/api/v1/evaluate", json=body)
        assert response.status_code == 200, response.text
        return dict(response.json()["candidate"])

    bare, bronze = candidate(), candidate(nut_material="bronze")
    assert bare["accuracy"]["backlash_mm"] is None
    assert bronze["accuracy"]["backlash_mm"] == pytest.approx([0.05, 0.3])
    messages = {c["name"]: c["message"] for c in bare["checks"]}
    assert messages["anti_backlash"] == "Free-wheeling nut; its axial play is not given."


def test_a_pitch_refused_on_an_inch_form_is_said_in_inches(client: TestClient) -> None:
    """The custom page typed in inches: the lead 1/4 in is no whole number of 0.1 in
    pitches, and a 0.3 in pitch on a 1/2 in screw puts d - P/2 = 0.35 in below its 0.36 in
    root; each said in inches (they were said in mm: 6.35 mm, 8.89 and 9.144 mm)."""
    inch = ("thread_half_angle_deg=14.5&friction_dynamic=0.13&friction_static=0.16"
            "&nut=bronze&material=c45-steel&load=20&speed=1&length=20&length_unit=in")  # fmt: skip
    cases = {
        "outer_diameter_mm=0.5&root_diameter_mm=0.35&lead_mm=0.25&pitch_mm=0.1":
            "The lead 0.25 in must be a whole number of pitches.",
        "outer_diameter_mm=0.5&root_diameter_mm=0.36&lead_mm=0.3&pitch_mm=0.3":
            "Too coarse for this screw: its flanks' pitch diameter d - P/2 = 0.35 in is not "
            "above the root diameter 0.36 in.",
    }  # fmt: skip
    for screw, words in cases.items():
        page = soup(client.get(f"/custom?{screw}&{inch}").text)
        assert page.select_one("#e-pitch_mm").text.strip() == words
