"""Numbers written as text: to a format or to significant figures, and a bound written
on its safe side (a fix's "at most", a field's allowed range), so that the figure a
reader types back keeps what it bounds. Units are ``app.contract.units``'; this module
writes a number already in the reader's unit.
"""

import math

from app.core.phrase import Rounding

#: the significant figures the format "g" writes (Python's default precision).
SHORTEST_G_FIGURES = 6
#: the most significant figures a bound's message writes to state it exactly (-459.67 °F).
EXACT_BOUND_FIGURES = 7


def plain(value: float, spec: str) -> str:
    """``value`` in the format ``spec``, but a whole number the format would write with
    an exponent written out, thousands grouped (up to 1e15).

    >>> plain(14740.4, ".4g"), plain(2419.0, ".4g"), plain(1.5e-5, ".3g"), plain(2e16, ".4g")
    ('14,740', '2419', '1.5e-05', '2e+16')
    """
    text = f"{value:{spec}}"
    if "e+" in text and abs(value) < 1e15:
        return f"{float(text):,.0f}"
    return text


def sig(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant figures; whole numbers past that, no exponent.

    >>> sig(4298.213), sig(12345.6), sig(0.20705016), sig(22.480894)
    ('4298', '12346', '0.2071', '22.48')
    """
    if abs(value) >= 10**digits:
        return f"{round(value):d}"
    return f"{value:.{digits}g}"


def apart(value: float, limit: float, decimals: int = 0) -> tuple[str, str]:
    """``value`` and the ``limit`` it is judged against, with ``decimals`` and as many
    more as it takes for two unequal numbers not to read equal (a speed 0.3 rpm over its
    limit reads "3661.3 rpm of 3661.0 allowed", not "3661 of 3661"), up to 6 more.

    >>> apart(3661.3, 3661.0), apart(1200.0, 3661.0), apart(2.0, 2.0)
    (('3661.3', '3661.0'), ('1200', '3661'), ('2', '2'))
    """
    for places in range(decimals, decimals + 7):
        shown = f"{value:.{places}f}", f"{limit:.{places}f}"
        if value == limit or shown[0] != shown[1]:
            return shown
    return shown


def _towards(value: float, lower: bool, digits: int) -> float:
    """``value`` (not 0) on the grid of its ``digits``-th significant figure, the step
    below it (``lower``) or above it."""
    scale = 10.0 ** (math.floor(math.log10(abs(value))) - digits + 1)
    steps = math.floor(value / scale) if lower else math.ceil(value / scale)
    return steps * scale


def round_towards(value: float, lower: bool, digits: int) -> float:
    """``value`` to ``digits`` significant figures, rounded down (``lower``) or up, so
    that a bound written with them still clears what it bounds; 0 or less as it is.

    >>> [round_towards(v, lower, 3) for v, lower in ((1677.74, True), (25.61, False))]
    [1670.0, 25.7]
    """
    if value <= 0:
        return value
    return float(f"{_towards(value, lower, digits):.{digits}g}")


def bound_text(value: float, spec: str, rounded: Rounding = None) -> str:
    """``value`` written in the format ``spec`` (``plain``), rounded to the nearest, or
    where that would cross it the way ``rounded`` forbids, one figure further down or up:
    a fix's "at most 118.2 mm/s" for 118.26 mm/s, never 118.3.

    >>> [bound_text(0.4872, ".3g", way) for way in ("up", None, "down")]
    ['0.488', '0.487', '0.487']
    >>> bound_text(118.26, ".4g", "down"), bound_text(97.6, ".0f", "down")
    ('118.2', '97')
    """
    text = plain(value, spec)
    if rounded is None or value <= 0.0:
        return text
    lower = rounded == "down"
    written = float(text.replace(",", ""))
    if written == value or (written < value) == lower:
        return text
    if spec.endswith("f"):  # fixed decimals: a step of the last one
        step = 10.0 ** -int(spec.rsplit(".", 1)[1][:-1])
        steps = math.floor(value / step) if lower else math.ceil(value / step)
        return plain(steps * step, spec)
    digits = int(spec.rsplit(".", 1)[1][:-1]) if "." in spec else SHORTEST_G_FIGURES
    return plain(round_towards(value, lower, digits), spec)


def bound_sig(value: float, lower: bool, digits: int = 4) -> str:
    """A field's bound in its display unit as ``sig`` writes it, never a number the bound
    refuses: exactly where at most ``EXACT_BOUND_FIGURES`` figures write it, else to
    ``digits`` figures rounded inside the allowed range, up for a ``lower`` bound and down
    for an upper one. 1 mm is at least 0.03938 in, not 0.03937 (0.0393700787 in); 1e6
    mm/s² at most 101.9 g, not 102.

    >>> bound_sig(0.0393700787, True), bound_sig(101.97162, False), bound_sig(-459.67, True)
    ('0.03938', '101.9', '-459.67')
    >>> bound_sig(224808.943, False), bound_sig(0.0, True), bound_sig(1000.0, False)
    ('224808', '0', '1000')
    """
    for figures in range(digits, EXACT_BOUND_FIGURES + 1):
        text = sig(value, figures)
        if math.isclose(float(text), value, rel_tol=1e-12, abs_tol=1e-300):
            return text
    text = sig(value, digits)
    if (float(text) >= value) == lower:
        return text
    if abs(value) >= 10**digits:
        return f"{math.ceil(value) if lower else math.floor(value):d}"
    return sig(_towards(value, not lower, digits), digits)
