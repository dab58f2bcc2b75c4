"""Selection: screen every candidate, rank the passing ones, explain the rejected."""

from collections import Counter
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from functools import partial

import numpy as np

from app.core.checks import BY_NAME
from app.core.model import Application, Change, ScrewSpec, Summary
from app.core.phrase import Amount, Phrase, Quantity, join
from app.core.record import Candidate, records
from app.core.robustness import Robustness, joint_for, robustness_in, robustness_of
from app.core.screening import Screening, eligible, screen, screen_table
from app.core.table import CandidateTable

NO_MATCH = "No catalog screw{lead} matches the filters; try another lead or 'any'."
#: Application inputs a summary may offer to change: (words, quantity).
INPUT_LABELS: dict[str, tuple[str, Quantity]] = {
    "load_n": ("load", "force"),
    "speed_m_s": ("speed", "speed"),
    "length_m": ("length", "length"),
    "accel_m_s2": ("acceleration", "accel"),
}
#: The checks that judge the motor, for ranking by its margin.
MOTOR_CHECKS = ("torque", "motor_curve", "motor_rms", "motor_speed")


def motor_use(s: Screening) -> np.ndarray:
    """Per candidate, the largest share of the motor it uses (torque, curve, RMS, speed);
    the drive torque itself when no motor is given."""
    shares = [use for name in MOTOR_CHECKS if (use := s.utilization.get(name)) is not None]
    if not shares:
        return s.total_torque_nm
    return np.asarray(np.nanmax(np.stack(shares), axis=0), dtype=np.float64)


def _rank_order(app: Application, s: Screening) -> np.ndarray:
    """Positions of passing candidates (in ``s``) in rank order, stable.

    torque: lowest total drive torque; margin: lowest worst utilisation; life: longest
    rated life (unrated last); size: smallest outer diameter; motor_margin: the smallest
    share of the motor used (``motor_use``). Ties: lower torque. With
    ``advice="rank"`` candidates with a warning come after those without.
    """
    pos = np.flatnonzero(s.passed)
    torque, util = s.total_torque_nm[pos], s.max_utilization[pos]
    primary = {
        "torque": torque,
        "margin": util,
        "life": -np.nan_to_num(s.table.life_min_m[pos]),
        "size": s.table.outer_diameter_m[pos],
        "motor_margin": motor_use(s)[pos] if app.rank_by == "motor_margin" else torque,
    }[app.rank_by]
    secondary = util if app.rank_by == "torque" else torque
    keys = [secondary, primary]
    if app.advice == "rank":
        keys.append(s.warned[pos].astype(np.float64))
    return pos[np.lexsort(tuple(keys))]


def with_robustness(app: Application, passing: Sequence[Candidate]) -> tuple[Candidate, ...]:
    """Passing candidates with their robustness to the catalog's ranged values."""
    found = robustness_of(app, [c.screw for c in passing])
    return tuple(c.with_robustness(r) for c, r in zip(passing, found, strict=True))


@dataclass(frozen=True, slots=True)
class Selection:
    """A selection's answer: the ranked passing candidates (``candidates``, cut to the
    limit, with their robustness) and the nearest rejected ones, as records that read
    their numbers when first asked; the counts and the summary; and the screening they
    come from, with the positions (in ``screening``) of the returned candidates, for
    callers that read the arrays directly."""

    application: Application
    candidates: Sequence[Candidate]
    rejected: Sequence[Candidate]
    evaluated: int
    passed: int
    failed_by_check: Mapping[str, int]
    summary: Summary
    screening: Screening
    ranked: tuple[int, ...]
    nearest: tuple[int, ...]
    robustness: tuple[Robustness, ...]


def _nearest_order(s: Screening) -> np.ndarray:
    """Positions of rejected candidates, nearest first: fewest failed limits, then the
    smallest worst utilisation (how far the worst limit is exceeded)."""
    failing = np.flatnonzero(~s.passed)
    return failing[np.lexsort((s.max_utilization[failing], s.failed_limits[failing]))]


def _screen(
    app: Application, table: CandidateTable
) -> tuple[Screening, Callable[[Sequence[int]], list[Robustness]]]:
    """The screening of the candidates eligible for ``app``, and how to judge the
    robustness of those at given positions in it: when the table keeps its variants and
    they are few, candidates and variants are screened in one pass (``joint_for``)."""
    joint = joint_for(app, table)
    if joint is None:
        s = screen(app, table)
        return s, lambda positions: robustness_in(app, table, s.index[list(positions)].tolist())
    index, rows = eligible(app, table)
    both = screen_table(app, joint.table, reach=table.reach)
    return both.head(joint.n, index, rows), partial(joint.robustness, both.passed)


