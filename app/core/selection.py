"""Selection: screen every candidate, rank the passing ones, explain the rejected."""

from collections import Counter
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from functools import partial
from operator import itemgetter

import numpy as np
from numpy.typing import NDArray

from app.core import kinds, motion
from app.core.changes import (
    Ranges,
    Words,
    accepted,
    describe_change,
    feasible_changes,
    input_change,
    input_words,
    one_input_changes,
)
from app.core.checks import BY_NAME, nut_heat
from app.core.checks.wear_life import life_band
from app.core.duty import ball_life_revolutions, ball_load_factors
from app.core.index import CatalogIndex
from app.core.model import Application, AxisProvenance, Remedy, ScrewSpec, Summary, holds
from app.core.phrase import Amount, Phrase, join, plural
from app.core.reach import Reach
from app.core.record import MOTOR_CHECKS, Candidate, records
from app.core.remedy import impossible, remedies, slower_positions
from app.core.robustness import Robustness, Variants, robustness
from app.core.screening import Screening, failing_beyond, screen_table
from app.core.table import CandidateTable

NO_MATCH = "No catalog screw with a {lead} lead matches the filters; try another lead or 'any'."
#: Nothing eligible at any lead: the other filters exclude every screw together.
NO_MATCH_ANY_LEAD = (
    "No catalog screw matches the filters together (families, nut material, "
    "anti-backlash, coating): widen one of them."
)
#: The nearest rejected candidates whose input changes the remedies start from.
REMEDY_FROM = 8


def motor_use(s: Screening) -> np.ndarray:
    """Per candidate, the largest share of the motor it uses (torque, curve, RMS, speed);
    the drive torque itself when no motor is given."""
    shares = [use for name in MOTOR_CHECKS if (use := s.utilization.get(name)) is not None]
    if not shares:
        return s.total_torque_nm
    return np.asarray(np.nanmax(np.array(shares), axis=0), dtype=np.float64)


def motor_limit(s: Screening) -> NDArray[np.intp]:
    """Per candidate, which motor check its ``motor_use`` is: a position in
    ``MOTOR_CHECKS`` (the one of the largest share), -1 where none ran."""
    shares = np.array(
        [
            np.full(len(s.passed), -np.inf) if (use := s.utilization.get(name)) is None else use
            for name in MOTOR_CHECKS
        ]
    )
    shares = np.where(np.isnan(shares), -np.inf, shares)
    top = shares.argmax(axis=0)
    return np.where(np.isfinite(shares.max(axis=0)), top, -1)


def shown_torque(s: Screening) -> np.ndarray:
    """The torque the results show for each candidate: the peak motor torque of either
    move's segments (braking included; without a stroke each at the top speed) or of
    starting from rest, rotor included: the torque the drive-torque check judges."""
    peak: np.ndarray = s.quantities.torque.peak_torque_nm
    return peak


def shown_rms(s: Screening) -> np.ndarray:
    """The RMS motor torque over the cycle; the shown torque where there is no move."""
    q = s.quantities
    return np.where(np.isnan(q.motor.motor_rms_nm), shown_torque(s), q.motor.motor_rms_nm)


def shown_life_min(app: Application, s: Screening, pos: np.ndarray) -> np.ndarray:
    """The low end of the life band the results show for the candidates at ``pos``, as
    nut travel [m] (``Life.travel_m``): the nut's wear life at the high end of its wear
    rate's range, or the seed's rated life where it is shorter; a ball nut's L10 life over
    the cycle (``duty.ball_life_revolutions`` times the lead), shown where it is finite (a
    stroke given); NaN where none is."""
    t = s.table
    share = np.array([life_band(t.screws[i])[0] for i in pos], dtype=np.float64)
    wear = s.quantities.life.wear_travel_m[pos] * share
    low = np.asarray(np.fmin(t.life_min_m[pos], wear), dtype=np.float64)
    ball = t.ball[pos]
    if ball.any():
        at = pos[ball]
        factor = ball_load_factors(app, t.nut_length_m[at])
        revolutions = ball_life_revolutions(app, t.dynamic_load_n[at], t.preload_n[at], factor)
        travel = revolutions * t.lead_m[at]
        low[ball] = np.where(np.isfinite(travel), travel, np.nan)
    return low


