"""The short form of screened candidates: what the compact select response reads,
straight from the screening's arrays.

A brief carries each check's pass and utilisation and, for a failed one, its fix
(written when read); no messages, formulas or breakdowns. ``evaluate.evaluations`` builds
the full form from the same arrays and picks the governing check with the same rule
(``governing``), so the two forms cannot disagree.
"""

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial
from typing import Literal, NamedTuple, Protocol, TypeVar

from app.core.checks import BY_NAME
from app.core.checks.base import Measure
from app.core.formulas import critical_speed
from app.core.model import Application, ProvenanceKind, ScrewSpec
from app.core.phrase import Phrase
from app.core.quantities import Quantities
from app.core.screening import Screening
from app.core.table import Mask

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


class Judged(Protocol):
    """What picking the governing check reads of a check's result (full or brief)."""

    @property
    def name(self) -> str: ...
    @property
    def kind(self) -> Literal["limit", "advice"]: ...
    @property
    def passed(self) -> bool: ...
    @property
    def utilization(self) -> float | None: ...


J = TypeVar("J", bound=Judged)


def number(x: float | None) -> float | None:
    """None for a missing or NaN value."""
    return None if x is None or math.isnan(x) else x


def ratio(demand: float | None, capacity: float | None) -> float | None:
    """A check's utilisation demand / capacity; None when either is missing or the
    capacity is zero (a yes/no check)."""
    value, limit = number(demand), number(capacity)
    return value / limit if value is not None and limit else None


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


#: One check of one candidate, gathered from the screening arrays:
#: (applies, demand, capacity, failed).
CheckRow = tuple[bool, float | None, float | None, bool]


def check_rows(m: Measure, failed: Mask, index: list[int]) -> list[CheckRow]:
    """The screening's values of one check at ``index``, as plain Python values."""
    n = len(index)
    demand = [None] * n if m.demand is None else m.demand[index].tolist()
    capacity = [None] * n if m.capacity is None else m.capacity[index].tolist()
    return list(
        zip(m.applicable[index].tolist(), demand, capacity, failed[index].tolist(), strict=True)
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


@dataclass(frozen=True, slots=True)
class Brief:
    """One screened candidate in short: its numbers (``quantities``), checks and verdict."""

    screw: ScrewSpec
    quantities: Quantities[float]
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


def briefs(
    app: Application,
    sc: Screening,
    positions: Sequence[int],
    robustness: Sequence[tuple[bool, tuple[str, ...]]] | None = None,
) -> list[Brief]:
    """The candidates at ``positions`` of a screening in short; ``robustness`` gives
    (robust, hinges_on) per position for passing candidates."""
    index = list(positions)
    if not index:
        return []
    rows = sc.quantities.rows(index)
    efficiency = sc.table.efficiency[index].tolist()
    locking = sc.table.self_locking[index].tolist()
    passed = sc.passed[index].tolist()
    columns = {name: check_rows(m, sc.failed[name], index) for name, m in sc.measures.items()}
    out = []
    for k, i in enumerate(index):
        s, r = sc.table.screws[i], rows[k]
        checks = tuple(
            CheckBrief(
                name,
                BY_NAME[name].kind,
                not failed,
                ratio(demand, capacity),
                partial(BY_NAME[name].fix, app, s, r, sc.reach) if failed else None,
            )
            for name, column in columns.items()
            for applies, demand, capacity, failed in (column[k],)
            if applies
        )
        top = governing(app, checks)
        years = (r.life_years_min, r.life_years_max)
        out.append(
            Brief(
                screw=s,
                quantities=r,
                efficiency=efficiency[k],
                self_locking=locking[k],
                critical_speed_margin=critical_speed.speed_margin(r.allowed_rpm, r.rpm),
                life_years=None if any(math.isnan(y) for y in years) else years,
                checks=checks,
                passed=passed[k],
                governing_check=None if top is None else top.name,
                governing_limit_provenance=limit_provenance(top, s),
                robust=None if robustness is None else robustness[k][0],
                hinges_on=() if robustness is None else robustness[k][1],
            )
        )
    return out
