"""What a catalog offers (``Reach``): its largest values, the leads each size and nut is
made in (and those sizes' rows), and the families and nut materials it holds, so that a
fix never names a screw nobody makes."""

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from itertools import count
from operator import attrgetter
from types import MappingProxyType

import numpy as np
from numpy.typing import NDArray

from app.core.model import ScrewSpec

Array = NDArray[np.float64]
Mask = NDArray[np.bool_]


#: One size and nut of a series, every lead: (series id, nut material, coated,
#: anti-backlash).
SizeKey = tuple[str, str, bool, bool]
_SIZE = attrgetter("series_id", "nut_material", "coated", "anti_backlash")


def size_of(screw: ScrewSpec) -> SizeKey:
    """The size and nut ``screw`` is one lead of."""
    size: SizeKey = _SIZE(screw)
    return size


def size_rows(screws: Sequence[ScrewSpec], lead_m: Array) -> dict[SizeKey, NDArray[np.intp]]:
    """The rows of each size and nut of ``screws`` (``size_of``), shortest lead first (one
    stable sort by size, then lead); each read-only. A size's code is the row it first
    appears in, so the codes rise in the order the sizes first appear, as ``codes`` holds
    them."""
    codes: dict[SizeKey, int] = {}
    first_row = map(codes.setdefault, map(_SIZE, screws), count())
    code = np.fromiter(first_row, dtype=np.intp, count=len(screws))
    if not codes:
        return {}
    order = np.lexsort((lead_m, code))
    order.setflags(write=False)  # the groups below are views of it
    groups = np.split(order, np.flatnonzero(np.diff(code[order])) + 1)
    return dict(zip(codes, groups, strict=True))


@dataclass(frozen=True, slots=True)
class Reach:
    """What a catalog offers, so that a fix never names a screw nobody makes (unbounded
    for a screw of the user's own): the largest values, the leads each size and nut is
    made in, ascending, and the families and nut materials it holds (None: any).

    ``rows`` are the rows of each size and nut in the catalog's own table (``size_rows``),
    which its leads are read from and its index reads (``CatalogIndex.sizes``); a subset of
    the table (``take``) keeps its catalog's reach, rows included."""

    max_lead_m: float = math.inf
    max_root_diameter_m: float = math.inf
    max_design_load_n: float = math.inf
    max_length_m: float = math.inf
    anti_backlash: bool = True
    leads: Mapping[SizeKey, tuple[float, ...]] = field(default_factory=lambda: MappingProxyType({}))
    families: tuple[str, ...] | None = None
    nut_materials: tuple[str, ...] | None = None
    rows: Mapping[SizeKey, NDArray[np.intp]] = field(
        default_factory=lambda: MappingProxyType({}), compare=False, repr=False
    )

    def made_lead(self, screw: ScrewSpec, bound_m: float, larger: bool) -> float | None:
        """The lead of ``screw``'s size nearest ``bound_m`` on its far side: the smallest
        made at or above it (``larger``) or the largest at or below it [m]; the bound
        itself for a screw of no catalog size; None when the size is made in none."""
        leads = self.leads.get(size_of(screw))
        if leads is None:
            return bound_m
        if larger:
            return next((lead for lead in leads if lead >= bound_m), None)
        return next((lead for lead in reversed(leads) if lead <= bound_m), None)


def _leads(
    rows: Mapping[SizeKey, NDArray[np.intp]], lead_m: Array
) -> Mapping[SizeKey, tuple[float, ...]]:
    """The leads each size and nut is made in, ascending, from its ``rows``."""
    # each size's rows come shortest lead first: its leads once each, in that order
    return MappingProxyType(
        {size: tuple(dict.fromkeys(lead_m[at].tolist())) for size, at in rows.items()}
    )


def _held(names: Iterable[str]) -> tuple[str, ...]:
    """``names`` once each (whatever their case), in alphabetical order."""
    once = {name.casefold(): name for name in names}
    return tuple(sorted(once.values(), key=str.casefold))


def reach_of(
    screws: Sequence[ScrewSpec],
    lead: Array,
    root: Array,
    design_load: Array,
    max_length: Array,
    anti_backlash: Mask,
) -> Reach:
    """What ``screws`` offer (``Reach``), from their columns."""
    rows = MappingProxyType(size_rows(screws, lead))
    return Reach(
        max_lead_m=_largest(lead),
        max_root_diameter_m=_largest(root),
        max_design_load_n=_largest(design_load),
        max_length_m=_largest(max_length),
        anti_backlash=bool(anti_backlash.any()),
        leads=_leads(rows, lead),
        families=_held(dict.fromkeys(map(attrgetter("family_id"), screws))),
        nut_materials=_held(dict.fromkeys(map(attrgetter("nut_material"), screws))),
        rows=rows,
    )


def _largest(values: Array) -> float:
    """The largest given value (NaN: not given); unbounded when none is."""
    given = values[~np.isnan(values)]
    return float(given.max()) if given.size else math.inf
