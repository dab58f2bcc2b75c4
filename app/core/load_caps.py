"""The largest load a limit on the thrust allows: the load input a fix or a change of the
application proposes, found by inverting the thrusts of the cycle (``motion``'s forms,
linear in the load) against a cap on the peak thrust or on the wear thrust.
"""

import itertools
import math

from app.core.formulas import wear
from app.core.model import Application
from app.core.motion import Form, at_load, wear_forms


def largest_load(forms: list[Form], allowed_n: float) -> float | None:
    """The largest load F with every g + h F at most ``allowed_n`` [N], below 0 when even
    no load is too much (the caller's input bounds refuse it); None when no load meets
    them all, or none bounds the load from above (the load is not the cause).

    >>> largest_load([(5.0, 1.0), (-5.0, -1.0)], 20.0), largest_load([(30.0, 0.0)], 20.0)
    (15.0, None)
    """
    low, high = -math.inf, math.inf
    for g, h in forms:
        if h > 0.0:
            high = min(high, (allowed_n - g) / h)
        elif h < 0.0:
            low = max(low, (allowed_n - g) / h)
        elif g > allowed_n:
            return None
    return high if low <= high < math.inf else None


def largest_load_for_wear(app: Application, allowed_n: float) -> float | None:
    """The largest load F >= 0 [N] whose cycle wears the nut no more than a steady
    ``allowed_n`` [N] would (``wear_thrust`` at most ``allowed_n``); None when even no load
    does, or when the load does not raise the wear. The wear thrust sum |g + h F| x / sum x
    is convex and piecewise linear in F, with corners where a segment's thrust changes
    sign, so the answer lies on the piece where it crosses ``allowed_n``.

    >>> app = Application(load_n=10.0, speed_m_s=0.1, length_m=0.5)
    >>> largest_load_for_wear(app, 4.0)
    4.0
    """
    forms, travels = wear_forms(app)

    def thrust(load_n: float) -> float:
        return wear.cycle_wear_thrust(at_load(forms, load_n), travels)

    corners = sorted({0.0, *(-g / h for g, h in forms if h and -g / h > 0.0)})
    if thrust(0.0) > allowed_n:
        return None
    last = corners[-1]
    slope = sum(abs(h) * x for (_, h), x in zip(forms, travels, strict=True)) / sum(travels)
    if thrust(last) <= allowed_n:
        return last + (allowed_n - thrust(last)) / slope if slope > 0.0 else None
    for low, high in itertools.pairwise(corners):
        if thrust(high) > allowed_n:
            share = (allowed_n - thrust(low)) / (thrust(high) - thrust(low))
            return low + share * (high - low)
    return None
