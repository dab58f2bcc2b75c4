"""A fix never lands on the limit (issue 21, item 6: "never a fix at utilisation 1.0002").

Each check's fix proposes values ``FIX_MARGIN`` inside the limit they are worked out from
(app.core.checks.base ``at_most`` / ``at_least``) and says so. Here the proposed value,
rounded to the four figures the page shows, is put back into the axis and the same screw
evaluated again: the check must then pass with room to spare, never at 1.0002."""

import math
from dataclasses import replace

import numpy as np
from hypothesis import HealthCheck, given, settings

from app.catalog import Catalog
from app.contract.units import render
from app.core.checks.base import FIX_MARGIN, MARGIN_NOTE
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.phrase import Amount
from app.core.selection import screen
from tests.core.conftest import applications, light_app

#: check -> (the fix's value, the axis input it proposes): a shorter length, a lower speed
#: or a lower thrust (the load, where the peak thrust is the load alone).
PROPOSALS = {
    "critical_speed": ("length", "length_m"),
    "buckling": ("length", "length_m"),
    "length": ("cap", "length_m"),
    "max_sliding_speed": ("speed", "speed_m_s"),
    "traverse_speed": ("limit", "speed_m_s"),
    "pv": ("speed", "speed_m_s"),
    "step_rate": ("speed", "speed_m_s"),
    "design_load": ("cap", "load_n"),
    "bearing_pressure": ("cap", "load_n"),
}
#: The largest utilisation a fixed design may show: a linear limit lands at 1 - margin, a
#: length against whirling or buckling at (1 - margin)^2; half the margin leaves rounding room.
WORST_AFTER_FIX = 1.0 - FIX_MARGIN / 2


def shown(value: float) -> float:
    """The value as the page shows it (four significant figures)."""
    return float(f"{value:.4g}")


def fixed_utilizations(
    app: Application, catalog: Catalog, per_check: int = 3
) -> dict[str, list[float]]:
    """For up to ``per_check`` failing screws of each check in ``PROPOSALS``: the check's
    utilisation after the fix's proposed value is applied to the axis."""
    s = screen(app, catalog.index)
    out: dict[str, list[float]] = {}
    for name, (key, field) in PROPOSALS.items():
        failed = s.failed.get(name)
        if failed is None:
            continue
        for i in np.flatnonzero(failed)[:per_check]:
            screw = s.table.screws[i]
            result = next(c for c in evaluate(app, screw).checks if c.name == name)
            assert result.fix is not None
            amount = result.fix.values.get(key)
            if amount is None and name in ("pv", "bearing_pressure") and not result.capacity:
                # derated to nothing at the nut's temperature: no figure to offer
                assert "no PV left" in render(result.fix)
                continue
            assert isinstance(amount, Amount), (name, render(result.fix))
            if amount.value <= 0.0 and key not in result.fix.template:
                continue  # no such length exists, and the sentence offers none
            if field == "load_n" and not math.isclose(result.demand, app.load_n):
                continue  # the peak thrust carries m a or a weight: the load alone is not it
            fixed = replace(app, **{field: shown(amount.value)})  # type: ignore[arg-type]
            again = next(c for c in evaluate(fixed, screw).checks if c.name == name)
            assert "5 % margin" in render(result.fix)
            out.setdefault(name, []).append(
                float("nan") if again.utilization is None else again.utilization
            )
    return out


@settings(
    max_examples=15, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(app=applications)
def test_a_fixed_design_never_sits_on_its_limit(catalog: Catalog, app: Application) -> None:
    for name, found in fixed_utilizations(app, catalog).items():
        assert all(u <= WORST_AFTER_FIX for u in found), (name, found)


#: Axes on which each proposal is made for some screw.
AXES = {
    "whirl-and-buckle": light_app(load_n=2500.0, speed_m_s=0.5, length_m=2.0),
    "long-coated": light_app(length_m=3.0, speed_m_s=0.001, compression=False),
    "fast-fine-lead": light_app(load_n=100.0, speed_m_s=0.2, length_m=0.4),
    "loaded-slow": light_app(load_n=5000.0, speed_m_s=0.0005, length_m=0.4, compression=False),
    "stepper": light_app(
        speed_m_s=0.05, step_angle_deg=1.8, microsteps=256, max_step_rate_hz=20_000.0
    ),
}


def test_every_proposal_is_tried(catalog: Catalog) -> None:
    """Not vacuous: over these axes every check of ``PROPOSALS`` fails for some screw, and
    each fixed design passes within the margin."""
    seen: dict[str, list[float]] = {}
    for app in AXES.values():
        for name, found in fixed_utilizations(app, catalog).items():
            seen.setdefault(name, []).extend(found)
    assert set(seen) == set(PROPOSALS)
    for name, found in seen.items():
        assert found and all(u <= WORST_AFTER_FIX for u in found), (name, found)


def test_the_margin_is_the_one_stated() -> None:
    """The sentence every fix with a figure ends with names the margin the code applies."""
    assert f"{FIX_MARGIN:.0%}".replace("%", " %") in MARGIN_NOTE
