"""When nothing passes: changes of the application that make a screw pass with a margin,
each verified by screening again with it made, or why no screw can do it.

A rejected candidate's failed checks say which input value would clear each one
(``Check.input_limits``: the value at the limit itself). A remedy moves each input
``MARGIN`` past that value (a load divided by 1.05, a stroke speed too), so that the
applied change never lands on a limit, then screens the eligible candidates again with
the change made: it is offered only when a candidate then passes with its governing
utilisation at most ``1 / (1 + MARGIN)``. Remedies span more than one input: a single
input, the nearest candidate's inputs together, two inputs each moved part of the way
(shorter AND slower), and a stiffer mounting of the screw's ends, alone or with one input.
"""

import math
from collections.abc import Collection, Iterator, Mapping, Sequence
from dataclasses import replace
from itertools import combinations

import numpy as np

from app.core.changes import Words, input_words, within
from app.core.checks import BY_NAME, REGISTRY
from app.core.input_rules import inputs_hold
from app.core.model import FIXITY_ORDER, PASS_UTILIZATION, Application, Remedy
from app.core.phrase import Phrase
from app.core.screening import Screening, asked_for, failing_beyond, screen_table

#: How far past a limit a proposed input lands: a remedy must pass at a governing
#: utilisation of at most 1 / (1 + MARGIN).
MARGIN = 0.05
#: Checks a stiffer mounting of the screw's ends helps.
MOUNTING_CHECKS = frozenset({"critical_speed", "buckling"})
#: Shares of the way to its single-input value each of two inputs moves together.
SPLITS = (0.5, 0.75)
#: At most this many remedies are offered, and this many changes screened.
OFFERED, TRIED = 6, 24
#: Checks that judge the motor, not the screw: when one excludes every screw, another
#: motor may still drive them.
MOTOR_BOUND = frozenset(c.name for c in REGISTRY if c.judges_motor)

#: A change of the application: core input name -> SI value (or the end fixity).
Inputs = Mapping[str, float | str]
#: The end fixity, the one input a remedy changes that is a word, as a change of it is named.
MOUNTING = "mounting"


def past_limit(current: float, limit: float) -> float:
    """``limit`` moved MARGIN further from ``current``: divided by 1 + MARGIN when the
    input must fall, multiplied when it must rise.

    >>> round(past_limit(1000.0, 420.0), 3), round(past_limit(1.0, 2.0), 3)
    (400.0, 2.1)
    """
    return limit / (1.0 + MARGIN) if limit < current else limit * (1.0 + MARGIN)


def part_way(current: float, target: float, share: float) -> float:
    """``share`` of the way from ``current`` to ``target``, geometrically (a length and
    a speed act as powers, so halving the ratio halves the step in the exponent)."""
    if current <= 0.0 or target <= 0.0:
        return current + share * (target - current)
    return float(current * (target / current) ** share)


def verify(app: Application, sc: Screening, change: Inputs) -> Remedy | None:
    """Screen the candidates of ``sc`` again with ``change`` made: a remedy when one
    passes at a governing utilisation of at most 1 / (1 + MARGIN), within the rounding a
    check passes by (``PASS_UTILIZATION``): a change that lands exactly MARGIN past a
    limit gives 1 / 1.05 to the last bit, either side."""
    changed = replace(app, **dict(change))  # type: ignore[arg-type]
    if not inputs_hold(changed):
        return None
    again = screen_table(changed, sc.table, sc.index, sc.reach)
    worst = again.max_utilization[again.passed]
    bound = PASS_UTILIZATION / (1.0 + MARGIN)
    clear = worst[worst <= bound]
    if not clear.size:
        return None
    return Remedy(dict(change), int(np.count_nonzero(again.passed)), float(clear.min()))


def _now(app: Application, key: str) -> float:
    """The application's current value of input ``key`` (0 when it has none)."""
    value = getattr(app, key, None)
    return float(value) if isinstance(value, int | float) else 0.0


def stiffer(app: Application, failed: set[str]) -> tuple[str, ...]:
    """Stiffer end fixities than ``app``'s, when a check they help fails."""
    if not failed & MOUNTING_CHECKS:
        return ()
    return FIXITY_ORDER[FIXITY_ORDER.index(app.end_fixity) + 1 :]


def proposals(
    app: Application, targets: Sequence[Mapping[str, float]], failed: set[str]
) -> Iterator[Inputs]:
    """Changes to try, fewest inputs first: each input alone; each candidate's inputs
    together; a stiffer mounting alone; two inputs each part of the way; a stiffer
    mounting with one input part of the way. Numbers are ``past_limit`` already."""
    singles = sorted(
        {(k, past_limit(_now(app, k), v)) for t in targets for k, v in t.items() if _now(app, k)},
        key=lambda kv: abs(math.log(kv[1] / _now(app, kv[0]))) if kv[1] > 0 else math.inf,
    )
    yield from ({k: v} for k, v in singles)
    # each input's furthest single value: the way two inputs share part of
    single = dict(singles)
    for target in targets:
        if len(target) > 1:
            yield {k: past_limit(_now(app, k), v) for k, v in target.items()}
    mountings = stiffer(app, failed)
    yield from ({"end_fixity": f} for f in mountings)
    for share in SPLITS:
        for a, b in combinations(single, 2):
            yield {k: part_way(_now(app, k), single[k], share) for k in (a, b)}
        for fixity in mountings:
            for key, value in single.items():
                yield {"end_fixity": fixity, key: part_way(_now(app, key), value, share)}


