"""Robust or marginal: does a candidate still pass at either end of the range of every
catalog value it depends on?

The catalog gives assumed (and some handbook) values with a plausible range; the loader
records, for each such value, the candidate's numbers at its low and at its high end
(``ScrewSpec.assumption_ends``, derived values recomputed). Here the candidate is
re-screened with those numbers through the same check registry, one value at a time, so
a result can say which assumption it hinges on.

The variant rows of a catalog are built once, at load (``app.core.index``); a screw of
the user's own has its few built when it is judged. Either way ``robustness`` reads them.
"""

from bisect import bisect_left
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from app.core.model import Application, ScrewSpec, at_values
from app.core.screening import screen_table
from app.core.table import CandidateTable, Mask


@dataclass(frozen=True, slots=True)
class Robustness:
    """``robust``: passes, and still passes at both ends of every ranged value.
    ``hinges_on``: the catalog values (as named in the catalog files, e.g.
    ``pv_limit_mpa_m_s``) at one end of whose range it fails, in catalog order."""

    robust: bool
    hinges_on: tuple[str, ...]


#: A screw none of whose rows fails (frozen, so one serves every such screw).
ROBUST = Robustness(True, ())


@dataclass(frozen=True, slots=True)
class Variants:
    """Screws at the low and the high end of each of their ranged values, one at a time:
    rows ``start[i]:start[i + 1]`` of ``table`` are screw ``i``'s, ``names`` gives the
    ranged value of each row and ``moved`` the screw's values (``ScrewSpec`` fields) it
    moves."""

    table: CandidateTable
    names: tuple[str, ...]
    start: NDArray[np.intp]
    moved: tuple[frozenset[str], ...] = ()

    def rows(self, positions: Sequence[int]) -> NDArray[np.intp]:
        """The rows of the screws at ``positions``, in that order."""
        spans = [np.arange(self.start[p], self.start[p + 1]) for p in positions]
        return np.concatenate(spans) if spans else np.zeros(0, dtype=np.intp)


def build_variants(screws: Sequence[ScrewSpec]) -> Variants:
    """The variants of ``screws`` as one table (see ``Variants``)."""
    rows: list[ScrewSpec] = []
    names: list[str] = []
    moved: list[frozenset[str]] = []
    start = [0]
    for screw in screws:
        for name, ends in screw.assumption_ends.items():
            for changes in ends:
                if changes:
                    rows.append(at_values(screw, changes))
                    names.append(name)
                    moved.append(frozenset(changes))
        start.append(len(rows))
    starts = np.array(start, dtype=np.intp)
    return Variants(CandidateTable.build(rows), tuple(names), starts, tuple(moved))


def robustness(
    app: Application,
    variants: Variants,
    positions: Sequence[int],
    screened: Mask | None = None,
) -> list[Robustness]:
    """``Robustness`` of the (passing) screws at ``positions`` of ``variants``: their
    variant rows re-screened for ``app`` in one pass, or read from ``screened`` (whether
    each row of ``variants.table`` passes) when a caller screened them already, together
    with the candidates.

    A screw hinges on the names of its rows that fail, once each, in row order; each
    range is moved alone, the other values stay as catalogued.
    """
    if screened is None:
        rows = variants.rows(positions)
        screened = np.ones(len(variants.table), dtype=bool)  # the rows not screened: unread
        if rows.size:
            screened[rows] = screen_table(app, variants.table.take(rows)).passed
    failing = (~screened).nonzero()[0].tolist()
    found = []
    start, names = variants.start.tolist(), variants.names
    for p in positions:
        low, high = bisect_left(failing, start[p]), bisect_left(failing, start[p + 1])
        if low == high:
            found.append(ROBUST)
            continue
        hinges = tuple(dict.fromkeys(map(names.__getitem__, failing[low:high])))
        found.append(Robustness(False, hinges))
    return found
