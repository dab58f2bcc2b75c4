"""Robust or marginal: does a candidate still pass at either end of the range of every
catalog value it depends on?

The catalog gives assumed (and some handbook) values with a plausible range; the loader
records, for each such value, the candidate's numbers at its low and at its high end
(``ScrewSpec.assumption_ends``, derived values recomputed). Here the candidate is
re-screened with those numbers through the same check registry, one value at a time, so
a result can say which assumption it hinges on.

The variants of a whole catalog are built into one table once (``variants_for``, at
start-up). When the eligible candidates' variants are few (a lead chosen), a selection
screens them in the same pass as the candidates (``joint_for``: one screening costs about
as much for a few rows as for a few hundred); otherwise it screens only the rows of the
candidates it returns (``judge``).
"""

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from app.core.model import Application, ScrewSpec
from app.core.screening import eligible, per_filters, screen_table
from app.core.table import CandidateTable, kept, per_table, table_of

#: The name the catalog's variant rows are kept under, with its table.
VARIANTS = "variants"


@dataclass(frozen=True, slots=True)
class Robustness:
    """``robust``: passes, and still passes at both ends of every ranged value.
    ``hinges_on``: the catalog values (as named in the catalog files, e.g.
    ``pv_limit_mpa_m_s``) at one end of whose range it fails, in catalog order."""

    robust: bool
    hinges_on: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Variants:
    """Every screw of a table at the low and the high end of each of its ranged values,
    one at a time: rows ``start[i]:start[i + 1]`` of ``table`` are screw ``i``'s, and
    ``names`` gives the ranged value of each row."""

    table: CandidateTable
    names: tuple[str, ...]
    start: NDArray[np.intp]


def passes(app: Application, screw: ScrewSpec) -> bool:
    """Whether ``screw`` passes every check that applies to ``app``."""
    return bool(screen_table(app, table_of(screw)).passed[0])


def at_values(screw: ScrewSpec, changes: Mapping[str, float]) -> ScrewSpec:
    """``screw`` with some of its numbers replaced (one end of a range)."""
    fields: dict[str, Any] = dict(changes)
    return replace(screw, **fields)


def build_variants(screws: Sequence[ScrewSpec]) -> Variants:
    """The variants of ``screws`` as one table (see ``Variants``)."""
    rows: list[ScrewSpec] = []
    names: list[str] = []
    start = [0]
    for screw in screws:
        for name, ends in screw.assumption_ends.items():
            for changes in ends:
                if changes:
                    rows.append(at_values(screw, changes))
                    names.append(name)
        start.append(len(rows))
    return Variants(CandidateTable.build(rows), tuple(names), np.array(start, dtype=np.intp))


def variants_for(table: CandidateTable) -> Variants:
    """``build_variants`` of ``table``'s screws, built once per table and kept with it:
    for a table that serves many queries (the catalog's, at start-up)."""
    return per_table(table, VARIANTS, lambda t: build_variants(t.screws))


def robustness_in(
    app: Application, table: CandidateTable, positions: Sequence[int]
) -> list[Robustness]:
    """``Robustness`` of the screws at ``positions`` of ``table``: from its kept variants
    (``variants_for``) when it has them, else from variants of those screws alone."""
    variants: Variants | None = kept(table, VARIANTS)
    if variants is not None:
        return judge(app, variants, positions)
    return robustness_of(app, [table.screws[p] for p in positions])


def verdicts(
    names: Sequence[str], spans: Sequence[range], passed: NDArray[np.bool_]
) -> list[Robustness]:
    """``Robustness`` per span of variant rows: the names of the rows that fail, once
    each, in row order (``names[r]`` and ``passed[r]`` are row ``r``'s)."""
    found = []
    for span in spans:
        hinges: list[str] = []
        for r in span:
            if not passed[r] and names[r] not in hinges:
                hinges.append(names[r])
        found.append(Robustness(not hinges, tuple(hinges)))
    return found


def judge(app: Application, variants: Variants, positions: Sequence[int]) -> list[Robustness]:
    """``Robustness`` of the (passing) screws at ``positions`` of the variants' source,
    with one screening of all their variants."""
    start = variants.start
    spans = [range(start[p], start[p + 1]) for p in positions]
    rows = np.fromiter((r for span in spans for r in span), dtype=np.intp)
    passed = np.zeros(len(variants.table), dtype=bool)
    if rows.size:
        passed[rows] = screen_table(app, variants.table.take(rows)).passed
    return verdicts(variants.names, spans, passed)


@dataclass(frozen=True, slots=True)
class Joint:
    """The eligible rows of a table (its first ``n``) followed by the variants of each,
    to screen together: the variants of eligible row ``k`` are rows
    ``n + start[k]`` to ``n + start[k + 1]``, ``names`` (from ``n`` on) their values."""

    table: CandidateTable
    n: int
    names: tuple[str, ...]
    start: NDArray[np.intp]

    def robustness(self, passed: NDArray[np.bool_], positions: Sequence[int]) -> list[Robustness]:
        """``Robustness`` of the eligible rows at ``positions``, from ``passed`` of a
        screening of the whole joint table."""
        spans = [range(self.start[k], self.start[k + 1]) for k in positions]
        return verdicts(self.names, spans, passed[self.n :])


#: A joint table stays worth screening in one pass up to about this many variant rows
#: (a screening costs about as much for a few rows as for a few hundred).
JOINT_MAX_VARIANTS = 600


def joint_for(app: Application, table: CandidateTable) -> Joint | None:
    """The ``Joint`` of the rows of ``table`` eligible for ``app``, kept per table and
    filters; None when the table has no kept variants (``variants_for``) or too many."""
    variants: Variants | None = kept(table, VARIANTS)
    if variants is None:
        return None
    return per_filters(app, table, "joint", lambda: _joint(app, table, variants))


def _joint(app: Application, table: CandidateTable, variants: Variants) -> Joint | None:
    index, rows = eligible(app, table)
    spans = [np.arange(variants.start[p], variants.start[p + 1]) for p in index.tolist()]
    picked = np.concatenate(spans) if spans else np.zeros(0, dtype=np.intp)
    if len(picked) > JOINT_MAX_VARIANTS:
        return None
    start = np.cumsum([0, *map(len, spans)]).astype(np.intp)
    names = tuple(variants.names[r] for r in picked.tolist())
    return Joint(rows.join(variants.table.take(picked)), len(index), names, start)


def robustness_of(app: Application, screws: Sequence[ScrewSpec]) -> list[Robustness]:
    """``Robustness`` of passing screws not in a prebuilt table (a screw of the user's)."""
    return judge(app, build_variants(screws), range(len(screws)))


def robustness(app: Application, screw: ScrewSpec) -> Robustness:
    """Re-screen ``screw`` at the low and the high end of each ranged value it uses.

    A candidate that fails as catalogued is not robust and hinges on nothing named here
    (it fails anyway). Each range is moved alone; the others stay at their values.
    """
    if not passes(app, screw):
        return Robustness(False, ())
    return robustness_of(app, [screw])[0]
