"""The detail panel and the report list each value a check reads with its provenance's
kind and source: a value the screw lacks says so (and what the check then does), a
preloaded ball nut's zero play says it rests on the assumed preload."""

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

AXIS = "load=100&speed=20&length=300"


@pytest.mark.parametrize("page", ["detail", "report"])
@pytest.mark.parametrize(
    ("query", "cid", "value", "kind"),
    [
        ("vacuum=true", "Tr20x4-acetal", "outgassing", "derived"),
        ("vacuum=true", "R16-10K3-FSCDIN", "outgassing", "derived"),
        ("positioning_tolerance=0.05", "R32-10K5-FSC", "backlash", "assumed"),
    ],
    ids=["iso-nut-outgassing", "ball-nut-outgassing", "preloaded-nut-play"],
)
def test_each_value_a_check_reads_shows_its_kind_and_source(
    client: TestClient, page: str, query: str, cid: str, value: str, kind: str
) -> None:
    response = client.get(f"/{page}?{AXIS}&{query}&id={cid}")
    assert response.status_code == 200, response.text
    soup = BeautifulSoup(response.text, "html.parser")
    items = soup.select("ul.sources li")
    assert items and soup.select(f'ul.sources li[data-value="{value}"]')
    for li in items:
        shown, source = li.select_one(".kind"), li.select_one(".source")
        assert shown is not None and source is not None and source.text.strip(), li
    for li in soup.select(f'ul.sources li[data-value="{value}"]'):
        shown = li.select_one(".kind")
        assert shown is not None and shown.text == kind
