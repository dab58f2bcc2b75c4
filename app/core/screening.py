"""Screening: every registered check over every eligible candidate, as arrays.

``select`` screens the whole catalog here in one pass, then builds full evaluations
(messages, fixes) only for the candidates it returns, reading the same arrays; a single
screw is screened as a table of one. So a check is computed by one piece of code.
"""

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, TypeVar

import numpy as np
from numpy.typing import NDArray

from app.core.checks import BY_NAME, REGISTRY
from app.core.checks.base import Measure, Reach
from app.core.model import PASS_UTILIZATION, Application
from app.core.quantities import NAMES, Quantities, operating_point
from app.core.table import Array, CandidateTable, Mask


@dataclass(frozen=True, slots=True)
class Screening:
    """Per eligible candidate (``index`` into the full table): its numbers and checks.

    ``failed`` holds every check's failures, ``failed_by_check`` those of the checks that
    reject (limits, and advice when the user asks); ``warned`` marks failed advice.
    """

    index: NDArray[np.intp]
    table: CandidateTable
    quantities: Quantities[Array]
    measures: dict[str, Measure]
    #: each check's demand / capacity (None for a yes/no check)
    utilization: dict[str, Array | None]
    failed: dict[str, Mask]
    failed_by_check: dict[str, Mask]
    passed: Mask
    max_utilization: Array
    failed_limits: Array
    warned: Mask
    reach: Reach

    @property
    def total_torque_nm(self) -> Array:
        return self.quantities.total_nm

    def head(self, n: int, index: NDArray[np.intp], table: CandidateTable) -> "Screening":
        """The screening of the first ``n`` rows alone (views), as rows ``index`` of
        ``table``: for a table screened together with rows that follow them."""
        cut = slice(0, n)
        return Screening(
            index,
            table,
            Quantities(*(getattr(self.quantities, name)[cut] for name in NAMES)),
            {name: m.head(n) for name, m in self.measures.items()},
            {name: None if u is None else u[cut] for name, u in self.utilization.items()},
            {name: mask[cut] for name, mask in self.failed.items()},
            {name: mask[cut] for name, mask in self.failed_by_check.items()},
            self.passed[cut],
            self.max_utilization[cut],
            self.failed_limits[cut],
            self.warned[cut],
            self.reach,
        )


def eligible_mask(app: Application, table: CandidateTable) -> Mask:
    """Candidates with the asked lead (0.5 %), coating choice, families (none asked: all)
    and nut material (case-insensitive; None: any)."""
    mask = np.ones(len(table), dtype=bool)
    if app.families:
        mask &= np.array([s.family_id in app.families for s in table.screws], dtype=bool)
    if app.nut_material is not None:
        wanted = app.nut_material.casefold()
        mask &= np.array([s.nut_material.casefold() == wanted for s in table.screws], dtype=bool)
    if app.lead_m is not None:
        mask &= np.abs(table.lead_m - app.lead_m) <= 0.005 * app.lead_m
    if app.coating != "auto":
        mask &= table.coated == (app.coating == "tfe")
    return mask


def _failed(m: Measure, utilization: Array | None) -> Mask:
    """Where a check applies and fails: over its limit, or a yes/no failure."""
    if utilization is None:
        failed = np.zeros(len(m.applicable), dtype=bool)
    else:
        failed = utilization > PASS_UTILIZATION
    if m.flagged is not None:
        failed |= m.flagged
    return m.applicable & failed


def _worst(
    measures: dict[str, Measure], utilization: dict[str, Array | None], n_failed: Array
) -> Array:
    """Worst utilisation of the rejecting checks per candidate; a failed yes/no check ranks
    behind every numeric near-miss (1 + the number of failed checks)."""
    worst = np.zeros(len(n_failed))
    for name, u in utilization.items():
        if u is not None:
            worst = np.fmax(worst, np.where(measures[name].applicable, u, np.nan))
    return np.where((n_failed > 0) & (worst <= PASS_UTILIZATION), 1.0 + n_failed, worst)


def _rejects(app: Application, name: str) -> bool:
    """A failed limit rejects; failed advice does only when the user asks for that."""
    return BY_NAME[name].kind == "limit" or app.advice == "reject"


def screen_table(
    app: Application,
    table: CandidateTable,
    index: NDArray[np.intp] | None = None,
    reach: Reach | None = None,
) -> Screening:
    """Every check that applies to ``app`` for every candidate of ``table``; ``reach`` is
    what the whole catalog offers (unbounded for a screw of the user's own)."""
    index = np.arange(len(table)) if index is None else index
    q = operating_point(app, table)
    measures = {c.name: c.measure(app, table, q) for c in REGISTRY if c.applies(app)}
    with np.errstate(invalid="ignore", divide="ignore"):
        utilization = {name: m.utilization() for name, m in measures.items()}
    failed = {name: _failed(m, utilization[name]) for name, m in measures.items()}
    rejecting = {name: mask for name, mask in failed.items() if _rejects(app, name)}
    n_failed = np.zeros(len(table))
    for mask in rejecting.values():
        n_failed += mask
    warned = np.zeros(len(table), dtype=bool)
    for name, mask in failed.items():
        if name not in rejecting:
            warned |= mask
    worst = _worst(measures, {k: utilization[k] for k in rejecting}, n_failed)
    return Screening(
        index,
        table,
        q,
        measures,
        utilization,
        failed,
        rejecting,
        n_failed == 0,
        worst,
        n_failed,
        warned,
        reach or Reach(),
    )


#: Work kept per table, filters (``filters``) and name: (table, the work); most queries
#: repeat a lead and a family, not a load. Bounded, since the filters are the user's.
_BY_FILTERS: dict[tuple[object, ...], tuple[CandidateTable, Any]] = {}
_BY_FILTERS_MAX = 128
T = TypeVar("T")


def filters(app: Application) -> tuple[object, ...]:
    """What picks the eligible candidates of a table (``eligible_mask``)."""
    return (app.lead_m, app.coating, app.families, app.nut_material)


def per_filters(app: Application, table: CandidateTable, name: str, work: Callable[[], T]) -> T:
    """``work()``, kept per table, ``filters(app)`` and ``name`` (keyed by the table's
    ``id``, held beside it so the id stays its own)."""
    key = (id(table), name, *filters(app))
    held = _BY_FILTERS.get(key)
    if held is not None and held[0] is table:
        found: T = held[1]
        return found
    found = work()
    if len(_BY_FILTERS) >= _BY_FILTERS_MAX:
        _BY_FILTERS.clear()
    _BY_FILTERS[key] = (table, found)
    return found


def eligible(app: Application, table: CandidateTable) -> tuple[NDArray[np.intp], CandidateTable]:
    """The positions (in ``table``) of the candidates eligible for ``app``, and their
    table; kept per table and filters."""
    return per_filters(app, table, "eligible", lambda: _eligible_rows(app, table))


def _eligible_rows(
    app: Application, table: CandidateTable
) -> tuple[NDArray[np.intp], CandidateTable]:
    index = np.flatnonzero(eligible_mask(app, table))
    index.setflags(write=False)  # shared by every query with these filters
    return index, table.take(index)


def screen(app: Application, table: CandidateTable) -> Screening:
    """Screen the candidates eligible for ``app`` (lead, coating, family, nut material)."""
    index, rows = eligible(app, table)
    return screen_table(app, rows, index, table.reach)