#: How many of the screened screws that a slower move may clear are tried.
SLOWER_TRIED = 3


def slower_positions(app: Application, sc: Screening) -> list[int]:
    """The positions in ``sc`` of the few screws that fail only checks a slower move may
    clear (``Check.slower_may_clear``) and fit the motor's curve at the fastest top speeds
    below the one asked for (``motor_fitting_speed_m_s``): a slower move is a stepper's
    way to more torque, which the nearest screws may not show (a coarser lead nearest to
    passing needs more torque than the curve gives at any speed; a finer one, far from
    passing at full speed, which it turns faster, fits a slower move). Their own fixes
    then name the speed that clears all their checks. None without a motor curve, or in a
    cycle of moves, whose speeds are the moves' own."""
    if not app.motor_curve or app.moves:
        return []
    # a head screening's numbers are the whole one's: its rows are the first
    speeds = np.asarray(sc.quantities.motor.motor_fitting_speed_m_s)[: len(sc.passed)]
    fits = np.isfinite(speeds) & (speeds > 0.0) & (speeds < app.speed_m_s)
    fits &= ~failing_beyond(sc, lambda check: check.slower_may_clear)
    found = np.flatnonzero(fits)
    fastest: list[int] = found[np.argsort(-speeds[found], kind="stable")][:SLOWER_TRIED].tolist()
    return fastest


def remedies(
    app: Application,
    sc: Screening,
    targets: Sequence[Mapping[str, float]],
    failed: set[str],
    ranges: Mapping[str, tuple[float, float]],
) -> tuple[tuple[Remedy, ...], frozenset[str]]:
    """Verified remedies (at most OFFERED, each a distinct set of inputs), from the
    input values that clear the nearest candidates' failed checks (``targets``), and the
    inputs of every change screened (whether or not it let a screw pass)."""
    found: list[Remedy] = []
    seen: set[frozenset[str]] = set()
    screened: set[str] = set()
    for tried, change in enumerate(proposals(app, targets, failed)):
        if tried == TRIED or len(found) == OFFERED:
            break
        keys = frozenset(change)
        if keys in seen or not within(change, ranges):
            continue
        screened |= keys
        remedy = verify(app, sc, change)
        if remedy is not None:
            found.append(remedy)
            seen.add(keys)
    return tuple(found), frozenset(screened)


#: Said where no change was screened.
NOTHING_TRIED = (
    "no change of the inputs was tried: a check the nearest screws fail names no input that "
    "would clear it"
)


def tried_words(tried: Collection[str], words: Words | None = None) -> str:
    """What no change tried achieved, naming the inputs changed (each by ``words``, in its
    order, the end fixity as ``MOUNTING``; none: that the failing checks name no input to
    change).

    >>> tried_words({"end_fixity", "accel_m_s2"}, {"accel_m_s2": ("acceleration", "accel")})
    'no change of acceleration or mounting tried lets one pass with a 5 % margin'
    >>> tried_words(()) == NOTHING_TRIED
    True
    """
    if not tried:
        return NOTHING_TRIED
    known = words or {}
    order = [k for k in known if k in tried] + sorted(k for k in tried if k not in known)
    names = [MOUNTING if k == "end_fixity" else input_words(k, known)[0] for k in order]
    listed = names[0] if len(names) == 1 else ", ".join(names[:-1]) + " or " + names[-1]
    return f"no change of {listed} tried lets one pass with a {MARGIN * 100:.0f} % margin"


def impossible(
    app: Application,
    most_excluding: str | None,
    label: str,
    excludes_all: bool,
    nearest_fails: Sequence[str],
    kind: str,
    tried: Collection[str] = (),
    words: Words | None = None,
) -> Phrase:
    """Why no change tried lets a screw pass. When the check that excludes the most
    excludes every screw, no screw of the ``kind`` screened ("leadscrew", "ball screw" or
    "screw" for both) can do it: say so, of the screws the application asks for
    (``asked_for``: a lead, families, a nut or a coating leave others unscreened), and what
    kind of drive could; otherwise name what the nearest screws fail on (``nearest_fails``,
    check labels), whose fixes name the change that would clear them. ``tried``: the
    inputs of the changes screened (``remedies``), the only ones the sentence names, by
    ``words``."""
    said = tried_words(tried, words)
    if not excludes_all:
        fails = ", ".join(nearest_fails) or label
        return Phrase(
            f"{said[0].upper()}{said[1:]}. The nearest screws fail on {fails}: "
            "their fixes name what would clear it (such as a larger motor, a brake or "
            "another nut)."
        )
    check = BY_NAME.get(most_excluding or "")
    none = check and ((kind == "ball screw" and check.why_none_ball) or check.why_none)
    why = none or f"{label} excludes every screw"
    drive = " with this motor" if most_excluding in MOTOR_BOUND else ""
    scope, values = asked_for(app)
    if not scope:
        return Phrase(
            f"No {kind} in the catalog can do this{drive} within the accepted inputs: "
            f"{said}. {why[0].upper()}{why[1:]}."
        )
    return Phrase(
        f"No {kind} {scope} can do this{drive} within the accepted inputs: {said}. "
        f"{why[0].upper()}{why[1:]}. Only the screws asked for were screened: leave the "
        "choice open to screen the rest of the catalog.",
        values,
    )
