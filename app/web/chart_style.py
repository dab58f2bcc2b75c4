"""What every chart shares: colours, axes (labelled log ticks) and the layout."""

import math
from collections.abc import Iterable, Sequence
from typing import Any

from app.contract.figures import sig

#: Okabe-Ito colours: distinguishable with the common colour-vision deficiencies.
PALETTE = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000")
#: mantissas labelled on log axes within each decade.
LOG_STEPS = (1.0, 2.0, 5.0)
#: a log axis whose 1-2-5 labels would number more than this labels its decades alone.
LOG_LABELS_MAX = 8


def rounded(value: float) -> float:
    """A chart value to 5 significant figures (smaller JSON, no float noise)."""
    return float(f"{value:.5g}")


def _decade_ticks(low: float, high: float, steps: tuple[float, ...]) -> list[float]:
    """The ticks of ``steps`` in each decade from the one below ``low`` to the one above
    ``high``, trimmed to the nearest tick outside each end."""
    ticks = [
        float(f"{step * 10.0**exponent:.6g}")
        for exponent in range(math.floor(math.log10(low)) - 1, math.ceil(math.log10(high)) + 1)
        for step in steps
    ]
    below = max((t for t in ticks if t <= low), default=ticks[0])
    above = min((t for t in ticks if t >= high), default=ticks[-1])
    return [t for t in ticks if below <= t <= above]


def log_ticks(values: Iterable[float]) -> tuple[list[float], list[str]]:
    """Tick positions and labels for a log axis over ``values``: every decade and the 2 and
    5 between, so a reader never has to count unlabelled gridlines; the decades alone
    where those would be more than ``LOG_LABELS_MAX`` labels, which would crowd a phone's
    or a printed chart (``minor_log_ticks`` keeps the 2 and 5 as gridlines).

    An infinite value (a share of a limit that is zero: a polymer nut past its
    temperature) has no place on a log axis and is left out, as is zero.

    >>> log_ticks([30.0, 700.0])
    ([20.0, 50.0, 100.0, 200.0, 500.0, 1000.0], ['20', '50', '100', '200', '500', '1000'])
    >>> log_ticks([math.inf, 100.0])
    ([100.0], ['100'])
    >>> log_ticks([150.0, 90000.0])
    ([100.0, 1000.0, 10000.0, 100000.0], ['100', '1000', '10000', '100000'])
    """
    positive = [v for v in values if 0 < v < math.inf]
    if not positive:
        return [], []
    low, high = min(positive), max(positive)
    shown = _decade_ticks(low, high, LOG_STEPS)
    if len(shown) > LOG_LABELS_MAX:
        shown = _decade_ticks(low, high, (1.0,))
    return shown, [sig(t, 3) for t in shown]


def minor_log_ticks(values: Iterable[float], labelled: Sequence[float]) -> list[float]:
    """The 2 and 5 of each decade over ``values`` that carry no label: gridlines only."""
    positive = [v for v in values if 0 < v < math.inf]
    if not positive:
        return []
    ticks = _decade_ticks(min(positive), max(positive), LOG_STEPS)
    return [t for t in ticks if t not in labelled]


def axis(title: str, log: bool = False, values: Iterable[float] = ()) -> dict[str, Any]:
    """An axis with its title; a log axis labels each decade and the 2 and 5 between.

    The margins grow to hold the tick labels (``automargin``), so no label reaches past
    the chart's edge: Plotly is told so (``ticklabeloverflow``), rather than measuring
    every label on every draw to hide those that would (its default for numeric axes,
    measured at a fifth to a third of the time a chart takes to draw in Chromium)."""
    spec: dict[str, Any] = {
        "title": {"text": title},
        "automargin": True,
        "ticklabeloverflow": "allow",
        "zeroline": False,
    }
    if log:
        values = list(values)
        tickvals, ticktext = log_ticks(values)
        spec.update(type="log", tickvals=tickvals, ticktext=ticktext, gridcolor="#e6e6e6")
        minor = minor_log_ticks(values, tickvals)
        if minor:
            spec["minor"] = {"tickvals": minor, "showgrid": True, "gridcolor": "#f2f2f2"}
    return spec


def layout(xaxis: dict[str, Any], yaxis: dict[str, Any], **extra: Any) -> dict[str, Any]:
    """The layout every chart shares: white, compact, the legend below the plot (clear of
    the toolbar)."""
    return {
        "xaxis": xaxis,
        "yaxis": yaxis,
        "margin": {"l": 8, "r": 8, "t": 36, "b": 8},
        "legend": {
            "orientation": "h",
            "x": 0,
            "y": 0,
            "yref": "container",
            "yanchor": "bottom",
            "traceorder": "normal",
        },
        "font": {"size": 12},
        "hovermode": "closest",
        "autosize": True,
        "paper_bgcolor": "#ffffff",
        "plot_bgcolor": "#ffffff",
        **extra,
    }
