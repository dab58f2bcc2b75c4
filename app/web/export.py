"""CSV export of a selection result, in the user's display units, safe to open in a spreadsheet."""

import csv
import io
from collections.abc import Callable
from typing import Any

from app.contract.fields import FIELDS
from app.contract.input_field import InputField
from app.contract.move_table import COLUMNS, shown_moves
from app.contract.outputs import SelectOut
from app.contract.reported import BY_KEY, REPORTED, Reported, value_of
from app.contract.schemas import CandidateOut
from app.contract.torque_curve import curve_text
from app.contract.units import Display
from app.core.checks import REGISTRY

#: A CSV column's value of a candidate.
Getter = Callable[[CandidateOut], Any]

#: the header's unit of a check's utilization: demand over capacity (1 is at the limit).
UTILIZATION_UNIT = BY_KEY["utilization"].unit

#: a text cell starting with one of these is a formula to a spreadsheet (CWE-1236); the
#: fullwidth forms count too, since spreadsheets in East Asian locales read them as ASCII.
FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r", "＝", "＋", "－", "＠")


def safe_cell(value: Any) -> Any:
    """Quote a text cell that a spreadsheet would run as a formula; numbers pass as numbers.

    Leading blanks (spaces, no-break and ideographic spaces, line breaks) are skipped
    before the test: spreadsheets skip them too, so `` =1+1`` is still a formula.

    >>> safe_cell("=HYPERLINK(1)"), safe_cell("-2+3"), safe_cell("B6000"), safe_cell(-1.5)
    ("'=HYPERLINK(1)", "'-2+3", 'B6000', -1.5)
    >>> safe_cell(" =1+1"), safe_cell("＝1+1"), safe_cell("\u3000＠SUM(A1)"), safe_cell(" 12 mm")
    ("' =1+1", "'＝1+1", "'\u3000＠SUM(A1)", ' 12 mm')
    """
    if isinstance(value, str) and (
        value.startswith(FORMULA_STARTS) or value.lstrip().startswith(FORMULA_STARTS)
    ):
        return "'" + value
    return value


def tidy(value: Any) -> Any:
    """A float to 10 significant figures, so unit conversions leave no binary noise
    (0.7500000000000001 is written 0.75) and a spreadsheet still recomputes the inputs
    exactly enough; other values as they are.

    >>> tidy(0.7500000000000001), tidy(1.968503937007874), tidy(True), tidy(3), tidy(None)
    (0.75, 1.968503937, True, 3, None)
    """
    return float(f"{value:.10g}") if isinstance(value, float) else value


def cell(value: Any) -> Any:
    """A value as the CSV writes it: numbers tidied, formula-like text quoted."""
    return safe_cell(tidy(value))


#: the API unit suffixes a number's key ends in, left out of its CSV heading, which names
#: the display unit in brackets instead.
API_SUFFIXES = (
    *("_mpa_m_s", "_m_s", "_mm_s2", "_mm_s", "_mm", "_m", "_nm", "_n", "_mpa"),
    *("_rpm", "_kg_m2", "_kg", "_w", "_k", "_c", "_s", "_hz", "_deg", "_km"),
)


def csv_name(key: str) -> str:
    """A key of the output table without its API unit suffix.

    >>> csv_name("torque.total_nm"), csv_name("lead_mm"), csv_name("rpm"), csv_name("fix")
    ('torque.total', 'lead', 'rpm', 'fix')
    """
    return next((key.removesuffix(s) for s in API_SUFFIXES if key.endswith(s)), key)


def _getter(row: Reported, d: Display, index: int | None = None) -> Getter:
    def get(c: CandidateOut) -> Any:
        value = value_of(c, row.key)
        if index is not None:
            value = None if value is None else value[index]
        if row.quantity is None or value is None:
            return value
        return d.value(value, row.quantity)

    return get


def _utilization(name: str) -> Getter:
    def get(c: CandidateOut) -> Any:
        return c.utilization.get(name)

    return get


def _columns(d: Display) -> list[tuple[str, Getter]]:
    """A column per CSV row of the output table, headed by its key and display unit: a
    band as its low and high ends, the utilizations as a column per check."""
    out: list[tuple[str, Getter]] = []
    for row in REPORTED:
        if not row.csv:
            continue
        name, unit = csv_name(row.key), row.unit_label(d)
        if row.key == "utilization":
            out += [
                (_heading("", f"{name}.{c.name}", unit), _utilization(c.name)) for c in REGISTRY
            ]
        elif row.cell in ("band", "life"):
            out.append((_heading("", f"{name}_min", unit), _getter(row, d, 0)))
            out.append((_heading("", f"{name}_max", unit), _getter(row, d, 1)))
        else:
            out.append((_heading("", name, "" if unit == name else unit), _getter(row, d)))
    return out


