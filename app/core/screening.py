"""Screening: every registered check over every eligible candidate, as arrays.

``select`` screens the whole catalog here in one pass, then builds full evaluations
(messages, fixes) only for the candidates it returns, reading the same arrays; a single
screw is screened as a table of one. So a check is computed by one piece of code.
"""

from dataclasses import dataclass

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


#: What picks the eligible candidates of a table: (lead [m], coating, families, nut material).
Filters = tuple[float | None, str, tuple[str, ...], str | None]


def filters(app: Application) -> Filters:
    """The values of ``app`` that ``eligible_mask`` reads."""
    return (app.lead_m, app.coating, app.families, app.nut_material)


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
