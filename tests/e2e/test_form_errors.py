"""The selector's form while typing, in Chromium (issue 34): a field's error shows once the
field has been left or the form submitted, never under fields not yet reached, and no
field moves when a message appears or clears (its line is reserved, a longer message lies
over what follows). Without JavaScript a submitted form shows every error inline.

Every test also asserts that the browser reported no console error.
"""

from pathlib import Path
from typing import Any
from urllib.parse import parse_qs, urlparse

import pytest

from tests.e2e.shots import shoot

#: the top of every visible control of the form, in page pixels
TOPS = """() => Object.fromEntries(
  [...document.querySelectorAll('#selector input:not([type=hidden]), #selector select')]
    .filter(e => e.getClientRects().length)
    .map(e => [e.id || e.name + '=' + e.value, e.getBoundingClientRect().top + scrollY]))"""
#: the error lines showing a message: id -> text
SHOWN = """() => Object.fromEntries([...document.querySelectorAll('#selector span.error')]
  .filter(s => s.textContent.trim()).map(s => [s.id, s.textContent]))"""
#: the ambiguous-comma message (app.contract.exact.AMBIGUOUS_COMMA) runs to two lines or more
AMBIGUOUS = "1,234"


def type_and_wait(page: Any, field: str, text: str) -> None:
    """Type ``text`` at the end of ``field`` and wait until the answer to the whole value
    has been applied (htmx drops the busy indicator's class once it has swapped it)."""
    value = page.input_value(f"#f-{field}") + text

    def asked(response: Any) -> bool:
        return parse_qs(urlparse(response.url).query).get(field) == [value]

    with page.expect_response(asked):
        page.locator(f"#f-{field}").press_sequentially(text, delay=20)
    page.wait_for_function("() => !document.querySelector('#busy.htmx-request')")


def assert_still(page: Any, before: dict[str, float]) -> None:
    after = page.evaluate(TOPS)
    assert after.keys() == before.keys()
    moved = {k: after[k] - before[k] for k in before if abs(after[k] - before[k]) > 1}
    assert moved == {}


@pytest.mark.parametrize("width", [1280, 390])
def test_first_keystroke_shows_no_error_and_no_banner(
    browser: Any, live_server: str, artifacts: Path, width: int
) -> None:
    context = browser.new_context(viewport={"width": width, "height": 900})
    page = context.new_page()
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.goto(live_server + "/")
    tops = page.evaluate(TOPS)
    bar = page.inner_text("#result-bar")
    status = page.inner_text("#status")
    type_and_wait(page, "load", "5")
    # the server did answer with the two required fields still empty ...
    listed = page.eval_on_selector_all(
        "#field-errors [data-error-for]", "items => items.map(i => i.dataset.errorFor)"
    )
    assert listed == ["speed", "length"]
    # ... and the page shows none of it: no message, no red field, no banner, no count
    assert page.evaluate(SHOWN) == {}
    assert page.locator("#selector [aria-invalid]").count() == 0
    assert page.locator("#results .notice.invalid").count() == 0
    assert page.locator("#results .prompt").is_visible()
    assert page.inner_text("#result-bar") == bar and page.inner_text("#status") == status
    assert page.title() == "Leadscrew selector"
    assert_still(page, tops)
    shoot(page, artifacts / f"form-first-keystroke-{width}.png")
    context.close()
    assert errors == []


def test_leaving_an_empty_required_field_shows_its_error(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    page.goto(live_server + "/")
    page.focus("#f-length")
    page.keyboard.press("Tab")  # left before anything was typed: no answer names it yet
    assert page.evaluate("() => document.activeElement.id") == "f-force_unit"
    page.wait_for_function("() => document.querySelector('#e-length').textContent === 'Required.'")
    assert page.get_attribute("#f-length", "aria-invalid") == "true"
    assert page.evaluate(SHOWN) == {"e-length": "Required."}
    type_and_wait(page, "load", "5")  # the answer names speed and length
    assert page.evaluate(SHOWN) == {"e-length": "Required."}  # speed is not reached yet
    assert page.locator("#f-speed[aria-invalid]").count() == 0
    page.focus("#f-speed")
    page.keyboard.press("Tab")
    assert page.evaluate(SHOWN) == {"e-speed": "Required.", "e-length": "Required."}
    assert page.get_attribute("#f-speed", "aria-invalid") == "true"
    assert console_errors == []


@pytest.mark.parametrize("width", [1280, 390])
def test_no_field_moves_as_errors_appear_and_clear(
    browser: Any, live_server: str, artifacts: Path, width: int
) -> None:
    context = browser.new_context(viewport={"width": width, "height": 900})
    page = context.new_page()
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.goto(live_server + "/")
    tops = page.evaluate(TOPS)
    type_and_wait(page, "load", "5")
    assert_still(page, tops)
    page.focus("#f-speed")
    page.keyboard.press("Tab")  # speed left empty: its error appears
    assert page.evaluate(SHOWN) == {"e-speed": "Required."}
    assert_still(page, tops)
    type_and_wait(page, "length", AMBIGUOUS)
    page.keyboard.press("Tab")  # a message of two lines or more, shown as length is left
    long = page.locator("#e-length")
    assert long.inner_text().startswith("Ambiguous")
    box = long.bounding_box()
    assert box is not None and box["height"] > 30  # wrapped, lying over what follows
    assert_still(page, tops)
    shoot(page, artifacts / f"form-errors-shown-{width}.png")
    page.fill("#f-length", "")
    type_and_wait(page, "length", "500")  # the long message clears
    type_and_wait(page, "speed", "50")  # and so does speed's: results
    page.wait_for_selector("#results table.candidates")
    assert page.evaluate(SHOWN) == {}
    assert page.locator("#selector [aria-invalid]").count() == 0
    assert_still(page, tops)
    shoot(page, artifacts / f"form-errors-cleared-{width}.png")
    context.close()
    assert errors == []


def test_submitting_shows_every_error(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    page.goto(live_server + "/")
    tops = page.evaluate(TOPS)
    type_and_wait(page, "load", "5")
    assert page.evaluate(SHOWN) == {}
    with page.expect_response(lambda r: "load=5" in r.url):
        page.click("#selector .actions button[type=submit]")
    page.wait_for_selector("#results .notice.invalid")
    assert page.evaluate(SHOWN) == {"e-speed": "Required.", "e-length": "Required."}
    for name in ("speed", "length"):
        assert page.get_attribute(f"#f-{name}", "aria-invalid") == "true"
    assert "2 fields to correct" in page.inner_text("#status")
    assert_still(page, tops)
    assert console_errors == []


def test_without_javascript_a_submitted_form_shows_every_error(
    browser: Any, live_server: str
) -> None:
    context = browser.new_context(java_script_enabled=False)
    page = context.new_page()
    page.goto(live_server + "/")
    page.fill("#f-load", "abc")
    page.click("#selector .actions button[type=submit]")
    page.wait_for_selector("#results .notice.invalid")
    assert page.inner_text("#e-load") == "Enter a number."
    assert page.inner_text("#e-speed") == "Required."
    assert page.inner_text("#e-length") == "Required."
    context.close()
