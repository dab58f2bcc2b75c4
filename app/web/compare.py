"""The side-by-side compare of 2-4 candidates: one column per candidate, one row per
quantity, the best value of each row marked.

Every value is read from the candidates' full output models (``CandidateOut``, API
units), the same the API's compare returns; the display units convert at the edge
(``Display``).
"""

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Literal

from app.contract.figures import bound_text
from app.contract.reported import REPORTED, show, value_of
from app.contract.schemas import CandidateOut
from app.contract.units import Display
from app.core.checks import REGISTRY
from app.core.wording import percent

Better = Literal["lower", "higher"] | None


@dataclass(frozen=True, slots=True)
class Row:
    """One quantity across the candidates: its label, unit, each candidate's text, and
    which columns hold the best value (none when the row is not ranked)."""

    key: str
    label: str
    unit: str
    cells: tuple[str, ...]
    best: frozenset[int]
    better: Better


def best_columns(values: Sequence[float | None], better: Better) -> frozenset[int]:
    """The columns holding the best finite value (all of them when tied); none when the
    row is not ranked or fewer than two columns have a value.

    >>> sorted(best_columns([3.0, 1.0, 1.0], "lower")), sorted(best_columns([2.0, None], "higher"))
    ([1, 2], [])
    """
    finite = [(i, v) for i, v in enumerate(values) if v is not None and math.isfinite(v)]
    if better is None or len(finite) < 2:
        return frozenset()
    pick = min if better == "lower" else max
    top = pick(v for _, v in finite)
    if all(v == top for _, v in finite):
        return frozenset()
    return frozenset(i for i, v in finite if v == top)


def _row(
    key: str,
    label: str,
    unit: str,
    values: Sequence[float | None],
    show: Callable[[float], str],
    better: Better,
) -> Row:
    cells = tuple("—" if v is None else show(v) for v in values)
    return Row(key, label, unit, cells, best_columns(values, better), better)


def _holding(c: CandidateOut, d: Display) -> str:
    if c.self_locking_with_margin:
        return "self-locking"
    if c.holding_torque.brake_nm == 0.0:
        return "no load to hold"
    needed = d.value(c.holding_torque.brake_to_fit_nm, "torque")
    return f"brake ≥ {bound_text(needed, '.3g', 'up')} {d.label('torque')}"


def _ranked(value: object) -> float | None:
    """The number a row ranks by: a band by its low end (the safe side), text not at all."""
    if isinstance(value, list):
        return value[0] if value else None
    return value if isinstance(value, float) and not isinstance(value, bool) else None


def quantity_rows(cs: Sequence[CandidateOut], d: Display) -> list[Row]:
    """A row per compare row of the output table (``app.contract.reported``), in its
    order: each candidate's value written as the results table writes it (a band as its
    range), the best marked by the row's ``better``; a row no candidate has a value for
    is left out (the RMS torque without a move)."""
    rows = []
    for entry in REPORTED:
        if not entry.compare:
            continue
        values = [value_of(c, entry.key) for c in cs]
        if all(v is None for v in values):
            continue
        unit = entry.unit_label(d)
        if entry.cell == "holding":  # words, each with its own unit
            cells, unit = tuple(_holding(c, d) for c in cs), ""
        else:
            cells = tuple(show(entry, v, d) for v in values)
        best = best_columns([_ranked(v) for v in values], entry.better)
        rows.append(Row(entry.key, entry.label, unit, cells, best, entry.better))
    return rows


def check_rows(cs: Sequence[CandidateOut]) -> list[Row]:
    """Each check's utilization, in registry order, for the checks that apply to any of
    the candidates with a number."""
    rows = []
    for check in REGISTRY:
        values = [c.utilization.get(check.name) for c in cs]
        if any(v is not None for v in values):
            rows.append(_row(check.name, check.label, "", values, percent, "lower"))
    return rows


def compare_rows(cs: Sequence[CandidateOut], d: Display) -> list[Row]:
    """Every row of the compare view: the verdicts, the output table's compare rows,
    each check."""
    verdicts = Row("verdict", "Verdict", "", tuple(c.verdict.text for c in cs), frozenset(), None)
    return [verdicts, *quantity_rows(cs, d), *check_rows(cs)]
