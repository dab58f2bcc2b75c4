"""The one path from validated inputs to a result, shared by the API and the pages."""

from collections.abc import Container, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import Any

from app.catalog import Catalog
from app.catalog.axis_motor import CurveOrigin
from app.contract.fields import FIELDS
from app.contract.outputs import CompareOut, EvaluateOut, FormulaOut, PageSelectionOut, SelectOut
from app.contract.params import api_url
from app.contract.schemas import ApplicationIn, CandidateOut
from app.contract.screw_link import custom_query
from app.contract.screws import CatalogScrewIn, CustomScrewIn
from app.contract.share_link import encode_query, share_query
from app.contract.units import DEFAULT_UNITS
from app.core.evaluate import evaluate
from app.core.record import Candidate
from app.core.robustness import build_variants
from app.core.selection import Selection, select, with_robustness
from app.report.formulas import FORMULAS
from app.report.present import (
    candidate_view,
    counts_and_summary,
    custom_screw,
    selection_out,
    selection_summary,
)

#: The formulas table as output models, built once.
FORMULAS_OUT = {name: FormulaOut(**f) for name, f in FORMULAS.items()}
#: Each input's accepted range in SI by core name, from the field table: the summary
#: never offers a change outside it.
INPUT_RANGES = {
    f.core: (f.bounds[0] * f.si_factor, f.bounds[1] * f.si_factor)
    for f in FIELDS
    if f.bounds is not None
}
#: Each input a summary may name, by core name: its label in words and its quantity,
#: from the field table.
INPUT_WORDS = {
    f.core: (f.label.lower(), f.dimension)
    for f in FIELDS
    if f.kind == "number" and f.dimension is not None
}
#: Where the compact select response points for the formulas table.
FORMULAS_URL = "/api/v1/formulas"


class UnknownScrew(LookupError):
    """A catalog id that the catalog does not hold."""


def run_selection(
    inputs: ApplicationIn,
    catalog: Catalog,
    units: Mapping[str, str] = DEFAULT_UNITS,
    view: str = "full",
) -> SelectOut:
    """Select and rank over the catalog: the API's select response, its sentences in
    ``units`` (the API's own by default), its candidates in ``VIEWS[view]`` (every field
    by default; "csv": the CSV export's)."""
    selection, origin = _select(inputs, catalog)
    return construct_select_out(inputs, catalog, selection_out(selection, units, view), origin)


def _select(inputs: ApplicationIn, catalog: Catalog) -> tuple[Selection, CurveOrigin | None]:
    """The selection over the catalog for ``inputs``, and where its motor curve comes
    from (``ApplicationIn.to_core_traced``)."""
    app, origin, provenance = inputs.to_core_traced(catalog.motors, catalog.supports)
    return select(app, catalog.index, INPUT_RANGES, INPUT_WORDS, provenance), origin


def construct_select_out(
    inputs: ApplicationIn,
    catalog: Catalog,
    selected: dict[str, Any],
    origin: CurveOrigin | None,
) -> SelectOut:
    """The select response around ``selection_out``'s candidates, counts and summary;
    ``origin``: where the motor curve comes from (``ApplicationIn.to_core_traced``)."""
    share = share_query(inputs)
    return SelectOut.model_construct(
        inputs=inputs,
        **selected,
        catalog_version=catalog.version,
        motor_curve_origin=origin,
        share_url="/?" + share,
        api_url=api_url("select", inputs, [("detail", "full")], share),
        formulas=FORMULAS_OUT,
    )


#: How many page selections are kept: a results page's charts and rejected list (/charts,
#: /rejected) ask for the selection the page has just made, within a moment of it. Each
#: keeps the records of its nearest rejected candidates for /rejected to list, and with
#: them the screening's arrays (some 0.6 MB of the default catalog).
RECENT_PAGE_SELECTIONS = 8


