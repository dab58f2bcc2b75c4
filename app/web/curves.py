"""What several charts share: lines spaced evenly in log about the user's value, and the
screws grouped by the curve they share, each curve named by its screws."""

from collections.abc import Callable, Sequence

from app.contract.schemas import CandidateOut
from app.web.chart_style import rounded as _round

CURVE_POINTS = 41
#: at most this many distinct curves on one chart
TOP = 5


def span(centre: float, factor: float) -> list[float]:
    """CURVE_POINTS values spaced evenly in log from centre / factor to centre * factor."""
    steps = CURVE_POINTS - 1
    return [centre * factor ** (2 * i / steps - 1) for i in range(CURVE_POINTS)]


def by_curve(
    candidates: Sequence[CandidateOut], key: Callable[[CandidateOut], float | None]
) -> list[list[CandidateOut]]:
    """The first TOP distinct curves among ``candidates``, each with the screws it holds:
    screws of one size and nut share a curve, and draw it once under all their ids."""
    groups: dict[float, list[CandidateOut]] = {}
    for c in candidates:
        value = key(c)
        if value is None:
            continue
        rounded = _round(value)
        if rounded in groups or len(groups) < TOP:
            groups.setdefault(rounded, []).append(c)
    return list(groups.values())


def curve_name(group: Sequence[CandidateOut]) -> str:
    """Legend text of a shared curve: the series, then each screw's id after it.

    The ids are kept whole when they do not start with the series.
    """
    series = group[0].series
    rest = [c.id.removeprefix(series).lstrip("-") or c.id for c in group]
    return (
        f"{series}: {', '.join(rest)}"
        if all(c.id.startswith(series) for c in group)
        else (", ".join(c.id for c in group))
    )
