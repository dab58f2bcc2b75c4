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

from app.contract.schemas import CandidateOut
from app.contract.units import Display
from app.core.checks import REGISTRY
from app.core.verdict import percent

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


def _life_years(c: CandidateOut) -> float | None:
    return None if c.life is None or c.life.years is None else c.life.years[0]


def _holding(c: CandidateOut, d: Display) -> str:
    if c.self_locking_with_margin:
        return "self-locking"
    if c.holding_torque.brake_nm == 0.0:
        return "no load to hold"
    return f"brake ≥ {d.text(c.holding_torque.brake_nm, 'torque', 3)} {d.label('torque')}"


def quantity_rows(cs: Sequence[CandidateOut], d: Display) -> list[Row]:
    """The candidates' key numbers: torques, efficiency, holding, critical speed, life
    (years with a duty, else the rated travel) and the governing utilisation (PV and every
    other check follow in ``check_rows``)."""
    t, torque = d.label("torque"), (lambda v: d.text(v, "torque"))
    rows = [
        _row("peak", "Peak motor torque", t, [c.torque.peak_motor_nm for c in cs], torque, "lower"),
        _row("running", "Running torque", t, [c.torque.total_nm for c in cs], torque, "lower"),
    ]
    if any(c.torque.rms_nm is not None for c in cs):
        rows.append(_row("rms", "RMS torque", t, [c.torque.rms_nm for c in cs], torque, "lower"))
    rows += [
        _row("efficiency", "Efficiency", "", [c.efficiency for c in cs], percent, "higher"),
        Row(
            "holding",
            "Holding, power off",
            "",
            tuple(_holding(c, d) for c in cs),
            best_columns([c.holding_torque.brake_nm for c in cs], "lower"),
            "lower",
        ),
        _row(
            "critical",
            "Critical speed margin",
            "×",
            [c.critical_speed.margin for c in cs],
            lambda v: f"{v:.2f}",
            "higher",
        ),
        _row("life", "Life", "years", [_life_years(c) for c in cs], lambda v: f"{v:.3g}", "higher"),
        _row(
            "travel",
            "Rated travel",
            "million cm",
            [None if c.life is None else c.life.travel_million_cm[0] for c in cs],
            lambda v: f"{v:.3g}",
            "higher",
        ),
        _row(
            "governing",
            "Governing utilisation",
            "",
            [c.verdict.utilization for c in cs],
            percent,
            "lower",
        ),
    ]
    return rows


def check_rows(cs: Sequence[CandidateOut]) -> list[Row]:
    """Each check's utilisation, in registry order, for the checks that apply to any of
    the candidates with a number."""
    rows = []
    for check in REGISTRY:
        values = [c.utilization.get(check.name) for c in cs]
        if any(v is not None for v in values):
            rows.append(_row(check.name, check.label, "", values, percent, "lower"))
    return rows


def compare_rows(cs: Sequence[CandidateOut], d: Display) -> list[Row]:
    """Every row of the compare view: the verdicts, the key numbers, each check."""
    verdicts = Row("verdict", "Verdict", "", tuple(c.verdict.text for c in cs), frozenset(), None)
    return [verdicts, *quantity_rows(cs, d), *check_rows(cs)]
