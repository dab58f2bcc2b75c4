"""The formula behind each reported quantity: text, the core function, and the source.

Served with every result (``formulas`` in the API, the detail view on the page), so each
number can be traced to its formula and from there to the catalog values and provenance.
Each row of the output table (``app.contract.reported``) with a formula names the core
function that computes the number; the text and source are the ones declared on that
function (``app.core.formulas.declare``), or given by the row where one function computes
several numbers (the operating point, the move) or a variant of its formula (the running
back-drive efficiency, a margin).
"""

from typing import Any, TypedDict

from app.contract.reported import REPORTED
from app.contract.reported import Formula as Behind
from app.contract.units import api_value
from app.core.checks import REGISTRY
from app.core.formulas.declare import formula_of


class Formula(TypedDict):
    formula: str
    function: str
    source: str


def _entry(behind: Behind) -> Formula:
    """The function's declared formula and source, or the text and source the row gives."""
    function, text, source = behind.function, behind.text, behind.source
    if text is None or source is None:
        declared = formula_of(function)
        text, source = text or declared.text, source or declared.source
    return {
        "formula": text,
        "function": f"{function.__module__}.{function.__qualname__}",
        "source": source,
    }


#: Each reported number's formula, from the output table: ``<its key>``.
FORMULAS: dict[str, Formula] = {r.key: _entry(r.formula) for r in REPORTED if r.formula}

#: Each check's own formula, from the registry: ``checks.<name>``.
FORMULAS.update(
    {
        f"checks.{c.name}": {
            "formula": c.formula,
            "function": f"{type(c).__module__}.{type(c).__name__}.measure",
            "source": c.source,
        }
        for c in REGISTRY
    }
)


#: Every check the selection runs, in registry order, as the API lists it: what it
#: means, its formula, its source, the catalog values it reads and its API unit.
CHECKS_OUT: dict[str, Any] = {
    "checks": [
        {
            "name": c.name,
            "label": c.label,
            "kind": c.kind,
            "description": c.description,
            "formula": c.formula,
            "source": c.source,
            "sources": list(c.sources),
            "unit": api_value(0.0, c.quantity)[1],
        }
        for c in REGISTRY
    ]
}
