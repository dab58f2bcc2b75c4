"""Drive torque against the torque the drive offers (when the user gives it)."""

import numpy as np

from app.core import segments
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
    least,
    lighter,
    same,
    searched_limits,
    value_alone,
)
from app.core.model import FIX_MARGIN
from app.core.phrase import Amount, Phrase


class DriveTorque(Check):
    name = "torque"
    why_none = "the motor is too small for every screw: a larger motor or a gearbox"
    judges_motor = True
    label = "Drive torque"
    description = (
        "The torque the screw needs, with the torque safety factor, against the drive: the "
        "largest of break-away and every moving segment of both moves (accelerate, "
        "constant, decelerate), each the thrust through the thread, the drag and the "
        "screw's and the rotor's inertia times the angular acceleration."
    )
    quantity = "torque"
    formula = "T_req = SF * max(T_move, T_breakaway); T_available = T_drive"
    source = (
        "seed catalog, Torque (inertia + static drag + load), with static friction; "
        "Shigley sec. 8-2 (thread torque by the flow of power)"
    )
    sources = ("inertia_per_length", "drag_torque", "friction_dynamic", "friction_static")

    def applies(self, app: Application) -> bool:
        return app.max_torque_nm is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.torque.required_nm, same(t, app.max_torque_nm))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "SF": app.torque_safety_factor,
            "T_move": np.max([np.abs(m[3]) for m in segments.moving_torques(app, t)], axis=0),
            "T_breakaway": q.torque.breakaway_nm,
            "T_drive": app.max_torque_nm,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "{req} required " + verb + " the {avail} available.",
            {
                "req": Amount(r.torque.required_nm, "torque"),
                "avail": Amount(app.max_torque_nm, "torque"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        less = lighter(app)
        alone, values = value_alone(app, self.limits(app, s, 1.0 / (1.0 + FIX_MARGIN)))
        return Phrase(
            "A drive of at least {req}, or a shorter lead, lower "
            + (less + " or " if less else "")
            + "acceleration."
            + alone
            + MARGIN_NOTE,
            {"req": least(r.torque.required_nm, "torque"), **values},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float] | None:
        return self.limits(app, s) or None

    def limits(self, app: Application, s: ScrewSpec, share: float = 1.0) -> dict[str, float]:
        """The largest acceleration and the largest load at which the required torque
        SF * max(T_move, T_breakaway) meets ``share`` of T_drive [m/s^2, N], each found by
        working the torque again (``searched_limits``: the thread, drag and inertia
        torques of ``drive.torques`` and ``segments.moving_torques``, affine in each but
        for the thread's change of direction); none in a cycle of moves, whose own
        accelerations and loads these inputs do not set."""
        if app.moves:
            return {}
        return searched_limits(self, app, s, ("accel_m_s2", "load_n"), share=share, convex=True)
