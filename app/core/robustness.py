"""Robust or marginal: does a candidate still pass at either end of the range of every
catalog value it depends on?

The catalog gives assumed (and some handbook) values with a plausible range; the loader
records, for each such value, the candidate's numbers at its low and at its high end
(``ScrewSpec.assumption_ends``, derived values recomputed). Here the candidate is
re-screened with those numbers through the same check registry, one value at a time, so
a result can say which assumption it hinges on.
"""

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

from app.core.model import Application, ScrewSpec
from app.core.screening import screen_table
from app.core.table import CandidateTable


@dataclass(frozen=True, slots=True)
class Robustness:
    """``robust``: passes, and still passes at both ends of every ranged value.
    ``hinges_on``: the catalog values (as named in the catalog files, e.g.
    ``pv_limit_mpa_m_s``) at one end of whose range it fails, in catalog order."""

    robust: bool
    hinges_on: tuple[str, ...]


def passes(app: Application, screw: ScrewSpec) -> bool:
    """Whether ``screw`` passes every check that applies to ``app``."""
    return bool(screen_table(app, CandidateTable.build([screw])).passed[0])


def at_values(screw: ScrewSpec, changes: Mapping[str, float]) -> ScrewSpec:
    """``screw`` with some of its numbers replaced (one end of a range)."""
    fields: dict[str, Any] = dict(changes)
    return replace(screw, **fields)


#: Variants of the screws seen so far, by ``id`` of the screw (kept alive beside them).
_VARIANTS: dict[int, tuple[ScrewSpec, tuple[tuple[str, ScrewSpec], ...]]] = {}
_VARIANTS_MAX = 100_000


def variants_of(screw: ScrewSpec) -> tuple[tuple[str, ScrewSpec], ...]:
    """``screw`` at the low and the high end of each of its ranged values, one at a
    time, with the value's name; built once per screw (catalog screws live on)."""
    held = _VARIANTS.get(id(screw))
    if held is not None and held[0] is screw:
        return held[1]
    found = tuple(
        (name, at_values(screw, changes))
        for name, ends in screw.assumption_ends.items()
        for changes in ends
        if changes
    )
    if len(_VARIANTS) >= _VARIANTS_MAX:
        _VARIANTS.clear()
    _VARIANTS[id(screw)] = (screw, found)
    return found


def robustness_of(app: Application, screws: Sequence[ScrewSpec]) -> list[Robustness]:
    """``robustness`` of many passing screws with one screening of every variant: each
    screw at the low and the high end of each of its ranged values, one at a time."""
    variants: list[ScrewSpec] = []
    owners: list[tuple[int, str]] = []
    for k, screw in enumerate(screws):
        for name, variant in variants_of(screw):
            variants.append(variant)
            owners.append((k, name))
    hinges: list[list[str]] = [[] for _ in screws]
    if variants:
        passed = screen_table(app, CandidateTable.build(variants)).passed.tolist()
        for (k, name), ok in zip(owners, passed, strict=True):
            if not ok and name not in hinges[k]:
                hinges[k].append(name)
    return [Robustness(not h, tuple(h)) for h in hinges]


def robustness(app: Application, screw: ScrewSpec) -> Robustness:
    """Re-screen ``screw`` at the low and the high end of each ranged value it uses.

    A candidate that fails as catalogued is not robust and hinges on nothing named here
    (it fails anyway). Each range is moved alone; the others stay at their values.
    """
    if not passes(app, screw):
        return Robustness(False, ())
    hinges = tuple(
        name
        for name, ends in screw.assumption_ends.items()
        if any(changes and not passes(app, at_values(screw, changes)) for changes in ends)
    )
    return Robustness(not hinges, hinges)
