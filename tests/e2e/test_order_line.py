"""The ordering line's copy button in Chromium: it puts the line on the clipboard, at a
desktop and a phone width (screenshots under test-artifacts/, ``shots``), with axe finding nothing;
without JavaScript the button stays hidden and the line is text to select."""

import json
import urllib.parse
import urllib.request
from pathlib import Path
from typing import Any

import pytest

from tests.e2e.shots import shoot
from tests.e2e.test_accessibility import AXE, RULE_TAGS, summary

AXIS = "load=50&speed=200&length=500"
API_AXIS = "load_n=50&speed_mm_s=200&length_mm=500"


def _first(live_server: str) -> dict[str, Any]:
    """The top candidate of the full select (the compact one leaves the line out)."""
    url = f"{live_server}/api/v1/select?{API_AXIS}&detail=full"
    with urllib.request.urlopen(url, timeout=30) as r:
        candidate: dict[str, Any] = json.load(r)["candidates"][0]
    return candidate


@pytest.mark.parametrize("width", [1280, 390])
def test_copy_button_puts_the_line_on_the_clipboard(
    browser: Any, live_server: str, artifacts: Path, width: int
) -> None:
    first = _first(live_server)
    context = browser.new_context(
        viewport={"width": width, "height": 900}, permissions=["clipboard-read", "clipboard-write"]
    )
    context.add_init_script(path=str(AXE))
    page = context.new_page()
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(f"{live_server}/detail?{AXIS}&id={urllib.parse.quote(first['id'])}")
    button = page.locator(".order button.copy-order")
    button.wait_for(state="visible")
    button.click()
    page.wait_for_function(
        "() => document.querySelector('.copy-order-status').textContent === 'Line copied.'"
    )
    copied = page.evaluate("() => navigator.clipboard.readText()")
    assert copied == first["order_line"]
    assert copied == page.inner_text(".order code.order-line")
    page.locator(".order").scroll_into_view_if_needed()
    shoot(page, artifacts / f"order-line-{width}.png")
    result = page.evaluate(
        "tags => axe.run(document, {runOnly: {type: 'tag', values: tags},"
        " resultTypes: ['violations']})",
        RULE_TAGS,
    )
    context.close()
    assert len(result["passes"]) > 20
    assert summary(result["violations"]) == []
    assert errors == []


def test_without_javascript_the_line_is_text_and_the_button_hidden(
    browser: Any, live_server: str
) -> None:
    first = _first(live_server)
    context = browser.new_context(java_script_enabled=False)
    page = context.new_page()
    page.goto(f"{live_server}/detail?{AXIS}&id={urllib.parse.quote(first['id'])}")
    assert page.inner_text(".order code.order-line") == first["order_line"]
    assert not page.locator(".order button.copy-order").is_visible()
    context.close()
