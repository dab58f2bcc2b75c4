"""Every segment of the move under the motor's torque-speed curve."""

import math

from app.core import motion
from app.core.checks.base import (
    MARGIN_NOTE,
    Application,
    Array,
    CandidateTable,
    Check,
    Mapping,
    Measure,
    Quantities,
    Reach,
    ScrewSpec,
    at_least,
    at_most,
    everywhere,
)
from app.core.phrase import Amount, Phrase


def worst_segment(app: Application, r: Quantities[float]) -> str:
    """The segment that uses the most of the curve, in words ("accelerate up")."""
    p = motion.move_profile(app)
    if p is None or r.motor_worst_segment < 0:
        return "move at the top speed"
    names = [(name, d) for d, _ in motion.directions(app) for name in motion.ORDER]
    name, direction = names[int(r.motor_worst_segment)]
    return f"{name} {direction}"


def accel_that_fits(r: Quantities[float]) -> float | None:
    """The acceleration at which the accelerate segment fits the curve, when that segment
    governs [m/s^2] (``Quantities.motor_fitting_accel_m_s2``; None: none fits)."""
    accel = r.motor_fitting_accel_m_s2
    return None if math.isnan(accel) else accel


class MotorCurve(Check):
    name = "motor_curve"
    label = "Motor torque-speed curve"
    description = (
        "Each segment of the move (accelerate, constant, decelerate, dwell; both ways) "
        "needs, times the torque safety factor, at most the torque the motor's curve gives "
        "at that segment's top speed; the segment nearest its curve is shown."
    )
    quantity = "torque"
    formula = "T_need = SF * T_seg; T_motor = T_curve"
    source = "Shigley sec. 8-2 (thread torque by the flow of power); motor torque-speed curve"
    sources = ("inertia_per_length", "drag_torque", "friction_dynamic")

    def applies(self, app: Application) -> bool:
        return bool(app.motor_curve)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.motor_worst_needed_nm, q.motor_curve_nm)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "SF": app.torque_safety_factor,
            "T_seg": q.motor_worst_nm,
            "T_curve": q.motor_curve_nm,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "The {segment} segment needs {need} at {rpm}, which " + verb + " the motor's "
            "{curve} there.",
            {
                "segment": worst_segment(app, r),
                "need": Amount(r.motor_worst_needed_nm, "torque"),
                "rpm": Amount(r.motor_worst_rpm, "rpm"),
                "curve": Amount(r.motor_curve_nm, "torque"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        values: dict[str, Amount | str] = {
            "short": Amount(r.motor_worst_needed_nm - r.motor_curve_nm, "torque"),
            "need": Amount(at_least(r.motor_worst_needed_nm), "torque"),
            "rpm": Amount(r.motor_worst_rpm, "rpm"),
            "segment": worst_segment(app, r),
        }
        accel = accel_that_fits(r)
        if accel is None:
            return Phrase(
                "The {segment} segment is {short} short: a motor giving {need} at {rpm}, or "
                "a lower speed, acceleration or load." + MARGIN_NOTE,
                values,
            )
        values["accel"] = Amount(at_most(accel), "accel")
        return Phrase(
            "The {segment} segment is {short} short: an acceleration of at most {accel}, "
            "or a motor giving {need} at {rpm}." + MARGIN_NOTE,
            values,
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float] | None:
        accel = accel_that_fits(r)
        return None if accel is None else {"accel_m_s2": accel}