def _rank_order(app: Application, s: Screening) -> np.ndarray:
    """Positions of passing candidates (in ``s``) in rank order, stable.

    torque: lowest torque shown (``shown_torque``: the peak motor torque);
    rms: lowest RMS motor torque (``shown_rms``); margin: lowest worst utilisation; life:
    longest life at the low end of the band shown (``shown_life_min``: rated, wear or L10;
    neither last); size: smallest outer diameter; motor_margin: the
    smallest share of the motor used (``motor_use``). Ties: lower shown torque.
    Where the load must be held with the power off (``hold_power_off`` and a load held),
    the surest holds come first: the screws whose thread alone holds the load with the
    friction margin (``hold_thread_margin`` at least 1: no brake or detent torque to fail)
    before those that rest on one, each group in the policy's order. Candidates with a
    warning (failed advice) come after those without, whatever the policy ("reject"
    rejects them).
    """
    pos = s.passed.nonzero()[0]
    torque, util = shown_torque(s)[pos], s.max_utilization[pos]
    primary = {
        "torque": torque,
        "rms": shown_rms(s)[pos] if app.rank_by == "rms" else torque,
        "margin": util,
        "life": -np.nan_to_num(shown_life_min(app, s, pos)) if app.rank_by == "life" else torque,
        "size": s.table.outer_diameter_m[pos] if app.rank_by == "size" else torque,
        "motor_margin": motor_use(s)[pos] if app.rank_by == "motor_margin" else torque,
    }[app.rank_by]
    secondary = util if app.rank_by == "torque" else torque
    thread = s.quantities.holding.hold_thread_margin[pos]
    rests_on_a_device = (np.isfinite(thread) & ~holds(thread)).astype(np.float64)
    keys = (secondary, primary, rests_on_a_device, s.warned[pos].astype(np.float64))
    return pos[np.lexsort(keys)]


def with_robustness(
    app: Application, candidate: Candidate, variants: Variants, position: int
) -> Candidate:
    """``candidate`` with its robustness, read from the variant rows of the screw at
    ``position`` of ``variants``, when it passes (as it is otherwise: it fails anyway)."""
    if not candidate.passed:
        return candidate
    (found,) = robustness(app, variants, [position])
    return candidate.with_robustness(found)


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
    failing = (~s.passed).nonzero()[0]
    return failing[np.lexsort((s.max_utilization[failing], s.failed_limits[failing]))]


def _fixable_order(s: Screening, order: np.ndarray, skip: Sequence[int]) -> np.ndarray:
    """The positions of ``order`` (the rejected candidates, nearest first:
    ``_nearest_order``) whose every failed check can name an input that clears it
    (``Check.offers_inputs``), those at ``skip`` left out: where the nearest fail on the
    screw itself (a thread that does not self-lock), these are the screws a change of
    the application can admit (a slower move for a finer lead)."""
    stuck = failing_beyond(s, lambda check: check.offers_inputs)
    keep = ~stuck[order] & ~np.isin(order, skip)
    fixable: np.ndarray = order[keep]
    return fixable


def screen(app: Application, index: CatalogIndex) -> Screening:
    """Screen the candidates of ``index`` eligible for ``app`` (lead, coating, family, nut
    material)."""
    rows = index.eligible(app)
    return screen_table(app, rows.table, rows.index, index.table.reach)


def _screen(
    app: Application, index: CatalogIndex
) -> tuple[Screening, Callable[[Sequence[int]], list[Robustness]]]:
    """The screening of the candidates eligible for ``app``, and how to judge the
    robustness of those at given positions in it. When their variant rows are few, the
    candidates and their variants are screened in one pass (``Eligible.joint``)."""
    rows = index.eligible(app)
    joint = rows.joint
    if joint is None:
        s = screen(app, index)
        return s, lambda at: robustness(app, *index.variants_at(s.index[list(at)].tolist()))
    both = screen_table(app, joint.table, reach=index.table.reach)
    passed = both.passed[joint.n :]
    return both.head(joint.n, rows.index, rows.table), partial(
        robustness, app, joint.variants, screened=passed
    )


