"""The one path from validated inputs to a result, shared by the API and the pages."""

from typing import Any

from app.catalog import Catalog
from app.core.evaluate import evaluate
from app.core.selection import select
from app.formulas import FORMULAS
from app.page_form import share_query
from app.present import candidate_dict, custom_screw, selection_dict
from app.schemas import ApplicationIn, CatalogScrewIn, CustomScrewIn


class UnknownScrew(LookupError):
    """A catalog id that the catalog does not hold."""


def run_selection(inputs: ApplicationIn, catalog: Catalog) -> dict[str, Any]:
    """Select and rank over the catalog; the API's select response as a dict."""
    selection = select(inputs.to_core(), catalog.table)
    return {
        "inputs": inputs.model_dump(),
        **selection_dict(selection),
        "catalog_version": catalog.version,
        "share_url": "/?" + share_query(inputs),
        "formulas": FORMULAS,
    }


def run_evaluation(
    inputs: ApplicationIn, screw: CatalogScrewIn | CustomScrewIn, catalog: Catalog
) -> dict[str, Any]:
    """Evaluate one catalog or custom screw; raise UnknownScrew for a bad catalog id."""
    if isinstance(screw, CatalogScrewIn):
        spec = catalog.by_id.get(screw.catalog_id)
        if spec is None:
            raise UnknownScrew(screw.catalog_id)
    else:
        spec = custom_screw(screw, catalog.materials)
    app = inputs.to_core()
    return {
        "inputs": inputs.model_dump(),
        "candidate": candidate_dict(evaluate(app, spec), app.vacuum),
        "catalog_version": catalog.version,
        "formulas": FORMULAS,
    }
