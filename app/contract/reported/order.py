"""The output table's rows of ordering: the line to send a maker for a quote and what
it rests on (``app.catalog.ordering``)."""

from typing import Any

from app.catalog import ordering
from app.contract.reported.row import Reported
from app.contract.source import From, Writer


def order_line(values: tuple[Any, float, float, Any], w: Writer) -> str:
    """The line to send for a quote, from the screw, its length [m], the nut length its
    nut checks used [m] and the provenance of the values they read
    (``app.catalog.ordering.ordering_line`` of ``ordering.as_rated``)."""
    screw, length_m, nut_length_m, provenance = values
    return ordering.ordering_line(ordering.as_rated(screw, nut_length_m, provenance), length_m)


def order_basis(screw: Any, w: Writer) -> str:
    """What the ordering line rests on (``app.catalog.ordering.ordering_basis``)."""
    return ordering.ordering_basis(screw)


ROWS: tuple[Reported, ...] = (
    Reported(
        "order_line",
        "To order",
        "The line to send a maker for a quote: the ISO 2903 designation with its tolerance "
        "class for an ISO trapezoidal screw, else the size, lead, materials, nut and length; "
        "then what to confirm with the maker where the catalog assumes a value.",
        cell="text",
        csv=True,
        compare=True,
        source=From(
            ("screw", "app.length_m", "quantities.nut.nut_length_m", "value_provenance"),
            via=order_line,
        ),
        type=str,
    ),
    Reported(
        "order_basis",
        "Ordering basis",
        "What the ordering line rests on: the standard's designation, or why there is no "
        "maker's ordering code, and the maker where that is public.",
        cell="text",
        source=From("screw", via=order_basis),
        type=str,
    ),
)