def select(
    app: Application,
    candidates: CatalogIndex | Sequence[ScrewSpec],
    ranges: Ranges | None = None,
    words: Words | None = None,
    axis: AxisProvenance | None = None,
) -> Selection:
    """Screen every eligible candidate and rank the passing ones by ``app.rank_by``.

    Passing candidates are ranked and cut to ``app.limit``; rejected ones are sorted
    nearest-to-passing first (lowest worst utilisation) and cut to the same limit; the
    counts cover everything screened; the summary offers input changes within ``ranges``
    only and names the inputs by ``words``; ``axis`` is the provenance of the axis's values
    the checks' capacities are (a library motor's curve; typed in where not given). The
    passing ones' robustness is screened now;
    the returned candidates' numbers and sections are read when first asked for. A
    sequence of screws is indexed here, without variant rows: those of the passing ones
    returned are built when they are judged.
    """
    index = (
        candidates
        if isinstance(candidates, CatalogIndex)
        else CatalogIndex.build(candidates, with_variants=False)
    )
    s, robust = _screen(app, index)
    ranked = _rank_order(app, s)[: app.limit].tolist()
    order = _nearest_order(s)
    nearest = order[: app.limit].tolist()
    found = robust(ranked)
    returned = records(app, s, ranked + nearest, [*found, *[None] * len(nearest)], axis)
    rejected = returned[len(ranked) :]
    skip = nearest[:REMEDY_FROM]
    fixable = [] if ranked else _fixable_order(s, order, skip)[:REMEDY_FROM].tolist()
    counts = {n: int(np.count_nonzero(m)) for n, m in s.failed_by_check.items()}
    by_check = Counter({n: count for n, count in counts.items() if count})
    n_passed = int(np.count_nonzero(s.passed))
    return Selection(
        application=app,
        candidates=returned[: len(ranked)],
        rejected=rejected,
        evaluated=len(s.index),
        passed=n_passed,
        failed_by_check=dict(by_check.most_common()),
        summary=summarize(
            app,
            index.table,
            len(s.index),
            n_passed,
            rejected,
            by_check,
            ranges or {},
            s,
            words,
            [s.table.screws[i].id for i in ranked],
            records(app, s, fixable, axis=axis) if fixable else (),
        ),
        screening=s,
        ranked=tuple(ranked),
        nearest=tuple(nearest),
        robustness=tuple(found),
    )


def _unheld(app: Application, reach: Reach) -> Phrase | None:
    """The families or the nut material asked for that the catalog (``reach``) does not
    hold, with those it holds; None when it holds every one (or none was asked for)."""
    held = reach.families
    missing = [] if held is None else [f for f in app.families if f not in held]
    if held is not None and missing:
        return Phrase(
            "The catalog has no family {asked}: its families are {held}.",
            {"asked": ", ".join(f"'{f}'" for f in missing), "held": ", ".join(held)},
        )
    nuts = reach.nut_materials
    if app.nut_material is None or nuts is None:
        return None
    if app.nut_material.casefold() in {n.casefold() for n in nuts}:
        return None
    return Phrase(
        "No catalog screw has a nut of {asked}: its nut materials are {held}.",
        {"asked": f"'{app.nut_material}'", "held": ", ".join(nuts)},
    )


def _no_match(app: Application, table: CandidateTable) -> Summary:
    """Nothing eligible: name a family or nut material the catalog does not have, else
    the nearest leads it has, below and above."""
    unheld = _unheld(app, table.reach)
    if unheld is not None:
        return Summary(None, 0, None, {}, unheld)
    if app.lead_m is None:
        return Summary(None, 0, None, {}, Phrase(NO_MATCH_ANY_LEAD))
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
    return Summary(None, 0, None, {}, Phrase(NO_MATCH + near, values))


def summarize(
    app: Application,
    table: CandidateTable,
    evaluated: int,
    passed: int,
    nearest: Sequence[Candidate],
    by_check: Counter[str],
    ranges: Ranges,
    screening: Screening | None = None,
    words: Words | None = None,
    passing_ids: Sequence[str] = (),
    fixable: Sequence[Candidate] = (),
) -> Summary:
    """Say what limits the selection; when nothing passes, the nearest fix and the
    feasible changes of the application (within ``ranges``; when the nearest screw's
    change lies outside them, the summary says so and offers none), the inputs named by
    ``words``. ``fixable``: the nearest rejected candidates besides ``nearest`` whose
    every failed check names an input that clears it (``_fixable_order``): where no
    remedy admits one of ``nearest``, the remedies and the feasible changes are theirs."""
    worst, worst_count = max(by_check.items(), key=itemgetter(1), default=(None, 0))
    if evaluated == 0:
        return _no_match(app, table)
    notes = (motion.speed_note(app), _unheld(app, table.reach))  # a family or nut it lacks
    note = [n for n in notes if n is not None]
    if passed:
        said = _passing_words(app, evaluated, passed, note, screening, passing_ids)
        return Summary(worst, worst_count, None, {}, said)
    best = nearest[0]
    # each of the nearest candidates' changes, worked out once (each may judge it again)
    near_changes = [input_change(c) for c in nearest[:REMEDY_FROM]]
    change = near_changes[0]
    label = BY_NAME[worst].label if worst in BY_NAME else str(worst)
    both = None if screening is None else kinds.neither(app, screening)
    parts = [
        *([both] if both is not None else []),
        *note,
        Phrase(
            f"No candidate passes. {label} excludes {worst_count} of {evaluated}. "
            f"Nearest: {best.screw.id}:"
        ),
    ]
    parts += [fix for c in best.failed_checks if (fix := c.fix) is not None]
    if change and not accepted(app, change, ranges):
        labels = " and ".join(input_words(k, words or {})[0] for k in change)
        parts.append(Phrase(f"No {labels} within the accepted inputs admits it."))
        change = {}
    most = (worst, label, worst_count == evaluated)
    found, why, pool, known = _verified(
        app, screening, (nearest, near_changes), fixable, most, ranges, words
    )
    offer = _offered_change(app, found, why, change, words)
    return Summary(
        worst,
        worst_count,
        best.screw.id,
        change,
        join([*parts, *offer]),
        feasible_changes(pool, ranges, known=known),
        found,
        why,
    )


