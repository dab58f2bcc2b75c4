"""Leadscrew against ball screw for one axis: the selection run once per kind (the
catalog families of that kind, within the query's own families when it names some),
and each kind's first-ranked passing screw, else its nearest rejected one.

The candidates are the select response's own (``run_selection``), so every number of
the view is the number the API's select gives for that screw and those inputs.
"""

from collections.abc import Mapping
from typing import Literal

from app.catalog import Catalog
from app.contract.outputs import CitedNoteOut, VersusOut, VersusSideOut
from app.contract.params import api_url
from app.contract.schemas import ApplicationIn, CandidateOut
from app.contract.share_link import share_query
from app.contract.units import DEFAULT_UNITS
from app.core.checks import BY_NAME
from app.report.service import run_selection

Kind = Literal["lead", "ball"]
#: The kinds, in the view's column order.
KINDS: tuple[Kind, ...] = ("lead", "ball")
#: What each kind is called in the view.
KIND_NAMES: dict[Kind, str] = {"lead": "Leadscrew", "ball": "Ball screw"}

_THOMSON = (
    "Thomson Industries (R. Lipsett), “How to correctly apply lead screws”, Design World, "
    "https://www.designworldonline.com/how-to-correctly-apply-lead-screws/"
)
_THK = (
    "THK, Ball Screw FAQ “What is preload?”, "
    "https://www.thk.com/eu/en/products/faq/ball_screw/-/0034/modal.html"
)
#: Per kind, what a maker's page says of its noise and play (none where none was found).
NOTES: dict[Kind, tuple[CitedNoteOut, ...]] = {
    "lead": (
        CitedNoteOut(
            topic="noise",
            text="A maker lists quieter operation than a ball screw among a lead screw's "
            "advantages (sliding contact, no recirculating balls).",
            source=_THOMSON,
        ),
    ),
    "ball": (
        CitedNoteOut(
            topic="backlash",
            text="A preloaded ball nut (balls slightly larger than the groove clearance) "
            "has no backlash and less axial deflection under load; a nut without preload "
            "keeps the axial play its catalog gives.",
            source=_THK,
        ),
    ),
}
#: Why the view shows no price.
PRICE_NOTE = (
    "No price band: no cited, dated list price of these screws was found, so none is shown."
)


def kind_families(catalog: Catalog, kind: Kind, asked: list[str] | None) -> list[str]:
    """The catalog's families of screws of ``kind``, within ``asked`` when given, in
    catalog order: read off each series' first screw (a series is one size of one
    family, every screw of it of one kind), not off each of the catalog's screws."""
    firsts = (series.screws[0] for series in catalog.series.values() if series.screws)
    found = dict.fromkeys(s.family_id for s in firsts if s.screw_type == kind)
    return [f for f in found if not asked or f in asked]


def _asked(inputs: ApplicationIn) -> list[str] | None:
    """The query's own families (the ``family`` input), None for every family."""
    asked: list[str] | None = getattr(inputs, "family", None)
    return asked


def kinds_offered(inputs: ApplicationIn, catalog: Catalog) -> bool:
    """The catalog offers both kinds within the query's families."""
    return all(kind_families(catalog, k, _asked(inputs)) for k in KINDS)


def _side(
    inputs: ApplicationIn, catalog: Catalog, kind: Kind, units: Mapping[str, str]
) -> VersusSideOut:
    families = kind_families(catalog, kind, _asked(inputs))
    notes = list(NOTES[kind])
    if not families:
        return VersusSideOut(
            screw_type=kind, passed=False, candidate=None, excluded_by=[], notes=notes
        )
    # the first of each list is all the view reads: the ranking does not depend on the limit
    one_kind = inputs.model_copy(update={"family": families, "limit": 1})
    selected = run_selection(one_kind, catalog, units)
    found = selected.candidates or selected.rejected
    best: CandidateOut | None = found[0] if found else None
    passed = bool(selected.candidates)
    excluded = [] if passed or best is None else _excluding(best)
    return VersusSideOut.model_construct(
        screw_type=kind, passed=passed, candidate=best, excluded_by=excluded, notes=notes
    )


def _excluding(c: CandidateOut) -> list[str]:
    """The labels of the limits a rejected candidate fails (advice does not reject)."""
    return [
        BY_NAME[f.name].label if f.name in BY_NAME else f.name
        for f in c.failed
        if f.kind == "limit"
    ]


def versus_url(query: str) -> str:
    """The versus page's link: the share link's ``query`` (``share_query``)."""
    return f"/versus?{query}"


def run_versus(
    inputs: ApplicationIn, catalog: Catalog, units: Mapping[str, str] = DEFAULT_UNITS
) -> VersusOut:
    """The best leadscrew and the best ball screw for ``inputs``, each in full."""
    return VersusOut.model_construct(
        inputs=inputs,
        sides=[_side(inputs, catalog, k, units) for k in KINDS],
        price_note=PRICE_NOTE,
        catalog_version=catalog.version,
        share_url=versus_url(share_query(inputs, units)),
        api_url=api_url("versus", inputs),
    )
