"""Issue 29, item 7: a page, share or CSV link with a parameter nothing reads says so,
naming it and the likely intended name, instead of giving the result without it."""

import html

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.contract.fields import FIELDS
from app.contract.params import PAGE_NAMES, likely_name
from app.contract.units import DEFAULT_UNITS

AXIS = {"load": "10", "speed": "50", "length": "300"}
MISSPELT = "Unknown parameter 'moving_mass' (did you mean 'moving_mass_kg'?)"


def test_the_page_names_the_parameter_and_shows_no_result(client: TestClient) -> None:
    page = BeautifulSoup(client.get("/", params={**AXIS, "moving_mass": "3"}).text, "html.parser")
    assert MISSPELT in page.select_one("#e-form").text
    assert page.select_one(".count-passed") is None  # no result without the mass


@pytest.mark.parametrize("path", ["/export.csv", "/export.json", "/report", "/compare"])
def test_links_refuse_it_with_the_name(client: TestClient, path: str) -> None:
    response = client.get(path, params={**AXIS, "moving_mass": "3", "ids": "a,b", "id": "x"})
    assert response.status_code == 422
    assert "moving_mass_kg" in response.text


def test_the_api_refuses_it_too(client: TestClient) -> None:
    """The GET API, like its JSON body, refuses a name it does not read (422 on it)."""
    query = {"load_n": "10", "speed_mm_s": "50", "length_mm": "300", "moving_mass": "3"}
    response = client.get("/api/v1/select", params=query)
    assert response.status_code == 422
    assert [e["field"] for e in response.json()["detail"]] == ["moving_mass"]
    body = {"load_n": 10, "speed_mm_s": 50, "length_mm": 300, "moving_mass": 3}
    assert client.post("/api/v1/select", json=body).status_code == 422


def test_every_name_the_form_writes_is_read(client: TestClient) -> None:
    """The names the page's own form and links carry (every field, the unit switches and
    the hidden ``from_*`` and ``typed_*`` records) pass: a result, no message."""
    names = {f.page for f in FIELDS} | set(DEFAULT_UNITS)
    assert names <= PAGE_NAMES
    switched = {**AXIS, "force_unit": "lbf", "from_force_unit": "N", "typed_load": "10|N"}
    page = BeautifulSoup(client.get("/", params=switched).text, "html.parser")
    assert page.select_one("#e-form") is None and page.select_one(".count-passed") is not None
    detail = client.get("/detail", params={**AXIS, "id": "Tr16x4-ptfe"})
    assert detail.status_code == 200


@pytest.mark.parametrize(
    ("typed", "meant"),
    [("moving_mass", "moving_mass_kg"), ("speed_mm_s", "speed"), ("lenght", "length"),
     ("stroke_mm", "stroke"), ("zzz", None)],
)  # fmt: skip
def test_likely_names(typed: str, meant: str | None) -> None:
    assert likely_name(typed, PAGE_NAMES) == meant


@pytest.mark.parametrize(
    ("name", "value", "message"),
    [
        ("force_unit", "lbs", "Unknown force unit 'lbs': choose N, lbf or kgf."),
        ("length_unit", "inch", "Unknown length unit 'inch': choose mm or in."),
        ("from_torque_unit", "Nm", "Unknown torque unit 'Nm': choose N_m, oz_in or lb_in."),
        ("accel_unit", "G", "Unknown acceleration unit 'G': choose mm_s2, m_s2, g or in_s2."),
    ],
)
def test_a_unit_no_switch_offers_is_named_not_read_as_the_default(
    client: TestClient, name: str, value: str, message: str
) -> None:
    """``load=22&force_unit=lbs`` was read as 22 N (the unknown unit fell back to the
    default): now the page names the unit and shows no result, and a link refuses it."""
    query = {**AXIS, name: value}
    page = BeautifulSoup(client.get("/", params=query).text, "html.parser")
    assert message in page.select_one("#e-form").text
    assert page.select_one(".count-passed") is None
    refused = client.get("/export.csv", params=query)
    assert refused.status_code == 422
    assert message in html.unescape(refused.text)


SCREW = {
    "outer_diameter_mm": "10", "root_diameter_mm": "8", "lead_mm": "2",
    "friction_dynamic": "0.15", "friction_static": "0.2", "pv_limit_mpa_m_s": "3",
}  # fmt: skip


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        ({"moving_mass": "3"}, MISSPELT),
        ({"force_unit": "lbs"}, "Unknown force unit 'lbs'"),
        ({"lead": "5"}, "'lead' is not read on this page: it chooses among the catalog's"),
        ({"material": "custom", "youngs_modulus_gpa": "200"}, "'youngs_modulus_gpa'"),
    ],
)
def test_the_custom_screw_page_names_what_it_does_not_read(
    client: TestClient, extra: dict[str, str], message: str
) -> None:
    """The custom screw's page and exports read the screw's, its material's and its nut's
    names besides the application's, and none of the catalog's filters (a lead there is
    the screw's own ``lead_mm``): anything else is named, never evaluated without."""
    query = {**SCREW, **AXIS, **extra}
    page = BeautifulSoup(client.get("/custom", params=query).text, "html.parser")
    assert message in page.select_one("#e-form").text
    assert page.select_one(".verdict") is None
    assert client.get("/custom/export.csv", params=query).status_code == 422


