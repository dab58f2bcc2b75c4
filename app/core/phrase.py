"""Sentences the core returns as numbers: a template and SI amounts, rendered at the edge.

The core never writes a unit into text. A check's message or fix is a ``Phrase``: a
``str.format`` template whose fields are ``Amount`` (an SI value and the quantity it
measures) or plain words; ``app.contract.units`` renders it in the units the reader chose.
"""

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Literal

#: What an amount measures: the one list of dimensions in the app. The core holds each in
#: the unit after it; ``app.contract.units`` holds every unit of each and converts at the edges.
Quantity = Literal[
    "force",  # N
    "length",  # m
    "travel",  # m: a distance travelled over a life (shown in km or miles)
    "speed",  # m/s
    "accel",  # m/s^2
    "torque",  # N m
    "mass",  # kg
    "inertia",  # kg m^2
    "inertia_per_length",  # kg m^2/m
    "density",  # kg/m^3
    "rpm",  # rev/min
    "pv",  # Pa m/s
    "pressure",  # Pa
    "expansion",  # 1/K
    "strain",  # m/m
    "time",  # s
    "years",  # year
    "temperature",  # deg C
    "temperature_rise",  # K: a difference of temperatures (no offset between scales)
    "factor",  # dimensionless
    "frequency",  # 1/s (step pulses per second)
    "inductance",  # H
    "voltage",  # V
    "power",  # W
    "energy",  # J
    "conductivity",  # W/(m K)
    "wear_rate",  # m^2/N: wear volume per load and sliding distance, m^3/(N m)
]


#: How the edge rounds an amount it writes: to the nearest (None), or down or up, so that
#: a fix's bound written to its figures stays on the safe side of its margin.
Rounding = Literal["down", "up"] | None


@dataclass(frozen=True, slots=True)
class Amount:
    """An SI value of a quantity, for the edge to show in the reader's units, rounded
    there as ``rounded`` says (a fix's upper bound down, its lower bound up)."""

    value: float
    quantity: Quantity
    rounded: Rounding = None


@dataclass(frozen=True, slots=True)
class Phrase:
    """``template`` with ``{name}`` fields filled from ``values`` at the edge.

    >>> Phrase("Run at most {v}.", {"v": Amount(0.1, "speed")}).template
    'Run at most {v}.'
    """

    template: str
    values: Mapping[str, "Amount | str | Phrase"] = field(default_factory=dict)


def join(parts: "list[Phrase]", separator: str = " ") -> Phrase:
    """Several phrases as one, their fields renamed so that they cannot collide.

    >>> join([Phrase("A {x}.", {"x": "1"}), Phrase("B {x}.", {"x": "2"})]).template
    '{p0} {p1}'
    """
    names = [f"p{i}" for i in range(len(parts))]
    return Phrase(
        separator.join("{" + n + "}" for n in names), dict(zip(names, parts, strict=True))
    )


def in_words(names: "list[str] | tuple[str, ...]", last: str = "and") -> str:
    """Names as a list in words, ``last`` before the last one.

    >>> in_words(["a"]), in_words(["a", "b", "c"]), in_words(("x", "y"), "or")
    ('a', 'a, b and c', 'x or y')
    """
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + f" {last} " + names[-1]


def plural(count: int, one: str, many: str) -> str:
    """``one`` for a count of 1, ``many`` for any other: the words that agree with it.

    >>> f"1 of 5 candidates {plural(1, 'passes', 'pass')}", plural(3, "screw does", "screws do")
    ('1 of 5 candidates passes', 'screws do')
    """
    return one if count == 1 else many


def figures(value: float, digits_below: int = 7) -> str:
    """A count or life to three significant figures as an engineer writes it: without an
    exponent from 0.001 to below 10^``digits_below``, thousands grouped.

    >>> figures(2391.7), figures(262.04), figures(0.04567), figures(4.2e8), figures(1.5e-5)
    ('2,390', '262', '0.0457', '4.2e+08', '1.5e-05')
    >>> figures(0.0), figures(float("inf")), figures(28_962_114.0, digits_below=15)
    ('0', 'inf', '29,000,000')
    """
    if not math.isfinite(value) or value == 0:
        return f"{value:.3g}"
    if not -3 <= math.floor(math.log10(abs(value))) < digits_below:
        return f"{value:.3g}"
    rounded = float(f"{value:.3g}")
    return f"{rounded:,.0f}" if rounded >= 100 else f"{rounded:.3g}"
