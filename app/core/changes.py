"""Input changes that would admit a rejected candidate: each failed check's bounds on the
application's inputs, combined so that one change clears them all, and the change in
words."""

import math
from collections import Counter
from collections.abc import Mapping, Sequence, Set
from dataclasses import replace
from typing import Any, cast

from app.core.batch import CheckResult
from app.core.evaluate import evaluate
from app.core.input_rules import inputs_hold, least_inputs, lowers
from app.core.model import Application, Change
from app.core.phrase import Amount, Phrase, Quantity, join
from app.core.record import Candidate

#: Each input's accepted range in SI, (low, high) by core name: a change outside it is
#: never offered (the edge passes its field table's bounds; none: any value).
Ranges = Mapping[str, tuple[float, float]]
#: Each input a summary may name, by core name: its label in the reader's words and the
#: quantity it measures. The edge passes its field table's (the labels live there); an
#: input it does not name is written as its core name, its value as a bare SI number.
Words = Mapping[str, tuple[str, Quantity]]


def input_words(key: str, words: Words) -> tuple[str, Quantity]:
    """Input ``key``'s label and quantity from ``words``; its core name and no unit when
    ``words`` does not name it.

    >>> input_words("load_n", {"load_n": ("axial load", "force")}), input_words("x_m", {})
    (('axial load', 'force'), ('x_m', 'factor'))
    """
    return words.get(key, (key, "factor"))


#: Rounds in which a change of two or more inputs is judged again with them set: one
#: input's change can move another's limit (a screw made longer for the stroke lowers the
#: critical speed the speed was cut to).
CHANGE_ROUNDS = 3


def input_change(best: Candidate) -> dict[str, float]:
    """Inputs that, changed together, clear every failed numeric check of ``best``.

    Each failed check offers alternatives (e.g. PV: lower load or lower speed); pick the
    input that the most failed checks share, and its tightest value. The change is
    judged again with it made, and a check that then fails adds or
    tightens its input (``CHANGE_ROUNDS``): each value is a bound, a most or a least, and
    a round never undoes an earlier one's (a shorter screw for the critical speed after a
    longer one for the stroke). Empty when a failed check has no input remedy (e.g. a
    yes/no check), or when the bounds on one input cannot both hold. The inputs' own
    rules bound it too (``least_inputs``: no screw shorter than its stroke). Empty too
    when a check still fails after the last round: a change admits the screw it names.
    """
    app, failed = best.app, best.failed_checks
    least = least_inputs(app)
    most: dict[str, float] = {}
    change: dict[str, float] = {}
    for _ in range(CHANGE_ROUNDS + 1):
        more = _shared_change(app, failed, keep=set(change), bounds=(least, most))
        for key, value in more.items():
            if lowers(app, key, value):
                most[key] = min(value, most.get(key, math.inf))
            else:
                least[key] = max(value, least.get(key, -math.inf))
        if any(least[k] > most[k] for k in least.keys() & most.keys()):
            return {}  # one check needs the input above where another needs it below
        change = {**change, **{k: most.get(k, least.get(k, 0.0)) for k in more}}
        if not more:
            break
        # judged again, one input too: a longer screw for the stroke turns a heavier screw
        app = replace(best.app, **cast(dict[str, Any], change))
        failed = evaluate(app, best.screw).failed_checks
        if not failed:
            break
    return {} if failed else change


Bounds = tuple[Mapping[str, float], Mapping[str, float]]


def _shared_change(
    app: Application,
    failed: Sequence[CheckResult],
    keep: Set[str] = frozenset(),
    bounds: Bounds = ({}, {}),
) -> dict[str, float]:
    """The inputs the most of ``failed`` share, each at its tightest value, until every
    check has one (``input_change``); empty when one of them offers none, or only an input
    another check moves the other way (a shorter screw for the critical speed, a longer
    one for the stroke). A limit below the input's value in ``app`` is a most, above it a
    least. A check that offers an input besides those of ``keep`` (set by an earlier
    round) changes that one; none takes an input past ``bounds`` (each input's least and
    most: an earlier round's, or the inputs' own rules)."""
    options = [c.input_limits for c in failed]
    if not options or any(not o for o in options):
        return {}
    least, most = bounds
    ways = [
        {
            (k, lowers(app, k, v)): v
            for k, v in o.items()
            if least.get(k, -math.inf) <= v <= most.get(k, math.inf)
        }
        for o in options
        if o
    ]
    if any(not o for o in ways):
        return {}
    ways = _forced([{kw: v for kw, v in o.items() if kw[0] not in keep} or o for o in ways])
    change: dict[str, float] = {}
    while ways:
        key, lower = Counter(kw for o in ways for kw in o).most_common(1)[0][0]
        picked = [o[key, lower] for o in ways if (key, lower) in o]
        change[key] = min(picked) if lower else max(picked)
        ways = [
            {kw: v for kw, v in o.items() if kw[0] != key} for o in ways if (key, lower) not in o
        ]
        if any(not o for o in ways):
            return {}
    return change


