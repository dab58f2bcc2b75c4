"""Where each field of a candidate's output model comes from in the core's candidate
record (``app.core.record.Candidate``), declared on the field itself:

    rpm: Annotated[float, From("rpm")]
    outer_diameter_mm: Annotated[float, From("screw.outer_diameter_m", "length")]

A path is dotted attribute names (a digit picks an item of a tuple), read from the
model's source: the record for the candidate model, the value its own ``From`` gives for
a nested model (a section, each item of a list, each value of a dict; ``From()``: the
parent's source). A path starting with ``/`` is read from the record whatever the
source. A path never passes through None: the record gives what may be missing as an
attribute of its own (``profile``, ``life``). A tuple of paths gives a list (None when
one of them is None). ``quantity`` names
the core quantity of an SI number, converted to the API's unit (``app.contract.units.API_UNITS``).
``via`` computes a value the paths cannot name, from the value at the path and the
reader's ``Writer`` (the sentences in the reader's display units).
"""

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from app.contract.units import api_value, from_si, render
from app.core.phrase import Phrase
from app.core.phrase import Quantity as CoreQuantity


class Writer:
    """Writes the core's sentences in the reader's display units (``app.contract.units.render``),
    each sentence once: a failed check's fix is shown with the check and in the
    candidate's joined fix."""

    __slots__ = ("_written", "units")

    def __init__(self, units: Mapping[str, str]) -> None:
        self.units = units
        # keyed by identity; each entry keeps its phrase alive, so no key is reused
        self._written: dict[int, tuple[Phrase, str]] = {}

    def text(self, phrase: Phrase) -> str:
        written = self._written.get(id(phrase))
        if written is None:
            written = self._written[id(phrase)] = (phrase, render(phrase, self.units))
        return written[1]


#: A computed value: (the value at the path, the sentences' writer) -> output value.
Via = Callable[[Any, Writer], Any]


@dataclass(frozen=True, slots=True)
class From:
    """The source of an output field: a path in the record, its SI quantity, or ``via``."""

    path: str | tuple[str, ...] = ""
    quantity: CoreQuantity | None = None
    via: Via | None = None


def degrees(angle_rad: float, w: Writer) -> float:
    """An angle [rad] in degrees."""
    return math.degrees(angle_rad)


def million_cm(travel_m: tuple[float, float], w: Writer) -> list[float]:
    """Rated travel [m] in millions of cm, the catalog's unit."""
    return [from_si(t, "million cm") for t in travel_m]


def check_value(check: Any, w: Writer) -> float | None:
    """A check's demand in the API unit of its quantity (None for a yes/no check)."""
    return api_value(check.demand, check.check.quantity)[0] if check.numeric else None


def check_limit(check: Any, w: Writer) -> float | None:
    """A check's capacity in the API unit of its quantity (None for a yes/no check)."""
    return api_value(check.capacity, check.check.quantity)[0] if check.numeric else None


def check_unit(check: Any, w: Writer) -> str:
    """The API unit of a check's value and limit ("" for a yes/no check)."""
    return api_value(0.0, check.quantity)[1]


def joined(phrases: tuple[Phrase, ...], w: Writer) -> str | None:
    """Sentences in the reader's units, joined by spaces (None when there are none)."""
    text = [w.text(p) for p in phrases]
    return " ".join(text) if text else None


def text(phrase: Phrase, w: Writer) -> str:
    """One sentence in the reader's units."""
    return w.text(phrase)


def texts(phrases: tuple[Phrase, ...], w: Writer) -> list[str]:
    """Each sentence in the reader's units."""
    return [w.text(p) for p in phrases]