def _heading(prefix: str, name: str, unit: str) -> str:
    """A column heading for a name (an input, a screw value) with its unit, if any."""
    return f"{prefix}{name} [{unit}]" if unit else f"{prefix}{name}"


def _input_rows(inputs: dict[str, Any], units: dict[str, str]) -> list[list[Any]]:
    """One (page name, value in the display units, display unit) per table input; an
    optional input left empty has an empty value."""
    return [
        [field.page, _input_value(field, inputs[field.api], units), field.display_unit(units)]
        for field in FIELDS
    ]


def _input_value(field: InputField, value: Any, units: dict[str, str]) -> Any:
    """An input in the display units; a curve as 'rpm:torque,...' in the torque unit."""
    if field.kind == "curve" and value:
        return curve_text(value, units, digits=10)
    return field.display_value(value, units)


def _move_rows(inputs: dict[str, Any], units: dict[str, str]) -> list[list[Any]]:
    """One (``<move>.<column>``, value in the display units, display unit) per cell of the
    cycle's moves, moves counted from 1; none without moves."""
    return [
        [f"{i}.{column.key}", value, column.field.display_unit(units)]
        for i, row in enumerate(shown_moves(inputs.get("moves") or [], units), start=1)
        for column, value in zip(COLUMNS, row, strict=True)
    ]


def _trailing(groups: list[tuple[str, list[list[Any]]]]) -> tuple[list[str], list[Any]]:
    """The columns every row carries after the candidate's own (the inputs, a custom
    screw's values): headings ``<prefix><name> [unit]`` and the values."""
    headings = [_heading(prefix, name, unit) for prefix, rows in groups for name, _, unit in rows]
    return headings, [value for _, rows in groups for _, value, _ in rows]


def _table(
    columns: list[tuple[str, Getter]],
    rows: list[tuple[str, Any, CandidateOut]],
    trailing: tuple[list[str], list[Any]],
) -> str:
    """One table: a header, then per candidate its status, rank, columns and the
    trailing values (the same on every row, so each row stands alone when filtered);
    with no candidate, one row of status ``none`` with the trailing values only."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\r\n")
    writer.writerow(["status", "rank", *(name for name, _ in columns), *trailing[0]])
    tail = [cell(v) for v in trailing[1]]
    for status, rank, c in rows:
        writer.writerow([status, rank, *(cell(get(c)) for _, get in columns), *tail])
    if not rows:  # no screw to show: one row still records what was asked
        writer.writerow(["none", "", *([""] * len(columns)), *tail])
    return out.getvalue()


def results_csv(result: SelectOut, units: dict[str, str]) -> str:
    """One table: a row per passing candidate (ranked) and per rejected one shown, with a
    column per check of the registry for its utilization (empty where the check does not
    apply or is yes/no), then a column per input (``input:<page name> [unit]``, in the
    display units, the same on every row) and per cell of the cycle's moves
    (``move:<move>.<column> [unit]``); the candidates need only the ``csv`` view's
    fields."""
    rows: list[tuple[str, Any, CandidateOut]] = [
        ("passed", rank, c) for rank, c in enumerate(result.candidates, start=1)
    ]
    rows += [("rejected", "", c) for c in result.rejected]
    dump = result.inputs.model_dump()
    groups = [("input:", _input_rows(dump, units)), ("move:", _move_rows(dump, units))]
    return _table(_columns(Display(units)), rows, _trailing(groups))


def candidate_csv(
    inputs: dict[str, Any], screw_rows: list[list[Any]], c: CandidateOut, units: dict[str, str]
) -> str:
    """One screw of the user's own as a one-row table: its status and columns, then a
    column per screw value (``screw:<name> [unit]``), per input (``input:...``) and per
    cell of the moves (``move:...``)."""
    status = "passed" if c.passed else "rejected"
    groups = [
        ("screw:", screw_rows),
        ("input:", _input_rows(inputs, units)),
        ("move:", _move_rows(inputs, units)),
    ]
    return _table(_columns(Display(units)), [(status, "", c)], _trailing(groups))
