"""The guide (/guide) and the validation page (/validation): how to read the results.

The guide iterates the check registry, so a new check appears here with its label,
description, formula and source; the ranking text follows ``app.core.selection``'s rank
order. The column help is the output table's (``app.contract.reported``), as the
results table's headers show it.
"""

from functools import cache

from fastapi import APIRouter
from fastapi.responses import HTMLResponse, Response

from app.catalog.entry import PROVENANCE_MEANINGS
from app.contract.fields import BY_API
from app.contract.figures import sig
from app.contract.reported import REPORTED
from app.core.checks import REGISTRY
from app.report.pull_out_curves import CURVES, PULL_OUT_TOLERANCE
from app.report.validation import EXAMPLES, TOLERANCE
from app.web.templating import templates

router = APIRouter(include_in_schema=False)


#: The results table's columns, each a row of the output table with its label and help.
COLUMNS = tuple(r for r in REPORTED if r.column)

#: each provenance kind and its words, in the guide's order (``PROVENANCE_MEANINGS``)
PROVENANCE = tuple(PROVENANCE_MEANINGS.items())

RANKING = {
    "torque": "lowest torque first, the peak torque the table shows: the largest motor "
    "torque of any moving segment of either move (without a stroke, each at the top "
    "speed) or of starting from rest, rotor included. Equal torques: the larger margin "
    "first.",
    "rms": "lowest RMS motor torque over the cycle first (the motor's continuous duty); "
    "without a move, as the lowest torque. Equal torques: the lower peak torque first.",
    "margin": "the screw furthest from every limit first (lowest worst utilization); "
    "equal margins: the lower torque first.",
    "life": "longest life first, by the low end of the band shown: the seed's rated "
    "life, else the nut's wear life (Archard, at the high end of its wear rate); screws "
    "with neither last; equal lives: the lower torque first.",
    "size": "smallest outer diameter first; equal sizes: the lower torque first.",
    "motor_margin": "the smallest share of the motor used first (its torque, curve, "
    "continuous rating and top speed); without a motor, the lower torque first.",
}

CHARTS = (
    (
        "Critical speed",
        "Each line is one screw size: the speed it may turn at against the "
        "length between supports (log scales). A cross is a screw's operating speed at your "
        "length; it passes while the cross lies below its line. The hover text gives the margin.",
    ),
    (
        "PV limit",
        "Each line is the largest load a nut's PV limit allows at each linear speed. "
        "Your load and speed (the cross) must lie below a nut's line for it to pass.",
    ),
    (
        "Torque breakdown",
        "Stacked bars of the torque while accelerating per screw (inertia, drag and load, "
        "before the torque safety factor); the diamond is the peak torque the torque check "
        "judges (the move's peak or the start from rest); the dashed line is your drive's "
        "maximum torque over the torque safety factor when you give one.",
    ),
    (
        "Lead sweep",
        "The top screw's size with every lead the catalog offers: drive torque, "
        "speed as a share of the allowed critical speed, and PV or an ISO nut's flank "
        "pressure used. The shaded band holds "
        "the leads that still self-lock; the dashed line is the chosen lead.",
    ),
    (
        "Motor torque against speed",
        "Given a stroke and a motor curve: the curve is the torque the motor can give at "
        "each speed; each point is one segment of the move (accelerate, constant, "
        "decelerate) of a screw, at its top speed, or its start from rest (break-away) at "
        "standstill, with the torque safety factor. Points under the line: the motor "
        "drives the move. Beside a continuous rating (dotted), each screw's square is its "
        "cycle's RMS torque as the RMS check judges it.",
    ),
    (
        "The move over time",
        "Given a stroke: the top screw's speed and the motor's torque through one cycle, "
        "out and back (up and down), with the dwells. Negative torque: the motor brakes.",
    ),
)


@router.get("/guide", response_class=HTMLResponse)
async def guide() -> Response:
    """What each check, provenance kind, ranking order and chart means."""
    return HTMLResponse(guide_html())


@cache
def guide_html() -> str:
    """The guide, rendered once: it depends on the code alone (the registry, the tables
    above), not on the query or the catalog."""
    rank_texts = {c.value: c.text for c in BY_API["rank_by"].choices}
    context = {
        "checks": REGISTRY,
        "provenance": PROVENANCE,
        "ranking": [(key, rank_texts[key], text) for key, text in RANKING.items()],
        "columns": COLUMNS,
        "charts": CHARTS,
    }
    return templates.get_template("guide.html").render(context)


@router.get("/validation", response_class=HTMLResponse)
async def validation() -> Response:
    """Every published worked example beside the app's value."""
    return HTMLResponse(validation_html())


@cache
def validation_html() -> str:
    """The validation page, computed and rendered once: the examples, the makers'
    pull-out curves and the formulas they run through are fixed while the process
    runs."""
    rows = [
        {
            "e": e,
            "value": sig(e.value),
            "ratio": f"{e.ratio:.4f}",
            "within": abs(e.ratio - 1) <= TOLERANCE,
        }
        for e in EXAMPLES
    ]
    curves = [
        {
            "c": c,
            "low": f"{min(ratios):.2f}",
            "high": f"{max(ratios):.2f}",
            "within": c.within(ratios),
            "range": c.in_supply_range,
        }
        for c in CURVES
        for ratios in (c.ratios(),)
    ]
    context = {
        "rows": rows,
        "tolerance": f"{TOLERANCE:.0%}",
        "curves": curves,
        "curve_tolerance": f"{PULL_OUT_TOLERANCE:.0%}",
    }
    return templates.get_template("validation.html").render(context)
