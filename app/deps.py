"""Request dependencies: the catalog loaded at start-up."""

from typing import Annotated

from fastapi import Depends, Request

from app.catalog import Catalog


def get_catalog(request: Request) -> Catalog:
    catalog: Catalog = request.app.state.catalog
    return catalog


CatalogDep = Annotated[Catalog, Depends(get_catalog)]
