"""The one path from validated inputs to a result, shared by the API and the pages."""

from collections.abc import Mapping
from typing import Any

from app.catalog import Catalog
from app.construct import construct
from app.core.evaluate import evaluate
from app.core.robustness import build_variants
from app.core.selection import select, short_forms, with_robustness
from app.fields import FIELDS
from app.formulas import FORMULAS
from app.present import (
    candidate_out,
    candidate_row,
    counts_and_summary,
    custom_screw,
    rejected_out,
    selection_out,
    selection_summary,
)
from app.schemas import (
    ApplicationIn,
    CatalogScrewIn,
    CustomScrewIn,
    EvaluateOut,
    FormulaOut,
    PageSelectionOut,
    RejectedSummaryOut,
    SelectOut,
)
from app.units import DEFAULT_UNITS
from app.web.form import share_query

#: The formulas table as output models, built once.
FORMULAS_OUT = {name: FormulaOut(**f) for name, f in FORMULAS.items()}
#: Each input's accepted range (the field table's bounds) in the core's SI units: the
#: summary never proposes a value the form or the API would refuse.
INPUT_RANGES = {
    f.core: (f.bounds[0] * f.si_factor, f.bounds[1] * f.si_factor)
    for f in FIELDS
    if f.bounds is not None
}
#: Where the compact select response points for the formulas table.
FORMULAS_URL = "/api/v1/formulas"


class UnknownScrew(LookupError):
    """A catalog id that the catalog does not hold."""


def run_selection(
    inputs: ApplicationIn, catalog: Catalog, units: Mapping[str, str] = DEFAULT_UNITS
) -> SelectOut:
    """Select and rank over the catalog: the API's select response, its sentences in
    ``units`` (the API's own by default)."""
    selection = select(inputs.to_core(), catalog.index, INPUT_RANGES)
    return construct_select_out(inputs, catalog, selection_out(selection, units))


def construct_select_out(
    inputs: ApplicationIn, catalog: Catalog, selected: dict[str, Any]
) -> SelectOut:
    """The select response around ``selection_out``'s candidates, counts and summary."""
    return construct(
        SelectOut,
        inputs=inputs,
        **selected,
        catalog_version=catalog.version,
        share_url="/?" + share_query(inputs),
        formulas=FORMULAS_OUT,
    )


def run_page_selection(
    inputs: ApplicationIn, catalog: Catalog, units: Mapping[str, str]
) -> tuple[PageSelectionOut, list[RejectedSummaryOut]]:
    """The results page's selection: the passing candidates as table rows (their checks'
    sentences load with each row's detail) and the rejected ones in the compact form
    (the list; each one's detail loads when opened), sentences in ``units``. The rejected
    are in full too only when nothing passes: then the charts and the advice are about
    them."""
    selection = select(inputs.to_core(), catalog.index, INPUT_RANGES)
    app = selection.application
    rejected = selection.rejected if not selection.passed else ()
    out = construct(
        PageSelectionOut,
        inputs=inputs,
        candidates=[candidate_row(e, app.brake_torque_nm) for e in selection.candidates],
        rejected=[candidate_out(e, app.vacuum, units, app.brake_torque_nm) for e in rejected],
        **counts_and_summary(selection, units),
        catalog_version=catalog.version,
        share_url="/?" + share_query(inputs),
    )
    _, compact = short_forms(selection)
    return out, [rejected_out(b, units) for b in compact]


def run_selection_summary(inputs: ApplicationIn, catalog: Catalog) -> dict[str, Any]:
    """Select and rank over the catalog: the API's compact select response
    (``SelectSummaryOut``'s fields, as plain JSON values and output models)."""
    selection = select(inputs.to_core(), catalog.index, INPUT_RANGES)
    return {
        "detail": "summary",
        "inputs": inputs,
        **selection_summary(selection),
        "catalog_version": catalog.version,
        "share_url": "/?" + share_query(inputs),
        "formulas_url": FORMULAS_URL,
    }


def run_evaluation(
    inputs: ApplicationIn,
    screw: CatalogScrewIn | CustomScrewIn,
    catalog: Catalog,
    units: Mapping[str, str] = DEFAULT_UNITS,
) -> EvaluateOut:
    """Evaluate one catalog or custom screw and, when it passes, its robustness (from the
    catalog's variant rows; a custom screw's are built here); raise UnknownScrew for a
    bad catalog id."""
    index = catalog.index
    app = inputs.to_core()
    if isinstance(screw, CatalogScrewIn):
        position = index.positions.get(screw.catalog_id)
        if position is None:
            raise UnknownScrew(screw.catalog_id)
        ev = evaluate(app, index.row(position), index.table.reach)
        variants, (at,) = index.variants_at([position])
    else:
        spec = custom_screw(screw, catalog.materials)
        ev = evaluate(app, spec)  # a screw of the user's own: any size can be made
        variants, at = build_variants([spec]), 0
    ev = with_robustness(app, ev, variants, at)
    return construct(
        EvaluateOut,
        inputs=inputs,
        candidate=candidate_out(ev, app.vacuum, units, app.brake_torque_nm),
        catalog_version=catalog.version,
        formulas=FORMULAS_OUT,
    )
