"""The table of moves in a real browser: a move edited with the keyboard updates the
result and its link, a row added with the keyboard takes the focus, a cell's error is
said beside it; screenshots at 1280 and 390 px under test-artifacts/ (``shots``)."""

import re
import urllib.parse
from pathlib import Path
from typing import Any

from tests.e2e.shots import shoot

MOVES = "300:250:2500:2500:0.2:2.5:10:opposes;-300:250:2500:2500:0.2:0.5:10:opposes"
LINK = urllib.parse.urlencode({"load": 10, "speed": 250, "length": 500, "moves": MOVES})


def _link_moves(page: Any) -> str:
    return urllib.parse.parse_qs(urllib.parse.urlsplit(page.url).query).get("moves", [""])[0]


#: every answer htmx has swapped and settled, by its request's address
RECORD_SETTLED = """() => {
  window.settledUrls = [];
  document.addEventListener("htmx:afterSettle", (event) => {
    const xhr = event.detail.xhr;
    window.settledUrls.push(xhr ? xhr.responseURL : "");
  });
}"""


def _wait_settled(page: Any, query: str) -> None:
    """Wait until the answer to the request carrying ``query`` (``name=value``, whole) is
    swapped and settled: the table and the errors are redrawn from it, so nothing of an
    earlier keystroke's answer is read, and no later swap moves the page under a test."""
    page.wait_for_function(
        "query => window.settledUrls.some(url => new URL(url).search.slice(1).split('&')"
        ".includes(query))",
        arg=query,
    )


def test_a_move_is_edited_and_a_row_added_with_the_keyboard(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str]
) -> None:
    page.goto(f"{live_server}/?{LINK}")
    page.wait_for_selector("tbody.candidate")
    assert page.locator("#moves-table tbody tr").count() == 2
    page.evaluate(RECORD_SETTLED)
    # the first move's speed retyped: the result and the address follow
    page.focus("#f-m0_speed")
    page.keyboard.press("Control+A")
    page.keyboard.type("200")
    _wait_settled(page, "m0_speed=200")
    assert "300:200:" in page.evaluate("location.search")
    assert _link_moves(page).startswith("300:200:2500")
    # Tab reaches the acceleration next, in row order
    page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.id") == "f-m0_accel"
    # a row added from the keyboard: the new row's first cell takes the focus
    page.focus("#moves-table button[name=add_move]")
    page.keyboard.press("Enter")
    _wait_settled(page, "add_move=1")
    page.wait_for_function(
        "() => document.activeElement && document.activeElement.id === 'f-m2_dist'"
    )
    assert page.locator("#moves-table tbody tr").count() == 3
    assert page.input_value("#f-m0_speed") == "200"
    # a distance alone: the move's speed is required, said at its cell
    page.keyboard.type("50")
    _wait_settled(page, "m2_dist=50")
    assert page.text_content("#e-m2_speed").strip() == "Required."
    shoot(page.locator("#moves-table"), artifacts / "move-table-1280.png")
    page.set_viewport_size({"width": 390, "height": 844})
    page.locator("#moves-table").scroll_into_view_if_needed()
    # the table scrolls in its own box: the page is no wider with it than without it
    box = page.locator("#moves-table .table-scroll").bounding_box()
    assert box is not None and box["x"] + box["width"] <= 390
    wide = page.evaluate("document.documentElement.scrollWidth")
    page.evaluate("document.querySelector('#moves-table').style.display = 'none'")
    assert page.evaluate("document.documentElement.scrollWidth") == wide
    page.evaluate("document.querySelector('#moves-table').style.display = ''")
    shoot(page, artifacts / "move-table-390.png")
    assert not [e for e in console_errors if not re.search(r"favicon", e)]
