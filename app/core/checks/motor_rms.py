"""The RMS torque of the cycle against the motor's continuous rating (its heating)."""

from dataclasses import replace

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
    everywhere,
    least,
    lighter,
    same,
    searched_limits,
    value_alone,
)
from app.core.dry_run import as_run
from app.core.model import FIX_MARGIN
from app.core.phrase import Amount, Phrase
from app.core.quantities import operating_point
from app.core.segments import continuous_rating


class MotorRms(Check):
    name = "motor_rms"
    why_none = "the motor's RMS torque is too low for every screw: a larger motor"
    judges_motor = True
    label = "Motor RMS torque"
    description = (
        "The root-mean-square motor torque over the cycle (out and back, or the moves given, "
        "with the dwells), "
        "times the torque safety factor, against the motor's continuous torque rating; "
        "where the motor's continuous duty zone narrows with speed, each segment's torque "
        "is first scaled by the rating over the continuous torque at its speed."
    )
    quantity = "torque"
    capacity_given = "motor_rms_torque"
    formula = "T_need = SF * T_rms_zone; T_motor = T_c0"
    source = (
        "RMS torque sqrt(sum T_i^2 t_i / sum t_i), e.g. Oriental Motor, Motor Sizing; held "
        "within the continuous duty zone, Yaskawa Sigma-II manual sec. 3.2.3"
    )
    sources = ("inertia_per_length", "drag_torque", "friction_dynamic")

    def applies(self, app: Application) -> bool:
        rated = continuous_rating(app) is not None
        return rated and (app.stroke_m is not None or bool(app.moves))

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.motor.motor_rms_needed_nm, same(t, continuous_rating(app)))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "SF": app.torque_safety_factor,
            # T_c0 sqrt(sum (T_i / T_c(n_i))^2 t_i / sum t_i), T_c the continuous duty zone
            # at each segment's speed: the plain RMS torque where the zone is flat
            "T_rms_zone": q.motor.motor_rms_zone_nm,
            "T_c0": continuous_rating(app),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        zone = ""
        values: dict[str, Amount | str] = {
            "need": Amount(r.motor.motor_rms_needed_nm, "torque"),
            "rating": Amount(continuous_rating(app) or 0.0, "torque"),
        }
        if app.motor_rms_curve:
            top_rpm, top_nm = app.motor_rms_curve[-1]
            zone = (
                ", each segment's torque scaled up where the continuous zone narrows with "
                "speed (to {top_nm} at {top_rpm} rpm)"
            )
            values |= {"top_nm": Amount(top_nm, "torque"), "top_rpm": f"{top_rpm:g}"}
        return Phrase(
            "The cycle's RMS torque {need}" + zone + ", " + verb + " the motor's continuous "
            "{rating}.",
            values,
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        less = lighter(app)
        options = ["a longer dwell"] if dwell_helps(app, r) else []
        lower = (["acceleration"] if acceleration_helps(app, s) else []) + ([less] if less else [])
        options += ["lower " + " or ".join(lower)] if lower else []
        alone, values = value_alone(app, self.limits(app, s, r, 1.0 / (1.0 + FIX_MARGIN)))
        return Phrase(
            "A motor rated for at least {need} continuous"
            + "".join((", or " if i == 0 else ", ") + o for i, o in enumerate(options))
            + "."
            + alone
            + MARGIN_NOTE,
            {"need": least(r.motor.motor_rms_needed_nm, "torque"), **values},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float] | None:
        return self.limits(app, s, r) or None

    def limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float], share: float = 1.0
    ) -> dict[str, float]:
        """The acceleration below the one given and the dwell above it at which the
        cycle's RMS torque SF * T_rms_zone meets ``share`` of the rating T_c0 [m/s^2, s],
        each found by working the cycle again (``searched_limits``: ``segments.rms``
        sqrt(sum T_i^2 t_i / sum t_i) over ``segments.segments``, whose ramps lengthen as
        the acceleration falls, so that the RMS need not fall with it: the nearest
        acceleration that passes, stepping down from the one given); the dwell only where
        it can help (``dwell_helps``). None in a cycle of moves, whose own accelerations
        and dwells these inputs do not set."""
        if app.moves:
            return {}
        longer = ("dwell_s",) if dwell_helps(app, r) else ()
        return searched_limits(self, app, s, ("accel_m_s2",), longer, share)


def dwell_helps(app: Application, r: Quantities[float]) -> bool:
    """Whether a longer dwell can bring the RMS torque within the rating with the fix's
    margin. A longer dwell draws the RMS towards the torque held in it, never below: the
    holding torque where the axis holds a load and does not self-lock (``segments``: a
    dwell holds its move's load at rest, at most the steady load's ``brake_nm``), else
    none. Held at standstill, where the continuous zone is the rating T_c0, it helps only
    when SF * T_dwell * (1 + margin) < T_c0. In a cycle of moves a dwell may hold a
    lighter load than the steady one, so a dwell stays offered there."""
    rating = continuous_rating(app)
    if rating is None or app.moves or not motion.holds_a_load(app):
        return True
    return at_least(app.torque_safety_factor * r.holding.brake_nm) < rating


#: The share of the acceleration at which ``acceleration_helps`` works the cycle again.
SLOWER = 0.9


def acceleration_helps(app: Application, s: ScrewSpec) -> bool:
    """Whether a lower acceleration lowers the RMS torque: each ramp's torque falls (less
    m a and spin), but the ramps last longer and the cycle with them, so that a cycle
    whose dwells hold little (or whose ramps are a small part of its torque) can come out
    with a higher RMS torque (sum T_i^2 t_i / sum t_i). Judged by working this screw's
    cycle out again with every acceleration and deceleration at ``SLOWER`` times its own,
    beside the cycle as given worked out the same way (the screw's row built again)."""
    moves = tuple(
        replace(m, accel_m_s2=SLOWER * m.accel_m_s2, decel_m_s2=SLOWER * m.decel_m_s2)
        for m in app.moves
    )
    decel = None if app.decel_m_s2 is None else SLOWER * app.decel_m_s2
    slower = replace(app, accel_m_s2=SLOWER * app.accel_m_s2, decel_m_s2=decel, moves=moves)
    row = as_run(app, CandidateTable.build([s]))
    needed = [operating_point(a, row).motor.motor_rms_needed_nm[0] for a in (app, slower)]
    return bool(needed[1] < needed[0])
