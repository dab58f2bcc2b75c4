"""Shared fixtures: the app with the built-in catalog, and a test client; and the
property tests' settings."""

from collections.abc import Iterator

import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient
from hypothesis import settings

from app.catalog import Catalog, load_catalog
from app.main import create_app

# No time limit per example: hypothesis' default of 200 ms made a property test fail on a
# first call slowed by a busy machine (and pass when replayed) - tests assert results,
# never times.
settings.register_profile("untimed", deadline=None)
settings.load_profile("untimed")


@pytest.fixture(scope="session")
def catalog() -> Catalog:
    return load_catalog()


@pytest.fixture(scope="session")
def app() -> FastAPI:
    return create_app()


@pytest.fixture(scope="session")
def client(app: FastAPI) -> Iterator[TestClient]:
    with TestClient(app) as test_client:
        yield test_client