Ways = list[dict[tuple[str, bool], float]]


def _forced(ways: Ways) -> Ways:
    """``ways`` (each failed check's inputs, by name and whether the check lowers it)
    without an input's direction that a check offering only the other forbids: where the
    stroke asks only for a longer screw, the critical speed's shorter one is no way out
    (its lower speed is).

    >>> _forced([{("x", True): 1.0, ("v", True): 2.0}, {("x", False): 3.0}])
    [{('v', True): 2.0}, {('x', False): 3.0}]
    """
    while True:
        forced = {next(iter(o)) for o in ways if len(o) == 1}
        banned = {(key, not lower) for key, lower in forced}
        pruned = [{kw: v for kw, v in o.items() if kw not in banned} for o in ways]
        if pruned == ways:
            return ways
        ways = pruned


def one_input_changes(best: Candidate) -> list[dict[str, float]]:
    """Each input that alone clears every failed numeric check of ``best`` (one offered
    by all of them), at its tightest value: the alternatives ``input_change`` chooses
    among (e.g. a shorter screw or a lower speed for the critical speed). An input the
    checks move different ways (a shorter screw for the critical speed, a longer one for
    the stroke) clears none of them alone; a most is met at the smallest, a least at the
    largest (``lowers``)."""
    options = [c.input_limits for c in best.failed_checks]
    if not options or any(not o for o in options):
        return []
    ways = [{(k, lowers(best.app, k, v)): v for k, v in o.items()} for o in options if o]
    shared = set.intersection(*(set(o) for o in ways))
    return [
        {key: (min if lower else max)(o[key, lower] for o in ways)} for key, lower in sorted(shared)
    ]


def accepted(app: Application, change: Mapping[str, float], ranges: Ranges) -> bool:
    """Whether the inputs accept ``app`` with ``change`` made: each value within its
    range (``within``), and the inputs' own rules kept (``inputs_hold``)."""
    changed = replace(app, **cast(dict[str, Any], change))
    return within(change, ranges) and inputs_hold(changed)


def within(change: Mapping[str, float | str], ranges: Ranges) -> bool:
    """Every numeric value of ``change`` lies within its input's range (inclusive); a
    choice (an end fixity) is one of its input's own.

    >>> within({"load_n": -5.0}, {"load_n": (0.0, 1e6)}), within({"load_n": 5.0}, {})
    (False, True)
    >>> within({"end_fixity": "fixed-fixed", "load_n": 5.0}, {"load_n": (0.0, 1e6)})
    True
    """
    unbounded = (-math.inf, math.inf)
    return all(
        ranges.get(k, unbounded)[0] <= v <= ranges.get(k, unbounded)[1]
        for k, v in change.items()
        if not isinstance(v, str)
    )


def describe_change(
    app: Application, change: Mapping[str, float | str], words: Words | None = None
) -> Phrase:
    """The change in words: "reduce the axial load to {value}" per input, each named by
    ``words`` ("mount the ends fixed-fixed" for the end fixity), each value rounded for
    the reader away from the limit it clears (a reduction down, a rise up)."""
    parts = []
    for key, value in change.items():
        if isinstance(value, str):
            parts.append(Phrase("mount the ends {v}", {"v": value}))
            continue
        label, quantity = input_words(key, words or {})
        less = value < getattr(app, key)
        # shown rounded away from the limit the change clears: a reduction down, a rise up
        amount = Amount(value, quantity, "down" if less else "up")
        parts.append(Phrase(f"{'reduce' if less else 'set'} the {label} to {{v}}", {"v": amount}))
    return join(parts, " and ")


def feasible_changes(
    nearest: Sequence[Candidate],
    ranges: Ranges,
    count: int = 5,
    known: Sequence[Mapping[str, float]] = (),
) -> tuple[Change, ...]:
    """Input changes within ``ranges`` that admit each of the nearest rejected candidates,
    one per distinct change: each clears every failed limit of the candidate it names
    and keeps the inputs' own rules (``inputs_hold``). ``known``: the input changes of
    the first candidates, already worked out."""
    changes: list[Change] = []
    for k, ev in enumerate(nearest):
        change = dict(known[k]) if k < len(known) else input_change(ev)
        if not change or any(c.inputs == change for c in changes):
            continue
        if accepted(ev.app, change, ranges):
            changes.append(Change(change, ev.screw.id))
        if len(changes) == count:
            break
    return tuple(changes)
