"""The built-in catalog, loaded once per test process: for the tables test modules build
when they are collected and for the session fixture ``catalog`` (a load is about half a
second of CPU, and each xdist worker collects every module)."""

from functools import cache

from app.catalog import Catalog, load_catalog


@cache
def builtin_catalog() -> Catalog:
    return load_catalog()
