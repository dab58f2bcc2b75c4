"""Leadscrews and ball screws in one ranking: what the summary says first when one kind
passes and the other does not, or when neither does."""

from collections import Counter
from collections.abc import Sequence

import numpy as np

from app.core.checks import BY_NAME
from app.core.model import Application
from app.core.phrase import Phrase, plural
from app.core.screening import Screening, asked_for
from app.core.table import Mask

#: How many passing ball screws the summary names.
NAMED = 3
NOT_A_SCREW = "a belt drive, a rack and pinion or a linear motor"
#: The shaft's own limits, which any screw of that length, speed and thrust meets, when
#: one excludes the screws of both kinds: what could do it instead.
SHAFT_CHECKS = {
    "critical_speed": "no screw shaft this long turns this fast as mounted; stiffer end "
    "fixing, a screw support or a shorter shaft may (each screw's fix says which), "
    f"otherwise {NOT_A_SCREW} can",
    "buckling": "no screw shaft this long carries this thrust in compression as mounted; "
    "stiffer end fixing, a screw that pulls (tension) or a shorter shaft may (each "
    f"screw's fix says which), otherwise {NOT_A_SCREW} can",
    "root_stress": "no screw's root carries this thrust, whatever its length, speed or "
    "mounting: a larger screw than the catalog's, a roller screw or a hydraulic cylinder",
}


def _most_excluding(sc: Screening, rows: Mask) -> tuple[str, int]:
    """The check that fails the most of ``rows``, and how many it fails."""
    counts = Counter({n: int(np.count_nonzero(m & rows)) for n, m in sc.failed_by_check.items()})
    name, count = counts.most_common(1)[0] if counts else ("", 0)
    return name, count


def _label(name: str) -> str:
    return BY_NAME[name].label if name in BY_NAME else name


def no_leadscrew(sc: Screening, passing_ids: Sequence[str]) -> Phrase | None:
    """When ball screws pass and no leadscrew does (both kinds screened): say so first,
    with the check that excludes the most leadscrews and the passing ball screws, before
    any change of the axis is offered; None otherwise."""
    ball = sc.table.ball
    lead = ~ball
    if not lead.any() or (sc.passed & lead).any() or not (sc.passed & ball).any():
        return None
    name, count = _most_excluding(sc, lead)
    balls = [i for i in passing_ids if sc.table.screws[_position(sc, i)].screw_type == "ball"]
    passing = int(np.count_nonzero(sc.passed & ball))
    return Phrase(
        f"No leadscrew passes: {_label(name)} excludes {count} of {int(lead.sum())} "
        f"leadscrews. {passing} {plural(passing, 'ball screw does', 'ball screws do')}"
        + (f", first {', '.join(balls[:NAMED])}." if balls else ".")
    )


def screened(sc: Screening) -> str:
    """The kind of screw screened: "leadscrew", "ball screw", or "screw" for both."""
    ball = sc.table.ball
    return "ball screw" if ball.all() else "screw" if ball.any() else "leadscrew"


def _position(sc: Screening, screw_id: str) -> int:
    return next(i for i, s in enumerate(sc.table.screws) if s.id == screw_id)


def _only_back_driving(sc: Screening, rows: Mask) -> int:
    """How many of ``rows`` fail the back-driving check and no other."""
    others = np.zeros(len(rows), dtype=bool)
    for name, mask in sc.failed_by_check.items():
        if name != "back_driving":
            others |= mask
    return int(np.count_nonzero(rows & sc.failed_by_check["back_driving"] & ~others))


def neither(app: Application, sc: Screening) -> Phrase | None:
    """When both kinds were screened and none passes: the limit that excludes the most
    ball screws, and what kind of drive could do it; None otherwise. Of the screws the
    application asks for (``screening.asked_for``) where it names some."""
    ball = sc.table.ball
    if not ball.any() or not (~ball).any() or sc.passed.any():
        return None
    name, count = _most_excluding(sc, ball)
    check = BY_NAME.get(name)
    if name.startswith("ball_") and check is not None and check.why_none:
        what = check.why_none
    elif name == "back_driving" and (only := _only_back_driving(sc, ball)):
        what = (
            f"{only} of them {plural(only, 'passes', 'pass')} every other check: a ball "
            "screw with a brake can (each one's fix gives the brake's holding torque)"
        )
    elif name in SHAFT_CHECKS:
        what = SHAFT_CHECKS[name]
    else:
        what = f"its fix names what would clear it, or {NOT_A_SCREW}"
    total = int(ball.sum())
    scope, values = asked_for(app)
    return Phrase(
        f"Neither a leadscrew nor a ball screw {scope or 'in the catalog'} can do this: "
        f"{_label(name)} excludes {count} of {total} ball screws too; {what}.",
        values,
    )
