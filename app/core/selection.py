"""Selection: evaluate every candidate, rank the passing ones, explain the rejected."""

from collections import Counter
from collections.abc import Callable, Iterable

from app.core.evaluate import evaluate
from app.core.model import Application, Evaluation, ScrewSpec, Selection, Summary

LEAD_MATCH_TOLERANCE = 0.005  # relative; 12.7 mm and 12.5 mm are different leads

INPUT_LABELS = {
    "load_n": ("load", "N", 1.0),
    "speed_m_s": ("speed", "mm/s", 1000.0),
    "length_m": ("length", "mm", 1000.0),
}


def lead_matches(lead_m: float, wanted_m: float | None) -> bool:
    """True when no lead is asked for, or the candidate's lead is that lead (0.5 %)."""
    return wanted_m is None or abs(lead_m - wanted_m) <= LEAD_MATCH_TOLERANCE * wanted_m


def coating_matches(coated: bool, choice: str) -> bool:
    """auto: both; tfe: coated only; none: uncoated only."""
    return choice == "auto" or coated == (choice == "tfe")


def eligible(app: Application, screws: Iterable[ScrewSpec]) -> list[ScrewSpec]:
    """Candidates that match the asked lead and coating choice."""
    return [
        s
        for s in screws
        if lead_matches(s.lead_m, app.lead_m) and coating_matches(s.coated, app.coating)
    ]


def _life_key(ev: Evaluation) -> float:
    """Rated life travel, low end [m]; unrated (free-wheeling) series rank last."""
    return 0.0 if ev.life is None else ev.life.travel_min_m


RANK_KEYS: dict[str, Callable[[Evaluation], tuple[float, ...]]] = {
    "torque": lambda ev: (ev.torque.total_nm, ev.max_utilization),
    "margin": lambda ev: (ev.max_utilization, ev.torque.total_nm),
    "life": lambda ev: (-_life_key(ev), ev.torque.total_nm),
    "size": lambda ev: (ev.screw.outer_diameter_m, ev.torque.total_nm),
}


def select(app: Application, screws: Iterable[ScrewSpec]) -> Selection:
    """Evaluate every eligible screw, rank passing ones by ``app.rank_by``.

    Passing candidates are ranked and cut to ``app.limit``; rejected ones are sorted
    nearest-to-passing first (lowest worst utilization) and cut to the same limit;
    counts cover everything evaluated.
    """
    evaluations = [evaluate(app, s) for s in eligible(app, screws)]
    passing = sorted((e for e in evaluations if e.passed), key=RANK_KEYS[app.rank_by])
    failing = sorted((e for e in evaluations if not e.passed), key=lambda e: e.max_utilization)
    by_check: Counter[str] = Counter(c.name for e in failing for c in e.failed_checks)
    return Selection(
        application=app,
        candidates=tuple(passing[: app.limit]),
        rejected=tuple(failing[: app.limit]),
        evaluated=len(evaluations),
        passed=len(passing),
        failed_by_check=dict(by_check.most_common()),
        summary=summarize(app, len(evaluations), passing, failing, by_check),
    )


def input_change(best: Evaluation) -> dict[str, float]:
    """Inputs that, changed together, clear every failed numeric check of ``best``.

    Each failed check offers alternatives (e.g. PV: lower load or lower speed); pick the
    input that the most failed checks share, and its tightest value.
    """
    failed = best.failed_checks
    if not failed or any(not c.input_limits for c in failed):
        return {}
    change: dict[str, float] = {}
    remaining = list(failed)
    while remaining:
        counts = Counter(k for c in remaining for k in c.input_limits)
        key = counts.most_common(1)[0][0]
        covered = [c for c in remaining if key in c.input_limits]
        change[key] = min(c.input_limits[key] for c in covered)
        remaining = [c for c in remaining if key not in c.input_limits]
    return change


def describe_change(app: Application, change: dict[str, float]) -> str:
    parts = []
    for key, value in change.items():
        label, unit, scale = INPUT_LABELS[key]
        current = getattr(app, key)
        verb = "reduce" if value < current else "set"
        parts.append(f"{verb} the {label} to {value * scale:.4g} {unit}")
    return " and ".join(parts)


def summarize(
    app: Application,
    evaluated: int,
    passing: list[Evaluation],
    failing: list[Evaluation],
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
    if passing:
        return Summary(
            worst, worst_count, None, {}, f"{len(passing)} of {evaluated} candidates pass."
        )
    best = failing[0]
    change = input_change(best)
    fixes = " ".join(c.fix for c in best.failed_checks if c.fix)
    how = describe_change(app, change)
    message = (
        f"No candidate passes. '{worst}' excludes {worst_count} of {evaluated}. "
        f"Nearest: {best.screw.id}: {fixes}"
        + (f" Or change the application: {how}." if how else "")
    )
    return Summary(worst, worst_count, best.screw.id, change, message)
