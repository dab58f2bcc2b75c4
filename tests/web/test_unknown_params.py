"""Issue 29, item 7: a page, share or CSV link with a parameter nothing reads says so,
naming it and the likely intended name, instead of giving the result without it."""

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
