"""Fill the form in real Chromium, submit, see results swapped and the URL pushed."""

import json
import urllib.request
from typing import Any


def test_submit_swaps_results_and_pushes_url(page: Any, live_server: str) -> None:
    query = "load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10"
    with urllib.request.urlopen(f"{live_server}/api/v1/select?{query}") as response:
        top = json.load(response)["candidates"][0]["id"]
    page.goto(live_server + "/")
    page.fill("#f-load", "100")
    page.fill("#f-lead", "10")
    page.fill("#f-speed", "50")
    page.fill("#f-length", "500")
    page.click("#selector .actions button[type=submit]")
    page.wait_for_selector("#results table.candidates tbody.candidate")
    first = page.locator("#results table.candidates tbody.candidate").first
    assert first.get_attribute("data-id") == top  # the page ranks as the API does
    page.wait_for_function("() => location.search.includes('load=100')")
    assert "speed=50" in page.url and "length=500" in page.url
    assert page.locator("h1").count() == 1  # the fragment was swapped in, not a full page
