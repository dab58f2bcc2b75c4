"""Numbers as engineers write them by hand: a decimal comma and imperial fractions.

The page reads '20,5' as 20.5 and '5/16', '1 1/4', '1-1/4' as the fractions they are,
refuses what it cannot read with a message at the field, and never yields a non-finite
number; the API keeps to JSON numbers and ASCII decimals and says so in its 422.
"""

import math
from fractions import Fraction
from urllib.parse import parse_qs

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient
from hypothesis import given, settings
from hypothesis import strategies as st

from app.contract.exact import ZERO_DENOMINATOR, page_value, read_exact, read_number
from app.contract.fields import BY_PAGE
from app.contract.form import parse_inputs
from app.contract.units import DEFAULT_UNITS

INCH = {**DEFAULT_UNITS, "length_unit": "in"}
AXIS = {"load": "100", "speed": "50", "length": "500"}


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("20,5", 20.5),
        ("-0,125", -0.125),
        (",5", 0.5),
        ("1,5e3", 1500.0),
        ("0,250", 0.25),  # a leading zero: no thousands separator
        ("5/16", 0.3125),
        ("1 1/4", 1.25),
        ("1-1/4", 1.25),
        ("-1 1/2", -1.5),
        ("  3/8 ", 0.375),
        ("20.5", 20.5),
    ],
)
def test_hand_written_numbers_read_as_written(text: str, value: float) -> None:
    assert read_number(text) == (value, "")


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("1/0", ZERO_DENOMINATOR),
        ("1 1/0", ZERO_DENOMINATOR),
        ("nan", "Enter a number."),
        ("inf", "Enter a number."),
        ("-Infinity", "Enter a number."),
        ("1e999", "Enter a finite number."),
        ("1/2/3", "Enter a number."),
        ("1,2,3", "Enter a number."),
        ("1.5,5", "Enter a number."),
        ("1 1", "Enter a number."),
    ],
)
def test_unreadable_numbers_are_refused_with_a_message(text: str, message: str) -> None:
    assert read_number(text) == (None, message)


def test_a_comma_that_may_group_thousands_is_refused_with_both_readings() -> None:
    value, message = read_number("1,234")
    assert value is None
    assert "1.234" in message and "1234" in message
    assert read_number("12,500,000") == (None, "Write 12500000 without the thousands separators.")


def test_a_fraction_of_an_inch_is_converted_exactly() -> None:
    """5/16 in = 0.3125 x 25.4 mm = 7.9375 mm (NIST SP 811: 1 in = 25.4 mm exactly)."""
    assert page_value(BY_PAGE["lead"], "5/16", INCH) == 0.3125 * 25.4 == 7.9375
    assert page_value(BY_PAGE["length"], "1-1/4", INCH) == 1.25 * 25.4


def test_one_third_is_rounded_once() -> None:
    """1/3 in times 25.4 mm/in, computed exactly and rounded once: 127/15 mm."""
    assert page_value(BY_PAGE["length"], "1/3", INCH) == float(Fraction(127, 15))


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet="0123456789,./- eEnaif+", max_size=12))
def test_the_page_never_reads_a_non_finite_number(text: str) -> None:
    value, message = read_number(text)
    if value is None:
        assert message
    else:
        assert math.isfinite(value) and message == ""


@settings(max_examples=200, deadline=None)
@given(
    st.integers(0, 10**6),
    st.integers(0, 10**6),
    st.integers(1, 10**6),
    st.sampled_from([" ", "-", "  "]),
)
def test_mixed_numbers_are_exact(whole: int, numerator: int, denominator: int, sep: str) -> None:
    exact = whole + Fraction(numerator, denominator)
    assert read_exact(f"{whole}{sep}{numerator}/{denominator}") == (exact, "")
    assert read_exact(f"-{whole}{sep}{numerator}/{denominator}") == (-exact, "")


@settings(max_examples=200, deadline=None)
@given(st.decimals(allow_nan=False, allow_infinity=False, places=4, min_value=-1e6, max_value=1e6))
def test_a_decimal_comma_reads_as_the_point(number: object) -> None:
    """'d,ddd' with one to three leading digits could group thousands and is refused;
    every other decimal reads the same with a comma as with a point."""
    text = f"{number:f}"
    if "." not in text:
        return
    comma = text.replace(".", ",")
    whole, _, fraction = text.lstrip("-").partition(".")
    if len(fraction) == 3 and whole[:1] != "0" and len(whole) <= 3:
        assert read_number(comma)[0] is None
    else:
        assert read_number(comma) == read_number(text)


def test_the_page_takes_20_comma_5_and_its_share_link_keeps_the_value(
    client: TestClient,
) -> None:
    html = client.get("/", params={**AXIS, "load": "20,5", "length_unit": "in", "lead": "5/16"})
    page = BeautifulSoup(html.text, "html.parser")
    assert page.select_one("#e-load").text == ""
    assert page.select_one("#e-lead").text == ""
    link = page.select_one("a.print-link")["href"]
    query = parse_qs(link.split("?", 1)[1])
    assert query["load"] == ["20.5"]
    assert query["lead"] == ["0.3125"]
    inputs, errors = parse_inputs({**AXIS, "load": "20,5", "lead": "5/16"}, INCH)
    assert errors == {} and inputs is not None
    dumped = inputs.model_dump()
    assert dumped["load_n"] == 20.5
    assert dumped["lead_mm"] == 7.9375


def test_the_page_explains_a_fraction_it_refuses(client: TestClient) -> None:
    html = client.get("/", params={**AXIS, "length": "1/0"})
    page = BeautifulSoup(html.text, "html.parser")
    assert page.select_one("#e-length").text == ZERO_DENOMINATOR
    assert page.select_one("#f-length")["aria-invalid"] == "true"


@pytest.mark.parametrize("text", ["20,5", "5/16", "1 1/4"])
def test_the_api_expects_a_decimal_and_says_so_at_the_field(client: TestClient, text: str) -> None:
    params = {"load_n": text, "speed_mm_s": "50", "length_mm": "500"}
    response = client.get("/api/v1/select", params=params)
    assert response.status_code == 422
    detail = [d for d in response.json()["detail"] if d["field"] == "load_n"]
    assert detail and "ASCII decimal such as 20.5" in detail[0]["message"]
