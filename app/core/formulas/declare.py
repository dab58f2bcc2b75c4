"""A formula's text and source, declared on the function that computes it.

The formulas table the API serves (``GET /api/v1/formulas``) and the page's detail view are
generated from these declarations: each reported number names the function behind it, and
the function carries its formula and source, so the text and the code live side by side.

>>> from app.core.formulas import geometry
>>> formula_of(geometry.lead_angle).text
'lambda = atan(lead / (pi d_p))'
"""

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, TypeVar, cast

#: The seed catalog the series data and many formulas come from.
SEED = "seed catalog, Leadscrew Assemblies: Design and Engineering Data"
#: Power screws: efficiency, self-locking, raising and lowering torque.
SHIGLEY = "Shigley's Mechanical Engineering Design, 9th ed., sec. 8-2"

F = TypeVar("F", bound=Callable[..., Any])


@dataclass(frozen=True, slots=True)
class Declared:
    """A formula as text (symbols as in the docstring) and where it comes from."""

    text: str
    source: str


def formula(text: str, source: str) -> Callable[[F], F]:
    """Decorator: declare the formula ``function`` computes and its source."""

    def declare(function: F) -> F:
        cast(Any, function).formula = Declared(text, source)
        return function

    return declare


def formula_of(function: Callable[..., Any]) -> Declared:
    """The formula declared on ``function``; AttributeError when none is."""
    declared: Declared = cast(Any, function).formula
    return declared
