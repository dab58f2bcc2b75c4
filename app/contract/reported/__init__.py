"""The output table: every reported number of a candidate, declared once.

A row names the number by its path in the candidate's JSON (``CandidateOut``:
``rpm``, ``torque.total_nm``, ``utilization.pv``) and says everything the edges need
to show it: its label and help, its display quantity (or unit), which way is better,
whether it is a column of the results table (and how its cell renders), a column of
the CSV, a row of the compare page, the views it is in, and the formula behind it.
Everything that shows a number reads this table:

- the output models: a row with a ``source`` adds its field to ``CandidateOut``
  (``app.contract.schemas``), and the views take the rows that name them;
- the results table (``templates/partials/candidates.html``) loops over ``columns``:
  a plain number renders by its ``cell`` kind (``show``; a row at a time: ``row_cells``),
  a composite cell (``COMPOSITE``: the screw, the torque with a move, the breakdown,
  holding, life, governing) by the macro of that name in ``templates/partials/cells.html``;
- the CSV (``app.web.export``), the compare page (``app.web.compare``), the guide's
  column help (``app.web.guide``) and the formulas table (``app.report.formulas``).

So a new number is one row in the module of its topic (plus the core computing it,
if it does not yet): ``screw``, ``order``, ``drive``, ``holding``, ``capacity``, ``duty``,
``moves``, ``verdict`` (the row's type in ``row``). They are put together here in the
table's order, which is the order of the results table's columns, the CSV's columns and
the compare page's rows.
"""

import math
from collections.abc import Iterable, Mapping
from typing import Annotated, Any, Optional

from pydantic import Field

from app.contract.figures import sig
from app.contract.reported import capacity, drive, duty, holding, moves, order, screw, verdict
from app.contract.reported.row import (
    COMPOSITE,
    Better,
    Cell,
    Formula,
    Reported,
    Shown,
    ViewName,
)
from app.contract.units import Display
from app.core.phrase import figures
from app.core.wording import percent, times

__all__ = [
    "BY_KEY",
    "COMPOSITE",
    "REPORTED",
    "Better",
    "Cell",
    "Formula",
    "Reported",
    "Shown",
    "ViewName",
    "added_fields",
    "columns",
    "merged",
    "row_cells",
    "show",
    "value_of",
    "view_of",
]

REPORTED: tuple[Reported, ...] = (
    *screw.NUT,
    *order.ROWS,
    *screw.GEOMETRY,
    *drive.ROWS,
    *holding.ROWS,
    *capacity.ROWS,
    *duty.ROWS,
    *moves.ROWS,
    *verdict.ROWS,
)

BY_KEY = {r.key: r for r in REPORTED}


def value_of(model: Any, key: str) -> Any:
    """The value at ``key`` (a row's dotted path) of a candidate's output model; None
    where a part on the way is missing (no life, no stroke) or a dict has no such key.

    >>> value_of({"utilization": {"pv": 0.5}}, "utilization.pv"), value_of({}, "life.years")
    (0.5, None)
    """
    value = model
    for name in key.split("."):
        if value is None:
            return None
        value = value.get(name) if isinstance(value, Mapping) else getattr(value, name)
    return value


def show(row: Reported, value: Any, d: Display) -> str:
    """A plain cell's text in the display units; an em dash where there is no value.

    >>> from app.contract.units import DEFAULT_UNITS
    >>> d = Display(dict(DEFAULT_UNITS))
    >>> show(BY_KEY["lead_mm"], 10.0, d), show(BY_KEY["efficiency"], 0.456, d)
    ('10', '46 %')
    >>> show(BY_KEY["critical_speed.margin"], 3.14159, d), show(BY_KEY["life.years"], None, d)
    ('3.14×', '—')
    >>> show(BY_KEY["critical_speed.margin"], 0.997, d)  # a fail never reads 1.00×
    '0.997×'
    >>> show(BY_KEY["life.travel_km"], [15.0, 45.0], d)
    '15–45'
    >>> show(BY_KEY["life.years"], [21.8, 21.8], d)  # one value (a ball nut's L10)
    '21.8'
    """
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "—"
    if isinstance(value, list):
        ends = [d.value(v, row.quantity) if row.quantity else v for v in value]
        return "–".join(dict.fromkeys(figures(v) for v in ends))
    if row.cell == "whole":
        return f"{value:.0f}"
    if row.cell == "percent":
        return percent(value)
    if row.cell == "times":
        return times(value, row.digits)
    if isinstance(value, float):
        return d.text(value, row.quantity, row.digits) if row.quantity else sig(value, row.digits)
    return str(value)


def row_cells(model: Any, shown: Iterable[Reported], d: Display) -> list[tuple[Reported, Any]]:
    """A candidate's results-table row: each shown column with its plain cell's text
    (``show``), None for a composite cell (``COMPOSITE``: its macro draws it). One call
    a row, where the table calling ``show`` and ``value_of`` a cell cost a fifth of its
    rendering.

    >>> from app.contract.units import DEFAULT_UNITS
    >>> shown = [BY_KEY["lead_mm"], BY_KEY["efficiency"], BY_KEY["id"]]
    >>> d = Display(dict(DEFAULT_UNITS))
    >>> cells = row_cells({"lead_mm": 10.0, "efficiency": 0.456}, shown, d)
    >>> [(row.key, text) for row, text in cells]
    [('lead_mm', '10'), ('efficiency', '46 %'), ('id', None)]
    """
    return [
        (row, None if row.cell in COMPOSITE else show(row, value_of(model, row.key), d))
        for row in shown
    ]


def columns(move: bool, motor: bool) -> list[Reported]:
    """The results table's columns shown for this result, in table order."""
    shown = {"always": True, "move": move, "no_move": not move, "motor": motor}
    return [r for r in REPORTED if r.column and shown[r.shown]]


def view_of(name: ViewName) -> dict[str, Any]:
    """The fields the rows put in a view (results-table columns: ``row``; CSV columns:
    ``csv``; and each row's ``views``), nested as ``VIEWS`` holds them: a dotted key
    takes its field of the section, a dict's key (``utilization.pv``) the whole dict."""
    view: dict[str, Any] = {}
    for row in REPORTED:
        if name in row.views or (name == "row" and row.column) or (name == "csv" and row.csv):
            head, _, rest = row.key.partition(".")
            if not rest or head == "utilization":
                view[head] = True
            elif view.get(head) is not True:
                view.setdefault(head, {})[rest] = True
    return view


def merged(*views: Mapping[str, Any]) -> dict[str, Any]:
    """Views together: a field whole in any of them is whole.

    >>> merged({"a": True, "t": {"x": True}}, {"t": {"y": True}}, {"a": {"z": True}})
    {'a': True, 't': {'x': True, 'y': True}}
    """
    out: dict[str, Any] = {}
    for view in views:
        for name, part in view.items():
            have = out.get(name)
            if have is True or part is True:
                out[name] = True
            else:
                out[name] = merged(have or {}, part)
    return out


def added_fields(declared: Iterable[str]) -> dict[str, Any]:
    """``create_model`` definitions of the rows that give a ``source`` for a number
    ``declared`` (the hand-written fields) does not hold: name -> (type, field)."""
    fields: dict[str, Any] = {}
    for row in REPORTED:
        if row.source is None:
            continue
        if "." in row.key or row.key in declared:
            raise ValueError(f"{row.key}: a row's own field is a new top-level field")
        annotation: Any = Annotated[Optional[row.type], row.source]  # noqa: UP045 (a run-time type)
        fields[row.key] = (annotation, Field(default=None, description=row.help))
    return fields
