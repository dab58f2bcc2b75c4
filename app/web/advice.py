"""What to change when nothing passes, as a short list the engineer can act on.

The core's summary gives the remedies (``summary.remedies``, API names and units): changes
of one input or several, or of the mounting, each 5 % past the limits it clears and
verified by selecting again with it made; or, when none is found, why no leadscrew can do
it (``summary.impossible``). The page shows each remedy with an Apply link (the share link
of the same inputs with that change made, each number rounded towards the side that
clears) and the nearest screw's failed checks by their labels, so no internal name
reaches the reader.
"""

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from pydantic import ValidationError

from app.contract.exact import page_value
from app.contract.fields import BY_API
from app.contract.figures import round_towards, sig
from app.contract.outputs import PageSelectionOut, SelectOut
from app.contract.schemas import ApplicationIn, CandidateOut
from app.contract.share_link import share_query
from app.core.checks import BY_NAME
from app.core.remedy import MARGIN
from app.core.wording import percent

#: significant figures of a proposed value, rounded towards the side that still clears.
PROPOSAL_DIGITS = 3


@dataclass(frozen=True, slots=True)
class Change:
    """One proposed input change: what the reader sees and the link that makes it."""

    field: str
    label: str
    verb: str
    value: str
    unit: str
    href: str


@dataclass(frozen=True, slots=True)
class RemedyLink:
    """A verified remedy: its changes in words, the link that makes them all, how many
    screws then pass and the lowest governing utilization among them."""

    changes: tuple[Change, ...]
    href: str
    passing: int
    utilization: str

    @property
    def fields(self) -> str:
        """The page fields it changes, space-separated."""
        return " ".join(c.field for c in self.changes)


@dataclass(frozen=True, slots=True)
class FailedCheck:
    """A failed check of the nearest screw: its label and what would clear it."""

    name: str
    label: str
    fix: str


def check_label(name: str | None) -> str:
    """The reader's name of a check ('Critical speed'); unknown names made readable."""
    if name is None:
        return ""
    check = BY_NAME.get(name)
    return check.label if check is not None else name.replace("_", " ")


def _link(inputs: ApplicationIn, changes: Mapping[str, float | str], units: dict[str, str]) -> str:
    """The page link of ``inputs`` with ``changes`` (API names, API units) made."""
    changed = ApplicationIn.model_validate({**inputs.model_dump(), **changes})
    return "/?" + share_query(changed, units)


def proposal(inputs: ApplicationIn, api: str, target: float, units: dict[str, str]) -> float:
    """The proposed API value: the target rounded in display units towards the safe side,
    kept within the field's bounds (the target lies within them, so the bound still clears)."""
    field = BY_API[api]
    current = float(getattr(inputs, api))
    shown = field.display_value(target, units)
    rounded = round_towards(float(shown), target < current, PROPOSAL_DIGITS)
    value = page_value(field, repr(rounded), units)  # as the page reads the rounded text
    low, high = field.bounds or (-math.inf, math.inf)
    return min(max(value, low), high)


def remedy_change(
    inputs: ApplicationIn, api: str, value: float | str, units: dict[str, str]
) -> tuple[Change, float | str]:
    """One input of a remedy in words, and the API value its link carries (a number
    rounded in display units towards the side that clears)."""
    field = BY_API[api]
    if isinstance(value, str):
        text = field.choice_text(value)
        return Change(field.page, field.label, "Mount the ends", text, "", ""), value
    number = proposal(inputs, api, value, units)
    lower = number < float(getattr(inputs, api))
    shown = sig(float(field.display_value(number, units)))
    verb = "Reduce" if lower else "Raise"
    return Change(field.page, field.label, verb, shown, field.display_unit(units), ""), number


def remedy_links(result: SelectOut | PageSelectionOut, units: dict[str, str]) -> list[RemedyLink]:
    """Each remedy of the summary with the link that makes it."""
    links = []
    for remedy in result.summary.remedies:
        made = [remedy_change(result.inputs, api, v, units) for api, v in remedy.inputs.items()]
        values = [value for _, value in made]
        try:
            href = _link(result.inputs, dict(zip(remedy.inputs, values, strict=True)), units)
        except ValidationError:  # rounded for the page, it no longer fits the other inputs
            continue
        links.append(
            RemedyLink(
                changes=tuple(change for change, _ in made),
                href=href,
                passing=remedy.passing,
                utilization=percent(remedy.utilization),
            )
        )
    return links


def failed_checks(candidate: CandidateOut | None) -> list[FailedCheck]:
    """The failed checks of ``candidate`` by label, each with its fix."""
    if candidate is None:
        return []
    return [
        FailedCheck(name=k.name, label=k.label, fix=k.fix or "")
        for k in candidate.checks
        if not k.passed
    ]


def nearest(result: SelectOut | PageSelectionOut) -> CandidateOut | None:
    """The rejected screw closest to passing, the one the summary's changes are for."""
    best = result.summary.best_rejected_id
    return next((c for c in result.rejected if c.id == best), None) or (
        result.rejected[0] if result.rejected else None
    )


def no_pass_advice(result: SelectOut | PageSelectionOut, units: dict[str, str]) -> dict[str, Any]:
    """Everything the 'nothing passes' notice shows."""
    best = nearest(result)
    most = result.summary.most_excluding_check
    return {
        "most_label": check_label(most),
        "most_count": result.counts.failed_by_check.get(most, 0) if most else 0,
        "nearest": best,
        "remedies": remedy_links(result, units),
        "impossible": result.summary.impossible,
        "margin": f"{MARGIN * 100:.0f} %",
        "failed": failed_checks(best),
    }
