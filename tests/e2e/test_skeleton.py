"""Fill the form in real Chromium, submit, see results swapped and the URL pushed."""

from typing import Any


def test_submit_swaps_results_and_pushes_url(page: Any, live_server: str) -> None:
    page.goto(live_server + "/")
    page.fill("#f-load", "100")
    page.fill("#f-lead", "10")
    page.fill("#f-speed", "50")
    page.fill("#f-length", "500")
    page.click("#selector button[type=submit]")
    page.wait_for_selector("#results table.candidates tbody tr")
    rows = page.locator("#results table.candidates tbody tr")
    assert rows.count() > 0
    assert "ZBX8000-L10" in page.inner_text("#results")
    page.wait_for_function("() => location.search.includes('load=100')")
    assert "speed=50" in page.url and "length=500" in page.url
    assert page.locator("h1").count() == 1  # the fragment was swapped in, not a full page
