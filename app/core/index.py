"""The catalog as every query reads it, built once when the catalog loads and passed in.

``CatalogIndex`` holds the candidates as columns (``CandidateTable``), the variant rows
that robustness re-screens (every screw at both ends of each ranged value), the rows of
each size and nut by lead (the lead sweep) and each candidate's row by id. Nothing in it
changes after it is built, except one bounded cache of what a query's filters pick
(``EligibleCache``), keyed by the filter values: most queries repeat a lead and a family
and vary the load.
"""

import threading
from collections import OrderedDict
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np
from numpy.typing import NDArray

from app.core import motion
from app.core.checks.wear_life import WEAR_ONLY
from app.core.dry_run import as_run
from app.core.model import Application, ScrewSpec
from app.core.reach import SizeKey, size_of
from app.core.robustness import Variants, build_variants
from app.core.screening import Filters, eligible_mask, filters
from app.core.table import COLUMNS, CandidateTable

__all__ = ["CatalogIndex", "SizeKey", "size_of"]

#: Eligible candidates whose variant rows number at most this are screened together with
#: them (a screening costs about as much for a few rows as for a few hundred).
JOINT_MAX_VARIANTS = 600
#: Sets of filters whose eligible rows are kept (the most recently used).
ELIGIBLE_KEPT = 128


@dataclass(frozen=True, slots=True)
class Joint:
    """Eligible rows (the first ``n`` rows of ``table``) followed by all their variant
    rows; ``variants`` gives eligible row ``k``'s variants as its screw ``k`` (its table
    is rows ``n`` on of ``table``)."""

    table: CandidateTable
    n: int
    variants: Variants


@dataclass(frozen=True, slots=True)
class Eligible:
    """The candidates one set of filters admits: their rows of the catalog table
    (``index``), those rows as a table, and the ``Joint`` to screen them with their
    variants in one pass (None: their variant rows are too many, or the index has none)."""

    index: NDArray[np.intp]
    table: CandidateTable
    joint: Joint | None


class EligibleCache:
    """``Eligible`` rows by filter values, the ``size`` most recently used kept."""

    def __init__(self, size: int) -> None:
        self._size = size
        self._held: OrderedDict[Filters, Eligible] = OrderedDict()
        self._lock = threading.Lock()

    def get(self, key: Filters, build: Callable[[], Eligible]) -> Eligible:
        """The rows kept for ``key``, else ``build()``'s, kept."""
        with self._lock:
            found = self._held.get(key)
            if found is not None:
                self._held.move_to_end(key)
                return found
        found = build()
        with self._lock:
            self._held[key] = found
            if len(self._held) > self._size:
                self._held.popitem(last=False)
        return found

    def __len__(self) -> int:
        return len(self._held)


@dataclass(frozen=True, slots=True)
class CatalogIndex:
    """A catalog's candidates as the queries read them; see the module docstring.

    ``variants`` is None for an index built without them (a synthetic catalog screened
    once): then the variants of the screws judged are built when they are judged.
    """

    table: CandidateTable
    variants: Variants | None
    #: each candidate's row of ``table``, by id
    positions: Mapping[str, int]
    eligible_rows: EligibleCache = field(compare=False, repr=False)

    @classmethod
    def build(cls, screws: Sequence[ScrewSpec], with_variants: bool = True) -> "CatalogIndex":
        """The index of ``screws``: columns, variant rows (unless ``with_variants`` is
        False), rows by id and by size; every array read-only."""
        table = _read_only(CandidateTable.build(screws))
        variants = build_variants(table.screws) if with_variants else None
        if variants is not None:
            _read_only(variants.table)
        return cls(
            table=table,
            variants=variants,
            positions=MappingProxyType({s.id: i for i, s in enumerate(table.screws)}),
            eligible_rows=EligibleCache(ELIGIBLE_KEPT),
        )

    @property
    def sizes(self) -> Mapping[SizeKey, NDArray[np.intp]]:
        """The rows of each size and nut, shortest lead first: those its catalog's reach
        was read from (``Reach.rows``)."""
        return self.table.reach.rows

    def eligible(self, app: Application) -> Eligible:
        """The candidates eligible for ``app`` (``screening.eligible_mask``), kept per
        set of filters."""
        return self.eligible_rows.get(filters(app), lambda: self._eligible(app))

    def _eligible(self, app: Application) -> Eligible:
        """The eligible rows at the friction ``app`` runs each nut at (``dry_run.as_run``),
        read-only: every query with these filters reads them."""
        index = np.flatnonzero(eligible_mask(app, self.table))
        index.setflags(write=False)
        rows = _read_only(as_run(app, self.table.take(index)))
        return Eligible(index, rows, self._joint(app, index, rows))

    def _joint(
        self, app: Application, index: NDArray[np.intp], rows: CandidateTable
    ) -> Joint | None:
        """``rows`` (at ``index`` of ``table``) followed by their variant rows that can
        change a verdict for ``app`` (``_screened``), as ``app`` runs them, when the index
        has variant rows and these are at most ``JOINT_MAX_VARIANTS``."""
        if self.variants is None:
            return None
        v = self.variants
        spans = [_screened(app, v, range(v.start[p], v.start[p + 1])) for p in index.tolist()]
        counts = [len(span) for span in spans]
        if sum(counts) > JOINT_MAX_VARIANTS:
            return None
        picked = np.array([r for span in spans for r in span], dtype=np.intp)
        start = np.concatenate(([0], np.cumsum(counts))).astype(np.intp)
        names = tuple(v.names[r] for r in picked.tolist())
        moved = tuple(v.moved[r] for r in picked.tolist())
        own = Variants(_read_only(v.table.take(picked)), names, start, moved)
        return Joint(_read_only(as_run(app, rows.join(own.table))), len(index), own)

    def row(self, position: int) -> CandidateTable:
        """The candidate at ``position`` of ``table`` as a table of one."""
        return self.table.take(np.array([position], dtype=np.intp))

    def variants_at(self, positions: Sequence[int]) -> tuple[Variants, Sequence[int]]:
        """Variant rows holding those of the screws at ``positions`` of ``table``, and
        where those screws are in them: the index's own, or (without) theirs built now."""
        if self.variants is not None:
            return self.variants, positions
        screws = self.table.screws
        return build_variants([screws[p] for p in positions]), range(len(positions))


def _screened(app: Application, v: Variants, rows: range) -> list[int]:
    """The variant ``rows`` of ``v`` that can change a verdict for ``app``: all of them,
    but those that move only values the nut's wear life alone reads (``WEAR_ONLY``) where
    no life is judged (``motion.life_judged``): there they pass wherever their screw does."""
    if motion.life_judged(app):
        return list(rows)
    return [r for r in rows if not v.moved[r] <= WEAR_ONLY]


def _read_only(table: CandidateTable) -> CandidateTable:
    """``table``, its columns made read-only (shared by every query that reads it)."""
    for name in COLUMNS:
        getattr(table, name).setflags(write=False)
    return table
