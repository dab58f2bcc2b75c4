"""A row of the output table (``Reported``), the formula behind it, and the kinds
its fields take: how its cell renders, when its column is shown, the views."""

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Literal

from app.contract.source import From
from app.contract.units import Display, Quantity

Better = Literal["lower", "higher"] | None
#: How a value renders: ``show`` writes the plain kinds; the composite ones are macros of
#: ``templates/partials/cells.html`` (the compare page writes them with ``show`` too).
Cell = Literal[
    "number",  # in its display unit, ``digits`` significant figures
    "whole",  # a whole number (a speed in rpm)
    "percent",  # a share, 0-1, as a whole percentage
    "times",  # a margin: ``digits`` decimals and "×"
    "text",  # as it is
    "band",  # a [low, high] pair: "low–high", three significant figures
    "screw",  # the id with its tags (coating, anti-backlash, nut material)
    "peak",  # the peak motor torque with the torque while accelerating under it
    "breakdown",  # inertia · drag · load torque
    "holding",  # self-locking, or the brake the load needs
    "life",  # the life band in years, else the rated travel, with its model
    "governing",  # the governing check's label with the pass marks and warnings
]
#: The cells drawn by a macro of their own (``templates/partials/cells.html``, one macro
#: per kind, named as it); every other kind is plain text, written by ``show``.
COMPOSITE: frozenset[Cell] = frozenset(
    ("screw", "peak", "breakdown", "holding", "life", "governing")
)
#: When a results-table column is shown: always, with a move (a stroke), without one, or
#: when a motor is given (or the ranking is by motor margin).
Shown = Literal["always", "move", "no_move", "motor"]
#: The forms of a candidate a row can add its number to (``app.contract.schemas.VIEWS``).
ViewName = Literal["row", "summary", "rejected", "csv"]


@dataclass(frozen=True, slots=True)
class Formula:
    """The core function behind a number; its declared formula and source (``@formula``)
    unless ``text`` and ``source`` are given (one function computing several numbers, or
    a variant of its formula)."""

    function: Callable[..., Any]
    text: str | None = None
    source: str | None = None


@dataclass(frozen=True, slots=True)
class Reported:
    """One reported number (or value) of a candidate; see the module's docstring."""

    #: its path in the candidate's JSON, and its one name: ``torque.total_nm``
    key: str
    #: the heading of its column or row, and what it means (the heading's hover text, the
    #: guide, the field's description)
    label: str = ""
    help: str = ""
    #: the display quantity of a number in a unit (converted by the page's switches), else
    #: the unit as text ("rpm", "years"; "" for a share or a count)
    quantity: Quantity | None = None
    unit: str = ""
    #: which way is better, for the compare page's best mark and the ranked column's order
    better: Better = None
    #: how its cell renders (``Cell``), and a number's significant figures (a margin's
    #: decimals)
    cell: Cell = "number"
    digits: int = 4
    #: a column of the results table: when shown, a second line under the heading, whether
    #: the heading names the unit (a composite cell names its own), the cell's CSS class,
    #: and the rankings it shows (the ranking input's choices)
    column: bool = False
    shown: Shown = "always"
    note: str = ""
    unit_heading: bool = True
    css: str = ""
    ranks: tuple[str, ...] = ()
    #: a column of the CSV (headed by the key without its API unit, in the display unit);
    #: a row of the compare page; the candidate's views it is in besides ``full``
    csv: bool = False
    compare: bool = False
    views: tuple[ViewName, ...] = ()
    #: the core function behind it (``app.report.formulas``)
    formula: Formula | None = None
    #: for a number the hand-written models do not hold: where it comes from in the core's
    #: record, and its type; the row then adds it to ``CandidateOut``
    source: From | None = None
    type: Any = float

    def unit_label(self, d: Display) -> str:
        """The unit the number is shown in: its quantity's display unit, else ``unit``."""
        return d.label(self.quantity) if self.quantity is not None else self.unit
