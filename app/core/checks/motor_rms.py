"""The RMS torque of the cycle against the motor's continuous rating (its heating)."""

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
    everywhere,
    lighter,
    same,
)
from app.core.phrase import Amount, Phrase


class MotorRms(Check):
    name = "motor_rms"
    why_none = "the motor's RMS torque is too low for every screw: a larger motor"
    judges_motor = True
    label = "Motor RMS torque"
    description = (
        "The root-mean-square motor torque over the cycle (out and back, or the moves given, "
        "with the dwells), "
        "times the torque safety factor, against the motor's continuous torque rating."
    )
    quantity = "torque"
    capacity_given = "motor_rms_torque"
    formula = "T_need = SF * T_rms; T_motor = T_continuous"
    source = "RMS torque sqrt(sum T_i^2 t_i / sum t_i), e.g. Oriental Motor, Motor Sizing"
    sources = ("inertia_per_length", "drag_torque", "friction_dynamic")

    def applies(self, app: Application) -> bool:
        return app.motor_rms_torque_nm is not None and (app.stroke_m is not None or bool(app.moves))

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.motor.motor_rms_needed_nm, same(t, app.motor_rms_torque_nm))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "SF": app.torque_safety_factor,
            "T_rms": q.motor.motor_rms_nm,
            "T_continuous": app.motor_rms_torque_nm,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "The cycle's RMS torque {need} " + verb + " the motor's continuous {rating}.",
            {
                "need": Amount(r.motor.motor_rms_needed_nm, "torque"),
                "rating": Amount(app.motor_rms_torque_nm or 0.0, "torque"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        less = lighter(app)
        return Phrase(
            "A motor rated for at least {need} continuous, or a longer dwell, lower "
            "acceleration" + (" or " + less if less else "") + "." + MARGIN_NOTE,
            {"need": Amount(at_least(r.motor.motor_rms_needed_nm), "torque")},
        )
