"""The move's top speed inside the motor's torque-speed curve."""

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
    most,
    same,
)
from app.core.formulas import geometry
from app.core.phrase import Amount, Phrase


def top_curve_rpm(app: Application) -> float:
    """The curve's last speed: the motor cannot run faster [rpm]."""
    return app.motor_curve[-1][0]


class MotorSpeed(Check):
    name = "motor_speed"
    slower_may_clear = True
    why_none = "the motor cannot turn fast enough for every lead: a faster motor"
    judges_motor = True
    label = "Motor speed"
    description = (
        "The screw's top speed in the move (the triangle's peak when the stroke is short) "
        "within the motor curve's last point: past it the motor cannot go."
    )
    quantity = "rpm"
    capacity_given = "motor_curve"
    formula = "n = 60 * v_peak / lead; n_motor = n_curve_max"
    source = "screw kinematics n = 60 v / lead; motor torque-speed curve"
    sources = ()

    def applies(self, app: Application) -> bool:
        return bool(app.motor_curve)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.motor.peak_rpm, same(t, top_curve_rpm(app)))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "v_peak": geometry.linear_speed(q.motor.peak_rpm, t.lead_m),
            "lead": t.lead_m,
            "n_curve_max": top_curve_rpm(app),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "The top speed {rpm} " + verb + " the motor curve's last point, {top}.",
            {"rpm": Amount(r.motor.peak_rpm, "rpm"), "top": Amount(top_curve_rpm(app), "rpm")},
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        values = {"speed": most(geometry.linear_speed(top_curve_rpm(app), s.lead_m), "speed")}
        # the lead the size is made in that turns the screw slowly enough, when made
        needed = at_least(r.motor.peak_rpm * s.lead_m / top_curve_rpm(app))
        lead = reach.made_lead(s, needed, larger=True)
        if lead is None or lead > reach.max_lead_m:
            return Phrase("A speed of at most {speed}, or a faster motor." + MARGIN_NOTE, values)
        return Phrase(
            "A speed of at most {speed}, a lead of at least {lead}, or a faster motor."
            + MARGIN_NOTE,
            {**values, "lead": Amount(lead, "length")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float] | None:
        return {"speed_m_s": geometry.linear_speed(top_curve_rpm(app), s.lead_m)}