@dataclass(frozen=True)
class _PageQuery:
    """A page selection's inputs, compared and hashed by their JSON, the display units
    and the catalog's identity and version (the catalog itself is kept, so its identity
    stays its own while the entry lives)."""

    key: tuple[str, tuple[tuple[str, str], ...], int, str]
    inputs: ApplicationIn = field(compare=False)
    catalog: Catalog = field(compare=False)
    units: Mapping[str, str] = field(compare=False)


@dataclass(frozen=True)
class _PageSelection:
    """A page selection as its parts read it: the page's result, the nearest rejected
    candidates' records and their list in the ``rejected`` view, written when first read
    (the page shows how many there are; /rejected, asked when the list is opened, lists
    them, and each one's fixes cost more than a table row)."""

    result: PageSelectionOut
    nearest: Sequence[Candidate] = field(repr=False)
    units: Mapping[str, str] = field(repr=False)

    @cached_property
    def rejected(self) -> list[CandidateOut]:
        return [candidate_view(c, "rejected", self.units) for c in self.nearest]


def run_page_selection(
    inputs: ApplicationIn, catalog: Catalog, units: Mapping[str, str]
) -> tuple[PageSelectionOut, list[CandidateOut]]:
    """The results page's selection (``run_page_result``) and its nearest rejected
    candidates in the ``rejected`` view (the list /rejected shows), sentences in
    ``units``. Callers read the result and never change it."""
    page = _page_selection(_page_query(inputs, catalog, units))
    return page.result, page.rejected


def run_page_result(
    inputs: ApplicationIn, catalog: Catalog, units: Mapping[str, str]
) -> tuple[PageSelectionOut, int]:
    """The results page's selection: the passing candidates as table rows (the ``row``
    view; their checks' sentences load with each row's detail) and how many nearest
    rejected candidates it lists (the list loads when opened: ``run_page_selection``),
    sentences in ``units``. The rejected are in full too only when nothing passes: then
    the charts and the advice are about them. The last few are kept
    (``RECENT_PAGE_SELECTIONS``): the page's charts, asked for as its table arrives, and
    its rejected list are drawn from the same selection without making it again.
    Callers read the result and never change it."""
    page = _page_selection(_page_query(inputs, catalog, units))
    return page.result, len(page.nearest)


def _page_query(inputs: ApplicationIn, catalog: Catalog, units: Mapping[str, str]) -> _PageQuery:
    key = (inputs.model_dump_json(), tuple(sorted(units.items())), id(catalog), catalog.version)
    return _PageQuery(key, inputs, catalog, units)


@lru_cache(maxsize=RECENT_PAGE_SELECTIONS)
def _page_selection(query: _PageQuery) -> _PageSelection:
    inputs, catalog, units = query.inputs, query.catalog, query.units
    selection, origin = _select(inputs, catalog)
    rejected = selection.rejected if not selection.passed else ()
    share = share_query(inputs)
    out = PageSelectionOut.model_construct(
        inputs=inputs,
        candidates=[candidate_view(c, "row", units) for c in selection.candidates],
        rejected=[candidate_view(c, "full", units) for c in rejected],
        **counts_and_summary(selection, units),
        catalog_version=catalog.version,
        motor_curve_origin=origin,
        share_url="/?" + share,
        api_url=api_url("select", inputs, share=share),
    )
    return _PageSelection(out, selection.rejected, units)


