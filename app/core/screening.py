"""Screening: every registered check over every eligible candidate, as arrays.

``select`` screens the whole catalog here in one pass, then builds full evaluations
(messages, fixes) only for the candidates it returns, reading the same arrays; a single
screw is screened as a table of one. So a check is computed by one piece of code.
"""

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from app.core import motion
from app.core.checks import BY_NAME, REGISTRY
from app.core.checks.base import Check, Measure, Reach
from app.core.dry_run import as_run
from app.core.model import PASS_UTILIZATION, Application
from app.core.phrase import Amount
from app.core.quantities import Quantities, operating_point
from app.core.table import Array, CandidateTable, Mask


# Not frozen, as ``Quantities``: a frozen dataclass sets each of its fields through
# object.__setattr__ (built twice per select). Nothing assigns to one.
@dataclass(slots=True)
class Screening:
    """Per eligible candidate (``index`` into the full table): its numbers and checks.

    ``failed`` holds every check's failures, ``failed_by_check`` those of the checks that
    reject (limits, and advice when the user asks); ``warned`` marks failed advice.
    ``quantities`` and ``measures`` are read at a candidate's position: those of a head
    (``head``) are the whole screening's, its candidates' rows first.
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
        return self.quantities.torque.total_nm

    def head(self, n: int, index: NDArray[np.intp], table: CandidateTable) -> "Screening":
        """The screening of the first ``n`` rows alone, as rows ``index`` of ``table``: for
        a table screened together with rows that follow them. Its verdicts and
        utilisations are views of the first ``n`` rows; its numbers and measures, read at
        a candidate's position, are the whole screening's (a hundred arrays, not sliced)."""
        cut = slice(0, n)
        failed = {name: mask[cut] for name, mask in self.failed.items()}
        return Screening(
            index,
            table,
            self.quantities,
            self.measures,
            {name: None if u is None else u[cut] for name, u in self.utilization.items()},
            failed,
            {name: failed[name] for name in self.failed_by_check},
            self.passed[cut],
            self.max_utilization[cut],
            self.failed_limits[cut],
            self.warned[cut],
            self.reach,
        )


def failing_beyond(s: Screening, cleared: Callable[[Check], bool]) -> Mask:
    """Where each candidate of ``s`` fails a rejecting check for which ``cleared`` does
    not hold: a check no input change clears (``Check.offers_inputs``), or one a motor's
    own values cannot clear (``Check.motor_may_clear``)."""
    stuck = np.zeros(len(s.passed), dtype=bool)
    for name, failed in s.failed_by_check.items():
        if not cleared(BY_NAME[name]):
            stuck |= failed
    return stuck


#: What picks the eligible candidates of a table and their variant rows: (lead [m],
#: coating, families, nut material, lubricated, life judged).
Filters = tuple[float | None, str, tuple[str, ...], str | None, str, bool]


def filters(app: Application) -> Filters:
    """The values of ``app`` its eligible rows depend on: those ``eligible_mask`` reads,
    the nut's lubrication (the friction the rows run at, ``dry_run.as_run``: run dry, or
    holding at a friction the lubricant eases by its own factor) and whether a life is
    judged (the variant rows screened with them, ``index.Eligible``)."""
    judged = motion.life_judged(app)
    return (app.lead_m, app.coating, app.families, app.nut_material, app.lubrication, judged)


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


def asked_for(app: Application) -> tuple[str, dict[str, Amount]]:
    """The screws the application asks for (``eligible_mask``), in words after "No
    leadscrew" ("of lead {lead}, with a bronze nut", its values); "" when it asks for every
    screw of the catalog. Only those are screened."""
    parts, values = [], {}
    if app.lead_m is not None:
        parts.append("of lead {lead}")
        values["lead"] = Amount(app.lead_m, "length")
    if app.families:
        parts.append("of the families asked for")
    if app.nut_material is not None:
        parts.append(f"with a {app.nut_material} nut")
    if app.coating != "auto":
        parts.append("coated" if app.coating == "tfe" else "uncoated")
    return ", ".join(parts), values


def _judge(
    measures: list[Measure], n: int
) -> tuple[list[bool], NDArray[np.bool_], NDArray[np.float64], NDArray[np.bool_]]:
    """Every check's measure over ``n`` candidates as rows of one array each, judged
    with one comparison for all checks: whether each check is numeric, where it applies,
    its utilisation demand / capacity (NaN where the limit does not exist, and for a
    yes/no check) and where it fails (applies, and over its limit or flagged)."""
    numeric = [m.demand is not None and m.capacity is not None for m in measures]
    ratio = np.empty((len(measures), n))
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for row, m, ok in zip(ratio, measures, numeric, strict=True):
            if ok:
                np.divide(m.demand, m.capacity, out=row)
            else:
                row.fill(np.nan)
    applicable = np.array([m.applicable for m in measures]).reshape(len(measures), n)
    failed = ratio > PASS_UTILIZATION
    for over, m in zip(failed, measures, strict=True):
        if m.flagged is not None:
            over |= m.flagged
    failed &= applicable
    return numeric, applicable, ratio, failed


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
    what the whole catalog offers (unbounded for a screw of the user's own). The table is
    screened at the friction ``app`` runs each nut at (``dry_run.as_run``): the screening's
    table is that one."""
    index = np.arange(len(table)) if index is None else index
    table = as_run(app, table)
    q = operating_point(app, table)
    measures = {c.name: c.measure(app, table, q) for c in REGISTRY if c.applies(app)}
    names = list(measures)
    rejecting: list[str] = []
    others: list[str] = []
    for name in names:
        (rejecting if _rejects(app, name) else others).append(name)
    # judged with the rejecting checks first, so each group is a slice of the rows
    order = rejecting + others
    numeric, applicable, ratio, failed = _judge([measures[name] for name in order], len(table))
    row = {name: i for i, name in enumerate(order)}
    utilization = {name: ratio[row[name]] if numeric[row[name]] else None for name in names}
    k = len(rejecting)
    n_failed = np.add.reduce(failed[:k], axis=0, dtype=np.float64)
    warned = np.logical_or.reduce(failed[k:], axis=0)
    # a check that does not apply, or a yes/no check (NaN), leaves the worst as it is
    worst = np.fmax.reduce(np.where(applicable[:k], ratio[:k], np.nan), axis=0, initial=0.0)
    worst = np.where((n_failed > 0) & (worst <= PASS_UTILIZATION), 1.0 + n_failed, worst)
    return Screening(
        index,
        table,
        q,
        measures,
        utilization,
        {name: failed[row[name]] for name in names},
        {name: failed[row[name]] for name in rejecting},
        n_failed == 0,
        worst,
        n_failed,
        warned,
        reach or Reach(),
    )
