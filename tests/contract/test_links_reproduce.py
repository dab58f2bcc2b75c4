"""A share link reproduces its answer to the last digit: the page's form, the API and the
link each read the same inputs the same way (issue 31, item 5), and the page reads a
motor curve's numbers as it reads any number (decimal comma, fractions; README, API)."""

import re
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.contract.inputs import ApplicationIn
from app.contract.torque_curve import curve_to_api

PASSED = re.compile(r'class="count-passed">(\d+)<')
SHARE = re.compile(r'class="share-link" href="([^"]+)"')
AXIS = {"load": "1", "speed": "50", "length": "500", "lead": "4"}


def _passed(page: str) -> list[str]:
    return PASSED.findall(page)


def _share(page: str) -> str:
    found = SHARE.search(page)
    assert found, "no share link on the page"
    return found.group(1).replace("&amp;", "&")


def test_a_motor_curve_speed_keeps_every_figure_in_the_link(client: TestClient) -> None:
    """50 mm/s on a 4 mm lead is 750 rpm: a curve ending at 749.9999992498 rpm cannot
    drive it, one ending at 750 can. Cut to 12 figures the first became the second."""
    typed = client.get("/", params={**AXIS, "motor_curve": "0 1\n749.9999992498 1"}).text
    ends_at_750 = client.get("/", params={**AXIS, "motor_curve": "0 1\n750 1"}).text
    assert _passed(typed) != _passed(ends_at_750)  # the case tells the two apart
    link = _share(typed)
    assert "749.9999992498" in link
    assert _passed(client.get(link).text) == _passed(typed)


@pytest.mark.parametrize(
    ("given", "as_read"),
    [
        ({"nut_material": "bronze "}, {"nut_material": "bronze"}),
        ({"nut_material": "ANY"}, {"nut_material": "any"}),
        ({"nut_material": " Any"}, {"nut_material": "any"}),
        ({"family": ["B "]}, {"family": ["B"]}),
        ({"family": [" TR-C45", "B"]}, {"family": ["TR-C45", "B"]}),
        ({"motor": "NONE"}, {"motor": "none"}),
    ],
    ids=["trailing-space", "any-in-capitals", "any-mixed", "family-space", "family-list", "none"],
)
def test_the_api_answers_as_its_share_link(
    client: TestClient, given: dict[str, Any], as_read: dict[str, Any]
) -> None:
    """The API reads text inputs as the page does (spaces around dropped, the word for
    none in any case), so its answer and the page its share_url opens agree."""
    axis = {"load_n": 1, "speed_mm_s": 50, "length_mm": 500}
    answer = client.post("/api/v1/select", json={**axis, **given}).json()
    same = client.post("/api/v1/select", json={**axis, **as_read}).json()
    assert answer["counts"] == same["counts"]
    assert answer["share_url"] == same["share_url"]
    page = client.get(answer["share_url"]).text
    passed = answer["summary"]["message"].split(" of ")[0]
    assert _passed(page) == [passed] or (passed == "No" and _passed(page) == ["0"]), (
        answer["summary"]["message"],
        _passed(page),
    )


def test_the_model_reads_text_as_the_page_does() -> None:
    inputs = ApplicationIn.model_validate(
        {"load_n": 1, "speed_mm_s": 1, "length_mm": 100, "nut_material": " ANY ", "family": ["B "]}
    )
    dumped = inputs.model_dump()
    assert (dumped["nut_material"], dumped["family"]) == ("any", "B")
    assert inputs.axis().nut_material is None and inputs.axis().families == ("B",)


@pytest.mark.parametrize(
    "text",
    ["0 1/2\n3000 1/4", "0 0,5\n3000 0,25", "0\t0,5\n3000\t0,25", "0 1/2; 3000 0,25"],
    ids=["fractions", "decimal-commas", "tabs", "semicolons"],
)
def test_the_page_reads_a_curve_as_it_reads_numbers(client: TestClient, text: str) -> None:
    """README: the page's form reads a decimal comma and fractions; a curve's numbers too,
    to the same points as 0.5 and 0.25 N m written as ASCII decimals."""
    assert curve_to_api(text, {}) == [[0.0, 0.5], [3000.0, 0.25]]
    page = client.get("/", params={**AXIS, "motor_curve": text}).text
    plain = client.get("/", params={**AXIS, "motor_curve": "0:0.5,3000:0.25"}).text
    assert 'id="e-motor_curve"></' in page  # no message under the field
    assert _passed(page) == _passed(plain) and _passed(page)


def test_a_curve_the_page_cannot_read_names_the_point(client: TestClient) -> None:
    page = client.get("/", params={**AXIS, "motor_curve": "0 1/0\n3000 1"}).text
    assert 'id="e-motor_curve">Point 1 &#39;0 1/0&#39;' in page and _passed(page) == []