def run_selection_summary(inputs: ApplicationIn, catalog: Catalog) -> dict[str, Any]:
    """Select and rank over the catalog: the API's compact select response
    (``SelectSummaryOut``'s fields, as plain JSON values and output models)."""
    selection, origin = _select(inputs, catalog)
    share = share_query(inputs)
    return {
        "detail": "summary",
        "inputs": inputs.model_dump(mode="json", exclude_defaults=True),
        **selection_summary(selection),
        "catalog_version": catalog.version,
        "motor_curve_origin": origin,
        "share_url": "/?" + share,
        "api_url": api_url("select", inputs, share=share),
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
    app, origin, provenance = inputs.to_core_traced(catalog.motors, catalog.supports)
    if isinstance(screw, CatalogScrewIn):
        position = index.positions.get(screw.catalog_id)
        if position is None:
            raise UnknownScrew(screw.catalog_id)
        candidate = evaluate(app, index.row(position), index.table.reach, provenance)
        variants, (at,) = index.variants_at([position])
    else:
        spec = custom_screw(screw, catalog.materials, catalog.nut_materials)
        # a screw of the user's own: any size can be made
        candidate = evaluate(app, spec, axis=provenance)
        variants, at = build_variants([spec]), 0
    candidate = with_robustness(app, candidate, variants, at)
    share_url, url = evaluate_urls(inputs, screw, units)
    return EvaluateOut.model_construct(
        inputs=inputs,
        candidate=candidate_view(candidate, "full", units),
        catalog_version=catalog.version,
        motor_curve_origin=origin,
        formulas=FORMULAS_OUT,
        share_url=share_url,
        api_url=url,
    )


def evaluate_urls(
    inputs: ApplicationIn, screw: CatalogScrewIn | CustomScrewIn, units: Mapping[str, str]
) -> tuple[str | None, str | None]:
    """A catalog screw's report page and the API's GET of the same evaluation; a custom
    screw's page of one's own screw with its geometry and the application (the API has
    no GET of a custom geometry)."""
    if not isinstance(screw, CatalogScrewIn):
        return "/custom?" + custom_query(inputs, screw, units), None
    report = f"/report?{share_query(inputs, units)}&{encode_query([('id', screw.catalog_id)])}"
    return report, api_url("evaluate", inputs, [("catalog_id", screw.catalog_id)])


#: How many candidates a compare takes.
COMPARE_MIN, COMPARE_MAX = 2, 4


class BadIds(ValueError):
    """A compare's ids: too few, too many, or not in the catalog (the message says which)."""


def compare_ids(raw: Sequence[str], known: Container[str]) -> list[str]:
    """The ids of a compare from the query's ``ids`` values (each comma-separated or
    repeated), each once, in order; ``BadIds`` unless there are 2 to 4 catalog ids."""
    ids = list(dict.fromkeys(i.strip() for value in raw for i in value.split(",") if i.strip()))
    if len(ids) < COMPARE_MIN:
        raise BadIds(f"choose at least {COMPARE_MIN} candidates to compare ({len(ids)} given)")
    if len(ids) > COMPARE_MAX:
        raise BadIds(f"choose at most {COMPARE_MAX} candidates to compare ({len(ids)} given)")
    unknown = [i for i in ids if i not in known]
    if unknown:
        names = ", ".join(repr(i[:100]) for i in unknown)
        raise BadIds(f"no catalog screw {names}")
    return ids


def compare_url(inputs: ApplicationIn, ids: Sequence[str], units: Mapping[str, str]) -> str:
    """The compare page's link: the share link's query and the ids, comma-separated."""
    return f"/compare?{share_query(inputs, units)}&{encode_query([('ids', ','.join(ids))])}"


def run_compare(
    inputs: ApplicationIn,
    ids: Sequence[str],
    catalog: Catalog,
    units: Mapping[str, str] = DEFAULT_UNITS,
) -> CompareOut:
    """Catalog screws ``ids`` (checked by ``compare_ids``) evaluated for ``inputs``, each
    in full with its robustness and verdict, side by side."""
    evaluated = [run_evaluation(inputs, CatalogScrewIn(catalog_id=i), catalog, units) for i in ids]
    return CompareOut.model_construct(
        inputs=inputs,
        candidates=[e.candidate for e in evaluated],
        catalog_version=catalog.version,
        motor_curve_origin=evaluated[0].motor_curve_origin,
        share_url=compare_url(inputs, ids, units),
        api_url=api_url("compare", inputs, [("ids", ",".join(ids))]),
    )
