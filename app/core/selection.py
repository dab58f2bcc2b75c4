"""Selection: screen every candidate, rank the passing ones, explain the rejected."""

from collections import Counter
from collections.abc import Mapping, Sequence

import numpy as np

from app.core.evaluate import evaluate
from app.core.model import Application, Evaluation, ScrewSpec, Selection, Summary
from app.core.screening import CandidateTable, Screening, screen

INPUT_LABELS = {
    "load_n": ("load", "N", 1.0),
    "speed_m_s": ("speed", "mm/s", 1000.0),
    "length_m": ("length", "mm", 1000.0),
}


def _rank_order(app: Application, table: CandidateTable, s: Screening) -> np.ndarray:
    """Positions of passing candidates (in ``s``) in rank order, stable.

    torque: lowest total drive torque; margin: lowest worst utilisation; life: longest
    rated life (unrated last); size: smallest outer diameter. Ties: lower torque.
    """
    pos = np.flatnonzero(s.passed)
    idx = s.index[pos]
    torque, util = s.total_torque_nm[pos], s.max_utilization[pos]
    primary = {
        "torque": torque,
        "margin": util,
        "life": -np.nan_to_num(table.life_min_m[idx]),
        "size": table.outer_diameter_m[idx],
    }[app.rank_by]
    secondary = util if app.rank_by == "torque" else torque
    return pos[np.lexsort((secondary, primary))]


def select(app: Application, candidates: CandidateTable | Sequence[ScrewSpec]) -> Selection:
    """Screen every eligible candidate and rank the passing ones by ``app.rank_by``.

    Passing candidates are ranked and cut to ``app.limit``; rejected ones are sorted
    nearest-to-passing first (lowest worst utilisation) and cut to the same limit; the
    counts cover everything screened. Only the returned candidates are fully evaluated.
    """
    table = (
        candidates if isinstance(candidates, CandidateTable) else CandidateTable.build(candidates)
    )
    s = screen(app, table)
    ranked = _rank_order(app, table, s)[: app.limit]
    failing = np.flatnonzero(~s.passed)
    nearest = failing[np.argsort(s.max_utilization[failing], kind="stable")][: app.limit]
    passing = tuple(evaluate(app, table.screws[s.index[p]]) for p in ranked)
    rejected = tuple(evaluate(app, table.screws[s.index[p]]) for p in nearest)
    by_check = Counter({name: int(mask.sum()) for name, mask in s.failed_by_check.items()})
    by_check = Counter({k: v for k, v in by_check.items() if v})
    n_passed = int(s.passed.sum())
    return Selection(
        application=app,
        candidates=passing,
        rejected=rejected,
        evaluated=len(s.index),
        passed=n_passed,
        failed_by_check=dict(by_check.most_common()),
        summary=summarize(app, len(s.index), n_passed, rejected[:1], by_check),
    )


def input_change(best: Evaluation) -> dict[str, float]:
    """Inputs that, changed together, clear every failed numeric check of ``best``.

    Each failed check offers alternatives (e.g. PV: lower load or lower speed); pick the
    input that the most failed checks share, and its tightest value. Empty when a failed
    check has no input remedy (e.g. a yes/no check).
    """
    options = [c.input_limits for c in best.failed_checks]
    if not options or any(not o for o in options):
        return {}
    change: dict[str, float] = {}
    remaining = [o for o in options if o]
    while remaining:
        key = Counter(k for o in remaining for k in o).most_common(1)[0][0]
        change[key] = min(o[key] for o in remaining if key in o)
        remaining = [o for o in remaining if key not in o]
    return change


def describe_change(app: Application, change: Mapping[str, float]) -> str:
    parts = []
    for key, value in change.items():
        label, unit, scale = INPUT_LABELS[key]
        verb = "reduce" if value < getattr(app, key) else "set"
        parts.append(f"{verb} the {label} to {value * scale:.4g} {unit}")
    return " and ".join(parts)


def summarize(
    app: Application,
    evaluated: int,
    passed: int,
    nearest: Sequence[Evaluation],
    by_check: Counter[str],
) -> Summary:
    """Say what limits the selection; when nothing passes, the nearest fix."""
    top = by_check.most_common(1)
    worst, worst_count = top[0] if top else (None, 0)
    if evaluated == 0:
        lead = "" if app.lead_m is None else f" with a {app.lead_m * 1000:g} mm lead"
        return Summary(
            None,
            0,
            None,
            {},
            f"No catalog screw{lead} matches the coating choice; try another lead or 'any'.",
        )
    if passed:
        return Summary(worst, worst_count, None, {}, f"{passed} of {evaluated} candidates pass.")
    best = nearest[0]
    change = input_change(best)
    fixes = " ".join(c.fix for c in best.failed_checks if c.fix)
    how = describe_change(app, change)
    message = (
        f"No candidate passes. '{worst}' excludes {worst_count} of {evaluated}. "
        f"Nearest: {best.screw.id}: {fixes}"
        + (f" Or change the application: {how}." if how else "")
    )
    return Summary(worst, worst_count, best.screw.id, change, message)
