"""Request dependencies: the catalog loaded at start-up."""

from typing import Annotated

from fastapi import Depends, Request

from app.catalog import Catalog


async def get_catalog(request: Request) -> Catalog:
    """The catalog of the running app (async: no thread hop for a lookup)."""
    catalog: Catalog = request.app.state.catalog
    return catalog


CatalogDep = Annotated[Catalog, Depends(get_catalog)]