def test_every_name_the_custom_page_writes_is_read(client: TestClient) -> None:
    """A custom result's share link, with a material of its own, reopens the result
    with no message; so do its exports."""
    own = {"material": "custom", "youngs_modulus_pa": "1.9e11", "density_kg_m3": "7900"}
    first = BeautifulSoup(
        client.get("/custom", params={**SCREW, **AXIS, **own}).text, "html.parser"
    )
    assert first.select_one("#e-form") is None
    share = first.select_one("a.share-link")["href"]
    again = BeautifulSoup(client.get(share).text, "html.parser")
    assert again.select_one("#e-form") is None and again.select_one(".verdict") is not None
    assert client.get(share.replace("/custom?", "/custom/export.csv?")).status_code == 200


def test_a_choice_no_field_offers_is_named_with_the_values_as_written(
    client: TestClient,
) -> None:
    """The error lists the choices as a link writes them: an input's API name inside a
    value ('motor_margin' holds the library motor's 'motor') is no field to relabel."""
    page = BeautifulSoup(client.get("/", params={**AXIS, "rank_by": "bogus"}).text, "html.parser")
    message = page.select_one("#e-rank_by").text
    assert "'motor_margin'" in message and "library motor" not in message


@pytest.mark.parametrize(
    ("value", "held"), [("maybe", None), ("no", False), ("0", False), ("yes", True), ("on", True)]
)
def test_a_yes_no_input_reads_yes_or_no_and_names_anything_else(
    client: TestClient, value: str, held: bool | None
) -> None:
    """``hold_power_off=maybe`` was read as no (anything not a yes-word was): now it is
    an error at the field, and the yes- and no-words are read as such, the field's
    select showing what is read (with 'no' it showed its first option, yes)."""
    page = BeautifulSoup(
        client.get("/", params={**AXIS, "hold_power_off": value}).text, "html.parser"
    )
    error = page.select_one("#e-hold_power_off").text
    if held is None:
        assert error == "Choose yes or no (true or false)."
        assert page.select_one(".count-passed") is None
    else:
        assert error == "" and page.select_one(".count-passed") is not None
        chosen = page.select_one("#f-hold_power_off option[selected]")
        assert chosen["value"] == ("true" if held else "false")


def test_a_link_error_alone_is_not_called_a_highlighted_field(client: TestClient) -> None:
    """The notice asks to correct highlighted fields only when some are: an unknown unit
    is said as it is (it said "Please correct the highlighted field." with none)."""
    alone = BeautifulSoup(
        client.get("/", params={**AXIS, "force_unit": "lbs"}).text, "html.parser"
    ).select_one(".notice.invalid")
    assert "highlighted" not in alone.text and "Unknown force unit 'lbs'" in alone.text
    field = BeautifulSoup(client.get("/", params={**AXIS, "speed": "x"}).text, "html.parser")
    notice = field.select_one(".notice.invalid").text
    assert "Please correct the highlighted field." in notice
    assert field.select_one("#e-speed").text == "Enter a number."


def test_a_family_repeated_is_read_as_the_api_reads_it_and_another_name_refused(
    client: TestClient,
) -> None:
    """family=HIWIN-ROLLED&family=HIWIN-GROUND (the API's form) kept only the last family
    on the page: both are read, as 'HIWIN-ROLLED,HIWIN-GROUND'. A number given twice is
    named, not silently taken at its last."""
    both = "load=100&speed=50&length=500&family=HIWIN-ROLLED&family=HIWIN-GROUND"
    joined = "load=100&speed=50&length=500&family=HIWIN-ROLLED,HIWIN-GROUND"
    count = "section.results"
    assert client.get(f"/?{both}").status_code == 200
    one = BeautifulSoup(client.get(f"/?{both}").text, "html.parser").select_one(count).text
    two = BeautifulSoup(client.get(f"/?{joined}").text, "html.parser").select_one(count).text
    assert one == two and "Evaluated 53" in " ".join(one.split())
    twice = client.get("/export.csv?load=100&load=200&speed=50&length=500")
    assert twice.status_code == 422 and "'load' is given 2 times" in html.unescape(twice.text)
