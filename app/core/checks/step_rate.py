"""The step pulse rate the top speed needs against the controller's maximum."""

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
    everywhere,
    most,
    same,
)
from app.core.formulas import geometry, stepping
from app.core.phrase import Amount, Phrase


def steps_per_rev(app: Application) -> float:
    """Step pulses per screw turn for the axis's motor and controller (0 without a step
    angle), for the step checks' sentences."""
    return stepping.steps_per_rev(app.step_angle_deg or 0.0, app.microsteps)


class StepRate(Check):
    name = "step_rate"
    slower_may_clear = True
    label = "Controller step rate"
    description = (
        "The step pulses per second the peak screw speed needs (360 / step angle x "
        "microsteps per turn) against the controller's maximum step rate."
    )
    quantity = "frequency"
    formula = "f = n_peak / 60 * 360 / step_angle * microsteps; f_max = f_ctrl"
    source = "Prusa calculators (steps per mm); kinematics"
    sources = ()

    def applies(self, app: Application) -> bool:
        return app.step_angle_deg is not None and app.max_step_rate_hz is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.motor.step_rate_hz, same(t, app.max_step_rate_hz))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "n_peak": q.motor.peak_rpm,
            "step_angle": app.step_angle_deg,
            "microsteps": app.microsteps,
            "f_ctrl": app.max_step_rate_hz,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "within" if passed else "above"
        return Phrase(
            "{steps} steps per turn at {rpm} need a step rate of {rate}, " + verb + " the "
            "controller's {limit}.",
            {
                "steps": f"{steps_per_rev(app):g}",
                "rpm": Amount(r.motor.peak_rpm, "rpm"),
                "rate": Amount(r.motor.step_rate_hz, "frequency"),
                "limit": Amount(app.max_step_rate_hz or 0.0, "frequency"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        limit = app.max_step_rate_hz or 0.0
        rpm = _limit_rpm(app)
        return Phrase(
            "At a step rate of {limit} the screw may turn {rpm} ({speed} on this lead): "
            "fewer microsteps, a longer lead or a lower speed." + MARGIN_NOTE,
            {
                "limit": Amount(limit, "frequency"),
                "rpm": most(rpm, "rpm"),
                "speed": most(geometry.linear_speed(rpm, s.lead_m), "speed"),
            },
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        """The top speed at the controller's step rate: the speed the fix offers, which a
        cycle a day may refuse (``input_rules.refused`` says so beside the fix)."""
        return {"speed_m_s": geometry.linear_speed(_limit_rpm(app), s.lead_m)}


def _limit_rpm(app: Application) -> float:
    """The screw speed at the controller's highest step rate [rpm]."""
    return (app.max_step_rate_hz or 0.0) / steps_per_rev(app) * stepping.SECONDS_PER_MINUTE
