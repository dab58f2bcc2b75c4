"""On a vertical axis, the load must not drive the screw down: the thread self-locks."""

import math

import numpy as np

from app.core.checks import register
from app.core.checks.base import (
    Application,
    Array,
    CandidateTable,
    Check,
    Mapping,
    Measure,
    Quantities,
    ScrewSpec,
    everywhere,
)
from app.core.formulas import efficiency, geometry
from app.core.phrase import Amount, Phrase


@register
class BackDriving(Check):
    name = "back_driving"
    label = "Back-driving (vertical axis)"
    description = (
        "On a vertical axis the load pushes the nut down; a thread whose lead angle is "
        "below its static friction angle holds it (self-locking), otherwise a brake must."
    )
    quantity = "length"
    formula = "lead = lead_screw; lead_max = pi * d_p * mu_s / cos(a_n)"
    source = "Shigley's Mechanical Engineering Design, sec. 8-2 (self-locking condition)"
    sources = ("friction_static", "thread_half_angle")
    order = 100

    def applies(self, app: Application) -> bool:
        return app.orientation == "vertical"

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), t.lead_m, t.max_self_locking_lead_m)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "lead_screw": t.lead_m,
            "d_p": t.pitch_diameter_m,
            "mu_s": np.array([s.friction_static for s in t.screws]),
            "a_n": np.array([s.thread_half_angle_rad for s in t.screws]),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if passed:
            return Phrase("Self-locking: the load cannot drive the screw down.")
        return Phrase(
            "Back-drivable: the load can drive the screw down; holding torque {seed} (seed "
            "method), {physics} (physics).",
            {
                "seed": Amount(r.holding_seed_nm, "torque"),
                "physics": Amount(r.holding_physics_nm, "torque"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float]) -> Phrase:
        d_p = geometry.pitch_diameter(s.outer_diameter_m, s.root_diameter_m)
        lead = efficiency.max_self_locking_lead(
            d_p, s.friction_static, math.cos(s.thread_half_angle_rad)
        )
        return Phrase(
            "Fit a brake of at least {brake} or use a lead of at most {lead}.",
            {"brake": Amount(r.brake_nm, "torque"), "lead": Amount(lead, "length")},
        )
