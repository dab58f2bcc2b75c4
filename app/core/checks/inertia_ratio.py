"""The load's inertia at the motor against the rotor's: a stepper keeps in step, and a
servo stays stable, only while the ratio is moderate (advice)."""

import sys

import numpy as np

from app.core import motion
from app.core.checks.base import (
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
    same,
)
from app.core.phrase import Amount, Phrase

#: Load-to-rotor inertia ratio a stepping motor is sized for (Oriental Motor's guide).
MAX_INERTIA_RATIO = 10.0


class InertiaRatio(Check):
    name = "inertia_ratio"
    label = "Load-to-rotor inertia ratio"
    kind = "advice"
    description = (
        "The screw's inertia, the coupling's and the heaviest moving mass of the cycle's "
        "moves reflected to the screw, over the motor's rotor inertia, against 10: above "
        "it a stepper loses steps in fast starts and stops and a servo needs careful "
        "tuning."
    )
    quantity = "factor"
    formula = "r = (J_screw + J_coupling + m * (lead / (2 * pi))^2) / J_rotor; r_max = 10"
    source = "Oriental Motor, Technical Reference, Motor Sizing Calculations (inertia ratio)"
    sources = ("inertia_per_length",)

    def applies(self, app: Application) -> bool:
        return bool(app.motor_inertia_kg_m2)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        # a rotor too small for any float ratio (5e-324 kg m²) gives an infinite ratio
        with np.errstate(over="ignore"):
            ratio = q.torque.inertia_kg_m2 / (app.motor_inertia_kg_m2 or np.nan)
        return Measure(everywhere(t), ratio, same(t, MAX_INERTIA_RATIO))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "J_screw": t.inertia_kg_m2_per_m * app.length_m,
            "J_coupling": app.coupling_inertia_kg_m2 or 0.0,
            "m": motion.heaviest_mass(app),
            "lead": t.lead_m,
            "J_rotor": app.motor_inertia_kg_m2,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "within" if passed else "above"
        with np.errstate(over="ignore"):
            ratio = r.torque.inertia_kg_m2 / (app.motor_inertia_kg_m2 or np.nan)
        # a rotor of 5e-324 kg m² (a rotor too small for any float ratio): said as such
        ratio_text = f"{ratio:.3g}" if np.isfinite(ratio) else f"over {sys.float_info.max:.3g}"
        return Phrase(
            "The load's {load} at the motor is {ratio} times the rotor's {rotor}, "
            + verb
            + " the guide of {limit}.",
            {
                "load": Amount(r.torque.inertia_kg_m2, "inertia"),
                "ratio": ratio_text,
                "rotor": Amount(app.motor_inertia_kg_m2 or 0.0, "inertia"),
                "limit": f"{MAX_INERTIA_RATIO:g}",
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "A motor with a larger rotor, a shorter lead (the mass reflects with the lead "
            "squared), or a lighter moving mass."
        )
