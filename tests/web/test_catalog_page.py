"""The catalog's pages (app/web/catalog_page.py): /catalog lists the families and their
series, each series' values load on demand from /catalog/{series_id}, which is also a page
of its own for a reader without JavaScript."""

import re
from urllib.parse import quote

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.catalog import PROVENANCE_KINDS, Catalog

HX = {"HX-Request": "true"}


def _page(client: TestClient, path: str, **kwargs: object) -> BeautifulSoup:
    response = client.get(path, **kwargs)  # type: ignore[arg-type]
    assert response.status_code == 200, response.text[:300]
    return BeautifulSoup(response.text, "html.parser")


def test_every_series_details_has_a_valid_unique_id(
    catalog_page: BeautifulSoup, catalog: Catalog
) -> None:
    """Each series' <details> and heading carry an HTML id without whitespace, one per
    series (a ball screw's id has a space: HIWIN-GROUND R16), and the series' own id as
    data-series."""
    ids = [d["id"] for d in catalog_page.select("details.series")]
    headings = [h["id"] for h in catalog_page.select("details.series > summary > h3")]
    assert len(ids) == len(catalog.series) == len(set(ids))
    assert headings == ["h-" + i for i in ids]
    assert not [i for i in ids + headings if re.search(r"\s", i)]
    assert "HIWIN-GROUND_R16" in ids
    named = [d["data-series"] for d in catalog_page.select("details.series")]
    assert named == list(catalog.series)


@pytest.mark.parametrize(
    "series_id", ["ZBX8000", "HIWIN-GROUND R16", "Tr26-P5"], ids=["zbx", "ball", "iso"]
)
def test_each_series_link_opens_a_page_of_its_own(
    client: TestClient, catalog_page: BeautifulSoup, catalog: Catalog, series_id: str
) -> None:
    """The <details>' link, followed as a browser without JavaScript would: the series'
    name as title and heading, its family linked back, and the same body as the fragment
    the <details> loads when opened."""
    series = catalog.series[series_id]
    details = next(
        d for d in catalog_page.select("details.series") if d["data-series"] == series_id
    )
    href = details.select_one("a.series-link")["href"]
    assert href == f"/catalog/{quote(series_id)}"
    page = _page(client, href)
    assert page.title.text == f"{series.name} · Catalog · Leadscrew selector"
    assert page.select_one("h1")["data-series"] == series_id
    assert page.select_one("h1").text.startswith(series.name)
    back = page.select_one(".breadcrumb a[href^='/catalog#']")["href"]
    assert catalog_page.select_one(back.removeprefix("/catalog"))["data-family"] == series.family
    fragment = _page(client, href, headers=HX)
    assert fragment.select_one("html") is None
    assert str(page.select_one(".series-body")) == str(fragment.select_one(".series-body"))
    meta = fragment.select_one(".series-meta").text
    assert series.file in meta and f"{len(series.screws)} candidates" in meta


def test_the_catalog_page_holds_the_summary_not_every_value(
    catalog_page: BeautifulSoup, catalog: Catalog
) -> None:
    """Every series in its family's comparison table and as a closed <details> whose body
    is a link; no series' table of every value (those are on their own pages)."""
    rows = catalog_page.select("table.family-compare tbody tr")
    assert [r["data-series"] for r in rows] == list(catalog.series)
    assert not catalog_page.select("table.series-fields, details[open]")


@pytest.mark.parametrize("headers", [{}, HX], ids=["page", "fragment"])
@pytest.mark.parametrize("series_id", ["NOPE", "zbx8000", "ZBX8000 ", "x" * 300])
def test_an_unknown_series_is_a_404_page(
    client: TestClient, series_id: str, headers: dict[str, str]
) -> None:
    response = client.get(f"/catalog/{quote(series_id)}", headers=headers)
    assert response.status_code == 404
    assert response.headers["content-type"].startswith("text/html")
    page = BeautifulSoup(response.text, "html.parser")
    assert f"no series '{series_id[:100]}' in the catalog" in page.text
    assert "x" * 101 not in page.text  # a long id is cut at 100 characters


@pytest.mark.parametrize("path", ["/detail", "/report"])
def test_a_candidates_detail_links_every_value_of_its_series(
    client: TestClient, catalog: Catalog, path: str
) -> None:
    """A result's detail (and its printed report) leads to the catalog values behind it:
    the page of its series, with each value's provenance and source."""
    axis = {"load": "100", "lead": "10", "speed": "50", "length": "500"}
    for series_id in ("ZBX8000", "HIWIN-GROUND R16"):
        cid = catalog.series[series_id].screws[0].id
        headers = HX if path == "/detail" else {}
        page = _page(client, path, params={**axis, "id": cid}, headers=headers)
        href = page.select_one("p.series-values a")["href"]
        assert catalog.by_id[cid].series_id == series_id
        assert href == f"/catalog/{quote(series_id)}"
        series = _page(client, href)
        assert series.select_one("h1")["data-series"] == series_id
        assert series.select("table.series-fields tr[data-field] td.source")


def test_a_ball_screw_size_shows_its_nuts_diameters_lengths_and_ratings(
    client: TestClient, catalog: Catalog
) -> None:
    """HIWIN-GROUND R32 (HIWIN Table 6.4): the values its candidates are judged with, with
    their provenance, one value where every nut has it (the 32 mm outer diameter), else
    each nut's in the order of the leads (Cdyn 18.4 to 12.4 kN over leads 5 to 40 mm). The
    size showed its leads alone, and the overview '—' for its diameters."""
    fields = client.get("/api/v1/series/" + quote("HIWIN-GROUND R32")).json()["fields"]
    nuts = sorted(
        (s for s in catalog.by_id.values() if s.series_id == "HIWIN-GROUND R32"),
        key=lambda s: s.lead_m,
    )
    assert fields["leads"]["value"] == [s.lead_m for s in nuts] == [0.005, 0.01, 0.02, 0.032, 0.04]
    assert fields["outer_diameter"]["value"] == 0.032
    assert fields["dynamic_load"]["value"] == [s.dynamic_load_n for s in nuts]
    assert fields["dynamic_load"]["value"] == [18400, 30800, 19000, 12800, 12400]
    assert fields["static_load"]["value"] == [s.static_load_n for s in nuts]
    assert fields["nut_length"]["value"] == [s.nut_length_m for s in nuts]
    assert fields["root_diameter"]["value"] == [s.root_diameter_m for s in nuts]
    for name in ("outer_diameter", "dynamic_load", "static_load", "nut_length"):
        assert fields[name]["provenance"]["kind"] == "vendor", name
    assert fields["preload"]["provenance"]["kind"] == "assumed"
    overview = _page(client, "/catalog")
    row = next(r for r in overview.select("tr") if r.find(string=re.compile(r"^HIWIN-GROUND R32$")))
    assert "32" in row.get_text(" ") and "28.74" in row.get_text(" ")


def test_the_legend_names_every_provenance_kind(client: TestClient) -> None:
    """Every kind a catalog value may carry is explained where values are listed (the
    legend left out 'vendor', the kind of every ball screw value, 'standard' and 'user')."""
    for path in ("/catalog", "/catalog/" + quote("HIWIN-GROUND R32")):
        legend = _page(client, path).select("span.kind")
        assert {s.get_text() for s in legend} >= set(PROVENANCE_KINDS), path
