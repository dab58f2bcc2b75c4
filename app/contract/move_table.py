"""The page's table of moves: one row per move, one cell per value, in display units.

A cell is the page field ``m<row>_<column>`` (``m0_dist``, ``m2_speed``); its number is
read as every page number is (``app.contract.exact.read_number``) in the unit of the scalar
input it stands beside (the distance as the stroke, the load as the axial load), and the
table's rows become the API's ``moves`` in its own units, each value exact, so that the
share link's ``moves`` text (``app.contract.cycle.moves_text``) gives the same answer.
A link without cells fills the table from its ``moves``. A plain GET edits the table
without JavaScript: ``add_move`` gives one more empty row, ``remove_move=<row>`` drops
that row. A row with every number left empty is not a move (a new row, not yet typed).
"""

import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from app.contract.cycle import MAX_MOVES, ORDER, parse_moves_text
from app.contract.exact import link_number, page_value, read_number
from app.contract.fields import BY_API, FIELDS
from app.contract.form import MOVES
from app.contract.input_field import InputField

#: The submit button that adds an empty row, and the one (its value the row) that drops one.
ADD_MOVE = "add_move"
REMOVE_MOVE = "remove_move"


@dataclass(frozen=True, slots=True)
class Column:
    """One column of the table: its key in the cell's name, the move's API name, and the
    scalar input whose label, unit and bounds it shares."""

    key: str
    api: str
    field: InputField
    label: str


def _scalar(api: str) -> InputField:
    """The scalar input a move's value shares its unit and bounds with: the one of the same
    API name, the stroke for the distance (the first value)."""
    return BY_API[api] if api in BY_API else next(f for f in FIELDS if f.core == "stroke_m")


#: The columns in the order of the compact text (``ORDER``), each with its cell key and
#: its heading.
COLUMNS = tuple(
    Column(key, api, _scalar(api), label)
    for key, label, api in zip(
        ("dist", "speed", "accel", "decel", "dwell", "mass", "load", "dir"),
        (
            "Distance",
            "Speed",
            "Acceleration",
            "Deceleration",
            "Dwell after",
            "Moving mass",
            "Load",
            "Load direction",
        ),
        ORDER,
        strict=True,
    )
)
BY_KEY = {c.key: c for c in COLUMNS}
BY_MOVE_API = {c.api: c for c in COLUMNS}
#: The column of a choice (the load direction), which alone never makes a row a move.
CHOICE = "dir"
CELL = re.compile(r"m([0-9]{1,2})_(" + "|".join(BY_KEY) + ")")

Row = dict[str, str]


def cell(row: int, key: str) -> str:
    """The page name of a cell: ``cell(0, 'dist')`` is 'm0_dist'."""
    return f"m{row}_{key}"


def is_cell(name: str) -> bool:
    """A page name of a cell of the table (rows 0 to ``MAX_MOVES`` less 1).

    >>> is_cell("m0_dist"), is_cell("m49_dir"), is_cell("m50_dist"), is_cell("m0_colour")
    (True, True, False, False)
    """
    match = CELL.fullmatch(name)
    return match is not None and int(match.group(1)) < MAX_MOVES


def cell_label(name: str) -> str | None:
    """A cell's page name in words, as its control is labelled; None for a name of no cell.

    >>> cell_label("m0_dir"), cell_label("load")
    ('Move 1 load direction', None)
    """
    match = CELL.fullmatch(name)
    if match is None or not is_cell(name):
        return None
    return f"Move {int(match.group(1)) + 1} {BY_KEY[match.group(2)].label.lower()}"


def _typed_rows(params: Mapping[str, str]) -> list[Row]:
    """The cells of the query as rows, in row order (a gap in the numbers closes up)."""
    rows: dict[int, Row] = {}
    for name, value in params.items():
        match = CELL.fullmatch(name)
        if match is not None and is_cell(name):
            rows.setdefault(int(match.group(1)), {})[match.group(2)] = value.strip()
    return [rows[i] for i in sorted(rows)]


def _shown(column: Column, text: str, units: Mapping[str, str]) -> str:
    """An API value of the moves text in the column's display unit, exactly (the link's
    number); text that is no number as it is, for the model to name."""
    number, _ = read_number(text) if column.key != CHOICE else (None, "")
    if number is None:
        return text
    return link_number(column.field, number, units)


