"""A results page's charts and rejected list (/charts, /rejected) are drawn from the
selection the page has just made (``run_page_selection`` keeps the last few), not from a
second one; other inputs, other units or another catalog make their own."""

from typing import Any

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.catalog import Catalog
from app.contract.units import DEFAULT_UNITS
from app.report import service
from app.web.pages import link_inputs

HX = {"HX-Request": "true"}


@pytest.fixture
def selections(monkeypatch: pytest.MonkeyPatch) -> list[Any]:
    """Every selection made (each call of the core's ``select``) from here on."""
    made: list[Any] = []
    select = service.select

    def counted(*args: Any, **kwargs: Any) -> Any:
        made.append(args[0])
        return select(*args, **kwargs)

    monkeypatch.setattr(service, "select", counted)
    service._page_selection.cache_clear()
    return made


def test_charts_and_rejected_reuse_the_pages_selection(
    client: TestClient, selections: list[Any]
) -> None:
    page = client.get("/?load=123&lead=10&speed=50&length=500", headers=HX)
    assert page.status_code == 200 and len(selections) == 1
    slot = BeautifulSoup(page.text, "html.parser").select_one("#charts-slot[data-src]")
    assert slot is not None
    charts = client.get(str(slot["data-src"]), headers=HX)
    rejected = client.get(str(slot["data-src"]).replace("/charts", "/rejected"), headers=HX)
    assert charts.status_code == rejected.status_code == 200
    assert "data-chart" in charts.text
    assert len(selections) == 1


def test_other_inputs_or_units_select_again(
    client: TestClient, catalog: Catalog, selections: list[Any]
) -> None:
    query = {"load": "124", "lead": "10", "speed": "50", "length": "500"}
    inputs, units = link_inputs(query, catalog)
    first, _ = service.run_page_selection(inputs, catalog, units)
    assert service.run_page_selection(inputs, catalog, units)[0] is first
    assert len(selections) == 1
    inches = {**DEFAULT_UNITS, "length_unit": "in"}
    in_inches, _ = service.run_page_selection(inputs, catalog, inches)
    assert len(selections) == 2 and in_inches is not first
    heavier, _ = link_inputs({**query, "load": "125"}, catalog)
    other, _ = service.run_page_selection(heavier, catalog, units)
    assert len(selections) == 3
    assert other.inputs.model_dump()["load_n"] == 125 != first.inputs.model_dump()["load_n"]


def test_the_rejected_list_is_written_when_it_is_asked_for(
    client: TestClient, monkeypatch: pytest.MonkeyPatch, selections: list[Any]
) -> None:
    """The page shows how many nearest rejected candidates there are; their list (each
    one's failed checks and fixes) is written when /rejected asks for it, once, from the
    page's selection, and holds as many as the page said."""
    views: list[str] = []
    view = service.candidate_view

    def counted(c: Any, name: str, *args: Any) -> Any:
        views.append(name)
        return view(c, name, *args)

    monkeypatch.setattr(service, "candidate_view", counted)
    page = client.get("/?load=126&lead=10&speed=50&length=500", headers=HX)
    assert page.status_code == 200 and "rejected" not in views
    summary = BeautifulSoup(page.text, "html.parser").select_one("details.rejected summary")
    assert summary is not None
    # "Rejected: 12 candidates (10 nearest shown)"
    shown = int(summary.text.split("(")[1].split()[0])
    rows = views.count("row")
    for _ in range(2):
        listed = client.get("/rejected?load=126&lead=10&speed=50&length=500", headers=HX)
        assert listed.status_code == 200
        found = BeautifulSoup(listed.text, "html.parser").select("li.rejected-candidate")
        assert len(found) == shown == views.count("rejected")
    assert views.count("row") == rows and len(selections) == 1
