"""Shared fixtures: the app with the built-in catalog, and a test client; and the
property tests' settings."""

from collections.abc import Iterable, Iterator
from pathlib import Path
from urllib.parse import quote

import pytest
from bs4 import BeautifulSoup
from fastapi import FastAPI
from fastapi.testclient import TestClient
from hypothesis import settings

from app import main as app_main
from app.catalog import Catalog, load_catalog
from app.main import create_app
from tests.builtin_catalog import builtin_catalog
from tests.readme_install import install_into

# No time limit per example: hypothesis' default of 200 ms made a property test fail on a
# first call slowed by a busy machine (and pass when replayed) - tests assert results,
# never times.
settings.register_profile("untimed", deadline=None)
settings.load_profile("untimed")


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """``--dist loadgroup``: the node id of a test marked ``xdist_group(name)`` ends in
    ``@name``, which tells the scheduler to keep the group on one worker.

    pytest-xdist 3.8 writes that suffix to ``item._nodeid``, which pytest 9.2 no longer
    reads (its node ids are structured): the marks were ignored and every test spread
    (pytest-dev/pytest-xdist issue 1386). This writes it where pytest 9.2 reads it, the
    same way xdist names a group; a no-op where xdist has already added it."""
    if not getattr(config.option, "loadgroup", False):  # set on xdist workers only
        return
    for item in items:
        marks = item.iter_markers("xdist_group")
        names = {
            str(mark.args[0] if mark.args else mark.kwargs.get("name", "default")) for mark in marks
        }
        suffix = "@" + "_".join(sorted(names))
        if names and not item.nodeid.endswith(suffix):
            from _pytest.nodeid import NodeId  # pytest 9.2's structured ids (older: none)

            item._id = NodeId.parse(item.nodeid + suffix)


@pytest.fixture(scope="session")
def catalog() -> Catalog:
    return builtin_catalog()


@pytest.fixture(scope="session")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """README's install step into a temporary target, made once for the tests marked
    ``ON_INSTALL`` (tests/readme_install.py), which one xdist worker runs."""
    return install_into(tmp_path_factory.mktemp("site"))


@pytest.fixture(scope="session")
def app() -> FastAPI:
    return create_app()


@pytest.fixture(scope="session")
def client(app: FastAPI) -> Iterator[TestClient]:
    with TestClient(app) as test_client:
        yield test_client


@pytest.fixture(scope="session")
def catalog_page(client: TestClient) -> BeautifulSoup:
    """The catalog page, parsed once for the tests that read it."""
    response = client.get("/catalog")
    assert response.status_code == 200
    return BeautifulSoup(response.text, "html.parser")


@pytest.fixture(scope="session")
def series_bodies(client: TestClient, catalog: Catalog) -> dict[str, BeautifulSoup]:
    """Every series' values as the catalog page's ``<details>`` loads them (the HTMX
    fragment of /catalog/{series_id}), by series id, parsed once for the tests that read
    them (1.2 MB of HTML in all: about 2 s of CPU to parse)."""
    bodies = {}
    for series_id in catalog.series:
        response = client.get(f"/catalog/{quote(series_id)}", headers={"HX-Request": "true"})
        assert response.status_code == 200, series_id
        bodies[series_id] = BeautifulSoup(response.text, "html.parser")
    return bodies


@pytest.fixture
def catalog_loaded_once(catalog: Catalog, monkeypatch: pytest.MonkeyPatch) -> None:
    """``create_app`` takes the session's built-in catalog instead of loading it again, for
    the tests of what the settings change (cache, overload), which build an app for each
    setting: loading the catalog was about nine tenths of a build (0.6 of 0.7 s of CPU).
    Extra catalog directories are loaded as the app loads them."""

    def built_in_or_loaded(extra_dirs: Iterable[Path] = ()) -> Catalog:
        dirs = list(extra_dirs)
        return load_catalog(dirs) if dirs else catalog

    monkeypatch.setattr(app_main, "load_catalog", built_in_or_loaded)