def rows_of_text(text: str, units: Mapping[str, str]) -> list[Row] | None:
    """The rows of a link's ``moves`` text (API units) in display units; None for text
    that is no list of moves (the model's message says why)."""
    try:
        moves = parse_moves_text(text)
    except ValueError:
        return None
    return [
        {c.key: _shown(c, move.get(c.api, ""), units) for c in COLUMNS if c.api in move}
        for move in moves
    ]


def edited(rows: list[Row], params: Mapping[str, str]) -> list[Row]:
    """The rows after the query's ``remove_move`` (a row number) and ``add_move``."""
    rows = list(rows)
    drop = params.get(REMOVE_MOVE, "")
    if drop.isdigit() and int(drop) < len(rows):
        del rows[int(drop)]
    if ADD_MOVE in params and len(rows) < MAX_MOVES:
        rows.append({})
    return rows


def table_rows(params: Mapping[str, str], units: Mapping[str, str]) -> list[Row]:
    """The table of the query: its cells, else its ``moves`` text, edited (``edited``)."""
    rows = _typed_rows(params)
    if not rows and params.get(MOVES, "").strip():
        rows = rows_of_text(params[MOVES], units) or []
    return edited(rows, params)


def converted_rows(
    rows: list[Row], entered: Mapping[str, str], units: Mapping[str, str]
) -> list[Row]:
    """The rows typed in the ``entered`` units in ``units``: each number the shortest
    text that reads back to the same API value (text that is no number as typed)."""
    if dict(entered) == dict(units):
        return rows
    out = []
    for row in rows:
        new = dict(row)
        for key, text in row.items():
            column = BY_KEY[key]
            if key != CHOICE and text and read_number(text)[0] is not None:
                new[key] = link_number(column.field, page_value(column.field, text, entered), units)
        out.append(new)
    return out


def is_move(row: Row) -> bool:
    """A row with a number typed in it (not an empty new row)."""
    return any(text.strip() for key, text in row.items() if key != CHOICE)


def moves_of_rows(
    rows: list[Row], units: Mapping[str, str]
) -> tuple[str, dict[str, str], list[int]]:
    """(the API's ``moves`` text of the rows, each number in API units written exactly;
    the errors of cells that hold no number, by cell; the table row of each move)."""
    texts, errors, index = [], {}, []
    for i, row in enumerate(rows):
        if not is_move(row):
            continue
        values = []
        for column in COLUMNS:
            text = row.get(column.key, "").strip()
            if column.key == CHOICE or not text:
                values.append(text)
                continue
            number, error = read_number(text)
            if number is None:
                errors[cell(i, column.key)] = error
                values.append("")
            else:
                values.append(repr(page_value(column.field, text, units)))
        texts.append(":".join(values))
        index.append(i)
    return ";".join(texts), errors, index


def cell_errors(errors: Mapping[str, str], index: list[int]) -> dict[str, str]:
    """The model's errors with each move's (``moves.<move>.<api name>``) at its cell."""
    out: dict[str, str] = {}
    for name, message in errors.items():
        parts = name.split(".")
        if len(parts) == 3 and parts[0] == MOVES and parts[1].isdigit():
            move, api = int(parts[1]), parts[2]
            key = BY_MOVE_API[api].key if api in BY_MOVE_API else COLUMNS[0].key
            row = index[move] if move < len(index) else move
            out.setdefault(cell(row, key), message)
        else:
            out.setdefault(name, message)
    return out


def shown_moves(moves: list[Mapping[str, Any]], units: Mapping[str, str]) -> list[list[Any]]:
    """The API's moves (``MoveIn`` dumps) as a table of inputs: a row per move, a value per
    column in its display unit (an empty deceleration: the acceleration's, None).

    >>> inch = {"force_unit": "N", "length_unit": "in", "torque_unit": "N_m"}
    >>> shown_moves([dict(zip(ORDER, [254.0, 25.4, 254.0, None]))], inch)[0][:5]
    [10.0, 1.0, 10.0, None, None]
    """
    return [[c.field.display_value(move.get(c.api), units) for c in COLUMNS] for move in moves]
