"""Stress at the root section under the peak thrust and the torque the screw carries with
it (von Mises) against the screw's yield."""

import numpy as np

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
    load_input,
    makers_stress,
    where_given,
)
from app.core.formulas import buckling
from app.core.phrase import Amount, Phrase


class RootStress(Check):
    name = "root_stress"
    why_none = "the thrust and the torque it takes yield every screw's root: consider a ball screw"
    why_none_ball = (
        "the thrust and the torque it takes yield every ball screw's root: consider a "
        "roller screw or a hydraulic cylinder"
    )
    label = "Root stress (yield)"
    description = (
        "The root section of the screw under the peak thrust, pushed or pulled, and the "
        "torque it carries with it (the thread's torque for that thrust, the nut's drag and "
        "the screw's own inertia torque), combined by von Mises, against a fraction (the "
        "buckling factor) of the screw material's yield strength; a ball screw's whose "
        "family declares no buckling rule at most THK's permissible P2 = 116 d1^2 N, "
        "147.7 MPa on the root area."
    )
    quantity = "pressure"
    formula = (
        "sigma_vm = sqrt((F_peak / (pi * d_r^2 / 4))^2 + 3 * (16 * T_root / (pi * d_r^3))^2); "
        "sigma_allowed = min(SF * S_y, sigma_m)"
    )
    source = (
        "Shigley's Mechanical Engineering Design, 9th ed., eqs. (8-7), (8-8) (body stresses "
        "of a power screw) and (5-15) (von Mises); yield strength from the material "
        "(handbook); a ball screw's whose family declares no buckling rule at most THK's "
        "P2 = 116 d1^2 N (General Catalog, Ball Screw, A15-30, formula 6), sigma_m = "
        "147.7 MPa"
    )
    sources = ("root_diameter", "yield_strength", "friction_static", "friction_dynamic")
    capacity_sources = ("yield_strength",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        allowed = np.minimum(app.buckling_safety_factor * t.yield_strength_pa, t.makers_stress_pa)
        return Measure(where_given(allowed), q.column.root_stress_pa, allowed)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "F_peak": q.axis.peak_force_n,
            "d_r": t.root_diameter_m,
            "T_root": q.column.root_torque_nm,
            "SF": app.buckling_safety_factor,
            "S_y": t.yield_strength_pa,
            # the makers' allowed root stress (inf: none published)
            "sigma_m": t.makers_stress_pa,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        capped = makers_stress(s) < app.buckling_safety_factor * (s.yield_strength_pa or 0.0)
        limit = "THK's P2 = 116 d1^2 N, below {sf} x yield {s_y}" if capped else ""
        return Phrase(
            "{stress} at the root (von Mises of {sigma} axial under the peak thrust and "
            "{tau} shear from the {torque} the screw carries with it) " + verb + " {allowed} "
            "(" + (limit or "{sf} x yield {s_y}") + ").",
            {
                "stress": Amount(r.column.root_stress_pa, "pressure"),
                "sigma": Amount(r.column.root_axial_stress_pa, "pressure"),
                "tau": Amount(r.column.root_shear_stress_pa, "pressure"),
                "torque": Amount(r.column.root_torque_nm, "torque"),
                "allowed": Amount(_allowed(app, s), "pressure"),
                "sf": Amount(app.buckling_safety_factor, "factor"),
                "s_y": Amount(s.yield_strength_pa or 0.0, "pressure"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        d_min = at_least(s.root_diameter_m * (r.column.root_stress_pa / _allowed(app, s)) ** 0.5)
        if d_min > reach.max_root_diameter_m:
            return Phrase("Reduce the load or the moving mass's acceleration.")
        return Phrase(
            "Use a root diameter of at least {d}, or reduce the load." + MARGIN_NOTE,
            {"d": Amount(d_min, "length", "up")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        if not r.axis.peak_force_n > 0.0:
            return {}
        # T_root = a F + b: the thread's torque grows with the thrust, drag and inertia not
        fixed_nm = r.torque.drag_nm + abs(r.torque.inertia_screw_nm)
        per_n = (r.column.root_torque_nm - fixed_nm) / r.axis.peak_force_n
        allowed_n = buckling.largest_root_load(_allowed(app, s), s.root_diameter_m, per_n, fixed_nm)
        return load_input(app, allowed_n)


def _allowed(app: Application, s: ScrewSpec) -> float:
    """Allowed root stress [Pa]: the buckling factor times the yield strength, at most the
    makers' (``makers_stress``)."""
    return min(app.buckling_safety_factor * (s.yield_strength_pa or 0.0), makers_stress(s))
