"""The short form of screened candidates: what the compact select response reads,
straight from the screening's arrays.

A brief carries each check's pass and utilisation and, for a failed one, its fix
(written when read); no messages, formulas or breakdowns. ``evaluate.evaluations`` builds
the full form from the same arrays and picks the governing check with the same rule
(``governing``), so the two forms cannot disagree.
"""

import math
from collections.abc import Callable, Sequence
from functools import partial
from typing import Any, Literal, NamedTuple

import numpy as np
from numpy.typing import NDArray

from app.core.checks import BY_NAME
from app.core.checks.base import Check
from app.core.formulas import critical_speed
from app.core.model import Application, J, Judged, ProvenanceKind, ScrewSpec
from app.core.phrase import Phrase
from app.core.robustness import Robustness
from app.core.screening import Screening
from app.core.table import Array

#: Provenance kinds from the least to the most certain.
CERTAINTY: tuple[ProvenanceKind, ...] = (
    "assumed",
    "derived",
    "user",
    "vendor",
    "handbook",
    "seed",
    "standard",
)


def number(x: float | None) -> float | None:
    """None for a missing or NaN value."""
    return None if x is None or math.isnan(x) else x


def governing(app: Application, checks: Sequence[J]) -> J | None:
    """Among the checks that reject (limits; advice too when the user asks), the one with
    the highest utilisation, or the first failed yes/no check when no numeric one fails."""
    rejecting = [c for c in checks if c.kind == "limit" or app.advice == "reject"]
    utilized = [c for c in rejecting if c.utilization is not None]
    top = max(utilized, key=lambda c: c.utilization or 0.0) if utilized else None
    failed = [c for c in rejecting if not c.passed]
    if failed and (top is None or top.passed):
        return failed[0]
    return top


def limit_provenance(check: Judged | None, s: ScrewSpec) -> ProvenanceKind | None:
    """How certain the governing check's limit is: the least certain provenance of the
    catalog values its capacity rests on ("user" when the capacity is the user's input)."""
    if check is None:
        return None
    fields = BY_NAME[check.name].capacity_sources
    if not fields:
        return "user"
    kinds = [s.provenance[f].kind for f in fields if f in s.provenance]
    return min(kinds, key=CERTAINTY.index) if kinds else None


#: Positions in a screening, as an index array (NumPy picks with one four times faster
#: than with a list).
Positions = NDArray[np.intp]


def positions_array(positions: Sequence[int]) -> Positions:
    """``positions`` as an index array."""
    return np.asarray(positions, dtype=np.intp)


#: One check of one candidate, gathered from the screening arrays:
#: (applies, demand, capacity, utilisation, failed).
CheckRow = tuple[bool, float | None, float | None, float | None, bool]


def check_rows(sc: Screening, name: str, index: Positions) -> list[CheckRow]:
    """The screening's values of one check at ``index``, as plain Python values."""
    m, n = sc.measures[name], len(index)
    demand = [None] * n if m.demand is None else m.demand[index].tolist()
    capacity = [None] * n if m.capacity is None else m.capacity[index].tolist()
    return list(
        zip(
            m.applicable[index].tolist(),
            demand,
            capacity,
            _utilizations(sc.utilization[name], index),
            sc.failed[name][index].tolist(),
            strict=True,
        )
    )


class CheckBrief(NamedTuple):
    """One applicable check of one candidate: passed, utilisation, and, failed, its fix
    (``remedy`` writes it when called)."""

    name: str
    kind: Literal["limit", "advice"]
    passed: bool
    utilization: float | None
    remedy: Callable[[], Phrase | None] | None

    @property
    def fix(self) -> Phrase | None:
        return None if self.passed or self.remedy is None else self.remedy()


class Brief(NamedTuple):
    """One screened candidate in short: its speed, drive torque, checks and verdict."""

    screw: ScrewSpec
    rpm: float
    total_torque_nm: float
    efficiency: float
    self_locking: bool
    critical_speed_margin: float
    life_years: tuple[float, float] | None
    checks: tuple[CheckBrief, ...]
    passed: bool
    governing_check: str | None
    governing_limit_provenance: ProvenanceKind | None
    robust: bool | None = None
    hinges_on: tuple[str, ...] = ()


def _utilizations(values: Array | None, index: Positions) -> list[float | None]:
    """A check's utilisation (demand / capacity) at ``index``: None for a yes/no check and
    where it is not a finite number (no demand or limit, or a zero limit)."""
    if values is None:
        return [None] * len(index)
    picked = values[index]
    finite = np.isfinite(picked).tolist()
    return [v if ok else None for v, ok in zip(picked.tolist(), finite, strict=True)]


def _numbers(sc: Screening, index: Positions) -> list[tuple[float, float, float, Any]]:
    """(rpm, drive torque, critical-speed margin, rated life in years or None) per
    candidate at ``index``."""
    q = sc.quantities
    rpm, allowed = q.rpm[index].tolist(), q.allowed_rpm[index].tolist()
    margin = [critical_speed.speed_margin(a, n) for a, n in zip(allowed, rpm, strict=True)]
    low, high = q.life_years_min[index].tolist(), q.life_years_max[index].tolist()
    years = [
        None if math.isnan(a) or math.isnan(b) else (a, b) for a, b in zip(low, high, strict=True)
    ]
    return list(zip(rpm, q.total_nm[index].tolist(), margin, years, strict=True))


def _fix(check: Check, app: Application, sc: Screening, i: int) -> Phrase | None:
    """The fix of a failed check of the candidate at ``i``, from its numbers."""
    return check.fix(app, sc.table.screws[i], sc.quantities.row(i), sc.reach)


def briefs(
    app: Application,
    sc: Screening,
    positions: Sequence[int],
    robustness: Sequence[Robustness | None] | None = None,
) -> list[Brief]:
    """The candidates at ``positions`` of a screening in short; ``robustness`` gives the
    robustness per position of passing candidates (None: not judged). A
    candidate's full numbers (for its fixes) are gathered only when one of its checks
    fails."""
    index = list(positions)
    if not index:
        return []
    at = positions_array(index)
    columns = {name: check_rows(sc, name, at) for name in sc.measures}
    thread = zip(sc.table.efficiency[at].tolist(), sc.table.self_locking[at].tolist(), strict=True)
    verdicts = sc.passed[at].tolist()
    out = []
    for k, (i, numbers, (efficiency, locking)) in enumerate(
        zip(index, _numbers(sc, at), thread, strict=True)
    ):
        s = sc.table.screws[i]
        checks = tuple(
            CheckBrief(
                name,
                BY_NAME[name].kind,
                not failed,
                utilization,
                partial(_fix, BY_NAME[name], app, sc, i) if failed else None,
            )
            for name, column in columns.items()
            for applies, _, _, utilization, failed in (column[k],)
            if applies
        )
        top = governing(app, checks)
        judged = None if robustness is None else robustness[k]
        out.append(
            Brief(
                s,
                *numbers[:2],
                efficiency,
                locking,
                *numbers[2:],
                checks,
                verdicts[k],
                None if top is None else top.name,
                limit_provenance(top, s),
                None if judged is None else judged.robust,
                () if judged is None else judged.hinges_on,
            )
        )
    return out