def select(app: Application, candidates: CandidateTable | Sequence[ScrewSpec]) -> Selection:
    """Screen every eligible candidate and rank the passing ones by ``app.rank_by``.

    Passing candidates are ranked and cut to ``app.limit``; rejected ones are sorted
    nearest-to-passing first (lowest worst utilisation) and cut to the same limit; the
    counts cover everything screened. The passing ones' robustness is screened now; the
    returned candidates' numbers and sections are read when first asked for.
    """
    table = (
        candidates if isinstance(candidates, CandidateTable) else CandidateTable.build(candidates)
    )
    s, robust = _screen(app, table)
    ranked = _rank_order(app, s)[: app.limit].tolist()
    nearest = _nearest_order(s)[: app.limit].tolist()
    found = robust(ranked)
    returned = records(app, s, ranked + nearest, [*found, *[None] * len(nearest)])
    by_check = Counter({n: int(np.count_nonzero(m)) for n, m in s.failed_by_check.items()})
    by_check = Counter({k: v for k, v in by_check.items() if v})
    n_passed = int(np.count_nonzero(s.passed))
    return Selection(
        application=app,
        candidates=returned[: len(ranked)],
        rejected=returned[len(ranked) :],
        evaluated=len(s.index),
        passed=n_passed,
        failed_by_check=dict(by_check.most_common()),
        summary=summarize(app, table, len(s.index), n_passed, returned[len(ranked) :], by_check),
        screening=s,
        ranked=tuple(ranked),
        nearest=tuple(nearest),
        robustness=tuple(found),
    )


def input_change(best: Candidate) -> dict[str, float]:
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


def describe_change(app: Application, change: Mapping[str, float]) -> Phrase:
    """The change in words: "reduce the load to {value}" per input."""
    parts = []
    for key, value in change.items():
        label, quantity = INPUT_LABELS[key]
        verb = "reduce" if value < getattr(app, key) else "set"
        parts.append(Phrase(f"{verb} the {label} to {{v}}", {"v": Amount(value, quantity)}))
    return join(parts, " and ")


def feasible_changes(nearest: Sequence[Candidate], count: int = 5) -> tuple[Change, ...]:
    """Input changes that admit each of the nearest rejected candidates, one per distinct
    change: each clears every failed limit of the candidate it names."""
    changes: list[Change] = []
    for ev in nearest:
        change = input_change(ev)
        if change and all(c.inputs != change for c in changes):
            changes.append(Change(change, ev.screw.id))
        if len(changes) == count:
            break
    return tuple(changes)


def _no_match(app: Application, table: CandidateTable) -> Summary:
    """Nothing eligible: name the nearest leads the catalog has, below and above."""
    if app.lead_m is None:
        return Summary(None, 0, None, {}, Phrase(NO_MATCH.format(lead="")))
    leads = np.unique(table.lead_m)
    below, above = leads[leads < app.lead_m], leads[leads > app.lead_m]
    values: dict[str, Amount | str] = {"lead": Amount(app.lead_m, "length")}
    nearest = []
    if below.size:
        values["below"] = Amount(float(below.max()), "length")
        nearest.append("{below}")
    if above.size:
        values["above"] = Amount(float(above.min()), "length")
        nearest.append("{above}")
    near = (" Nearest leads: " + " and ".join(nearest) + ".") if nearest else ""
    return Summary(
        None, 0, None, {}, Phrase(NO_MATCH.format(lead=" with a {lead} lead") + near, values)
    )


def summarize(
    app: Application,
    table: CandidateTable,
    evaluated: int,
    passed: int,
    nearest: Sequence[Candidate],
    by_check: Counter[str],
) -> Summary:
    """Say what limits the selection; when nothing passes, the nearest fix and the
    feasible changes of the application."""
    top = by_check.most_common(1)
    worst, worst_count = top[0] if top else (None, 0)
    if evaluated == 0:
        return _no_match(app, table)
    if passed:
        return Summary(
            worst, worst_count, None, {}, Phrase(f"{passed} of {evaluated} candidates pass.")
        )
    best = nearest[0]
    change = input_change(best)
    label = BY_NAME[worst].label if worst in BY_NAME else str(worst)
    parts = [
        Phrase(
            f"No candidate passes. {label} excludes {worst_count} of {evaluated}. "
            f"Nearest: {best.screw.id}:"
        )
    ]
    parts += [fix for c in best.failed_checks if (fix := c.fix) is not None]
    if change:
        parts.append(
            Phrase("Or change the application: {how}.", {"how": describe_change(app, change)})
        )
    return Summary(
        worst, worst_count, best.screw.id, change, join(parts), feasible_changes(nearest)
    )
