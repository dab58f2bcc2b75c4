"""The value of one input at which a check's limit is just met, found by working the
check again with the input changed: for demands the core works out segment by segment
(the drive's peak torque, the cycle's RMS torque), whose inverse has no clean closed form.

The check's own utilisation (its ``measure``, over ``quantities.operating_point`` of the
screw's one row) is read at each trial value, so no formula is written twice. From the
input's value, which fails, the search steps geometrically (``STEP``) towards less (an
acceleration, a load) or more (a dwell) until a value passes, then narrows the bracket
by regula falsi with the Illinois modification (Dowell and Jarratt, BIT 11 (1971)
168-174): a torque piecewise affine in the input is met in a few steps. The value
returned is the bracket's passing end, so that the check passes at it.
"""

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any, cast

from app.core import motion
from app.core.dry_run import as_run
from app.core.model import Application, ScrewSpec
from app.core.quantities import Quantities, operating_point
from app.core.table import Array, CandidateTable

#: A check's utilisation of a one-row table (demand / capacity, the check's ``measure``).
Utilisation = Callable[[Application, CandidateTable, Quantities[Array]], float]

#: Each step away from the input's value multiplies or divides it by this.
STEP = 2.0
#: At most this many steps: a value 2^-12 of the input's (or 2^12 times it) is the last
#: one tried.
STEPS = 12
#: The bracket is narrowed until its width is at most this share of its passing end.
TOLERANCE = 2.0**-30
#: At most this many narrowing steps.
NARROWING = 60


def largest_below(
    app: Application,
    s: ScrewSpec,
    key: str,
    used: Utilisation,
    share: float = 1.0,
    convex: bool = False,
) -> float | None:
    """The value of input ``key`` nearest below its value in ``app`` at which screw ``s``
    is used at most ``share`` of the check's limit (1: the limit itself; 1 / 1.05: a fix's
    margin), ``used`` the check's utilisation; None where no value tried passes (down to
    2^-STEPS of the input's value; a load down to 0) or the input is not above 0. A
    ``convex`` utilisation (a peak torque: the largest of magnitudes each affine in the
    input, but for the thread's change of direction) passes below its value only if it
    passes at the lowest value tried, which is tried first; the value found is then the
    largest."""
    now = float(getattr(app, key))
    if now <= 0.0:
        return None
    trials = [now / STEP**k for k in range(1, STEPS + 1)]
    if key == "load_n":
        trials.append(0.0)
    excess = _utilisation(app, s, key, used, share)
    if convex and not excess(trials[-1]) <= 0.0:
        return None
    return _bracketed(excess, now, trials)


def smallest_above(
    app: Application, s: ScrewSpec, key: str, used: Utilisation, share: float = 1.0
) -> float | None:
    """The smallest value of input ``key`` above its value in ``app`` at which ``s`` is
    used at most ``share`` of the check's limit (``largest_below``, raising the input: a
    longer dwell); an input at 0 is tried from the move's cycle time up. None where no
    value up to 2^STEPS times the first passes."""
    now = float(getattr(app, key))
    p = motion.move_profile(app)
    start = now if now > 0.0 else (p.cycle_time_s if p is not None else 0.0) / STEP
    if start <= 0.0:
        return None
    trials = [start * STEP**k for k in range(1, STEPS + 1)]
    return _bracketed(_utilisation(app, s, key, used, share), now, trials)


def _utilisation(
    app: Application, s: ScrewSpec, key: str, used: Utilisation, share: float
) -> Callable[[float], float]:
    """The check's utilisation of ``s`` over ``share``, less 1, with input ``key`` at a
    given value: at most 0 where it passes."""
    row = as_run(app, CandidateTable.build([s]))

    def excess(value: float) -> float:
        changed = replace(app, **cast(dict[str, Any], {key: value}))
        return used(changed, row, operating_point(changed, row)) / share - 1.0

    return excess


def _bracketed(excess: Callable[[float], float], now: float, trials: list[float]) -> float | None:
    """The passing end of a bracket narrowed about ``excess``'s root: from ``now`` (which
    fails) along ``trials`` to the first value that passes, then by Illinois steps."""
    fail, f_fail = now, excess(now)
    if not f_fail > 0.0:
        return None
    for value in trials:
        f_value = excess(value)
        if math.isnan(f_value):
            return None
        if f_value <= 0.0:
            return _narrowed(excess, (value, f_value), (fail, f_fail))
        fail, f_fail = value, f_value
    return None


def _narrowed(
    excess: Callable[[float], float], passing: tuple[float, float], failing: tuple[float, float]
) -> float:
    """Regula falsi with the Illinois modification between a ``passing`` (value, excess
    at most 0) and a ``failing`` (excess above 0) point: the passing end once the bracket
    is at most ``TOLERANCE`` of it wide, or after ``NARROWING`` steps."""
    (a, f_a), (b, f_b) = passing, failing
    side = 0
    for _ in range(NARROWING):
        if abs(b - a) <= TOLERANCE * max(abs(a), abs(b)) or f_a == 0.0:
            break
        c = (a * f_b - b * f_a) / (f_b - f_a)
        if not min(a, b) < c < max(a, b):
            c = (a + b) / 2.0
        f_c = excess(c)
        if f_c <= 0.0:
            a, f_a = c, f_c
            f_b = f_b / 2.0 if side == -1 else f_b
            side = -1
        else:
            b, f_b = c, f_c
            f_a = f_a / 2.0 if side == 1 else f_a
            side = 1
    return a
