"""The motor RMS check offers a lower acceleration only where it lowers the RMS torque.

A lower acceleration lowers each ramp's torque (less m a and spin) but lengthens the
ramps and the cycle: with a dwell that holds nothing (a horizontal axis) the RMS torque
sqrt(sum T_i^2 t_i / sum t_i) (Oriental Motor, Motor Sizing Calculations) can rise.
Tr16x4 bronze, 200 N and 20 kg over a 0.3 m stroke at 0.2 m/s with a 2 s dwell: at
2 m/s^2 the ramps are a small part of the torque, and 1.8 m/s^2 raises the RMS torque
needed from 0.27528 to 0.27560 N m, so the fix no longer offers it; at 10 m/s^2 the ramps
dominate, 9 m/s^2 lowers it (0.2792 to 0.2784 N m), and it is offered.
"""

from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.core.batch import CheckResult
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.phrase import Phrase

AXIS = Application(
    load_n=200.0, speed_m_s=0.2, length_m=0.6, stroke_m=0.3, dwell_s=2.0, moving_mass_kg=20.0,
    motor_rms_torque_nm=0.05, cycles_per_day=100.0,
)  # fmt: skip


def _rms(catalog: Catalog, app: Application) -> CheckResult:
    checks = evaluate(app, catalog.by_id["Tr16x4-bronze"]).checks
    return next(c for c in checks if c.name == "motor_rms")


@pytest.mark.parametrize(("accel", "helps"), [(2.0, False), (10.0, True)])
def test_a_lower_acceleration_is_offered_where_it_lowers_the_rms(
    catalog: Catalog, accel: float, helps: bool
) -> None:
    app = replace(AXIS, accel_m_s2=accel)
    given = _rms(catalog, app)
    slower = _rms(catalog, replace(app, accel_m_s2=0.9 * accel))
    assert not given.passed and given.value is not None and slower.value is not None
    assert (slower.value < given.value) is helps
    assert isinstance(given.fix, Phrase)
    assert ("lower acceleration" in given.fix.template) is helps
    assert "load or moving mass" in given.fix.template