def _passing_words(
    app: Application,
    evaluated: int,
    passed: int,
    note: list[Phrase],
    screening: Screening | None,
    passing_ids: Sequence[str],
) -> Phrase:
    """What the summary says when some candidates pass: that no leadscrew passes where
    only ball screws do (``kinds.no_leadscrew``), the speed and catalog ``note``, the
    count, then the life and unchecked nut heat notes."""
    message = Phrase(f"{passed} of {evaluated} candidates {plural(passed, 'passes', 'pass')}.")
    first = [] if screening is None else [kinds.no_leadscrew(screening, passing_ids)]
    sliding = screening is None or bool((screening.passed & ~screening.table.ball).any())
    later = (motion.life_note(app), nut_heat.unchecked_note(app, sliding))
    parts = [p for p in first if p is not None]
    after = [n for n in later if n is not None]
    return join([*parts, *note, message, *after])


def _verified(
    app: Application,
    sc: Screening | None,
    near: tuple[Sequence[Candidate], Sequence[Mapping[str, float]]],
    fixable: Sequence[Candidate],
    most: tuple[str | None, str, bool],
    ranges: Ranges,
    words: Words | None = None,
) -> tuple[tuple[Remedy, ...], Phrase | None, Sequence[Candidate], Sequence[Mapping[str, float]]]:
    """The remedies (``_remedies``) from the nearest candidates and their input changes
    (``near``), else, where none is verified and the nearest fail on the screw itself,
    from those of ``fixable``; with the candidates and changes the feasible changes are
    read from."""
    nearest, changes = near
    found, why = _remedies(app, sc, nearest, changes, most, ranges, words)
    if found or not fixable:
        return found, why, nearest, changes
    fixes = [input_change(c) for c in fixable]
    behind = _remedies(app, sc, fixable, fixes, most, ranges, words)[0]
    if not behind:
        return found, why, nearest, changes
    return behind, None, fixable, fixes


def _offered_change(
    app: Application,
    found: Sequence[Remedy],
    why: Phrase | None,
    change: Mapping[str, float],
    words: Words | None,
) -> list[Phrase]:
    """What the no-pass summary offers last: the first verified remedy (past its limits
    by the margin), else why there is none, else the unverified change (no screening
    given: the values at the limits)."""
    if why is not None and not found:
        return [why]
    inputs: Mapping[str, float | str] = found[0].inputs if found else change
    if not inputs:
        return []
    return [
        Phrase("Or change the application: {how}.", {"how": describe_change(app, inputs, words)})
    ]


def _remedies(
    app: Application,
    sc: Screening | None,
    nearest: Sequence[Candidate],
    changes: Sequence[Mapping[str, float]],
    most: tuple[str | None, str, bool],
    ranges: Ranges,
    words: Words | None = None,
) -> tuple[tuple[Remedy, ...], Phrase | None]:
    """The verified remedies from the nearest candidates' input changes (``changes``: the
    first ``REMEDY_FROM`` candidates' ``input_change``) and those of the screws a slower
    move may let pass (``remedy.slower_positions``), or (none found) why no screw
    of the kind screened can do it; nothing without the screening to verify against.
    ``most``: the check excluding the most screws, its label, and whether it excludes
    them all."""
    if sc is None:
        return (), None
    near = nearest[:REMEDY_FROM]
    slower = records(app, sc, positions) if (positions := slower_positions(app, sc)) else []
    tried = [*near, *slower]
    targets = [t for c in tried for t in one_input_changes(c)]
    together = [*changes, *(input_change(c) for c in slower)]
    targets += [dict(change) for change in together if len(change) > 1]
    failed = {k.name for c in tried for k in c.failed_checks}
    found, screened = remedies(app, sc, targets, failed, ranges)
    if found:
        return found, None
    worst, label, excludes_all = most
    fails = list(dict.fromkeys(k.label for c in near for k in c.failed_checks))
    kind = kinds.screened(sc)
    return found, impossible(app, worst, label, excludes_all, fails, kind, screened, words)
