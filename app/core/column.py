"""The screw as a shaft and a column for many candidates at once: its critical speed over its
length, its buckling load over the span from the thrust bearing to the nut (Euler or
Johnson), and the stress at its root under the peak thrust and the torque it carries.
"""

from typing import Any

import numpy as np

from app.core.formulas import (
    buckling,
    column_rules,
    critical_speed,
    torque,
)
from app.core.model import Application
from app.core.table import Array, CandidateTable, filled


def root_torque(t: CandidateTable, peak_n: float, torques: dict[str, Any]) -> Array:
    """``torque.root_torque`` at the peak thrust, at the lower of the running and the
    static efficiency (the thrust of a start from rest passes the thread at static
    friction), with the nut's drag and the whole screw's inertia torque [N m]."""
    return np.asarray(
        torque.root_torque(
            peak_n, t.lead_m, t.root_efficiency, torques["drag_nm"], torques["inertia_screw_nm"]
        )
    )


def column_length(app: Application) -> float:
    """The length of the screw that buckles [m]: from the thrust bearing to the nut at its
    farthest when that span is given (THK, Ball Screw "Method for Mounting the Ball Screw
    Shaft": the buckling load uses the distance between the mounting surfaces, the
    bearing and the nut), else the whole screw; never longer than the screw.

    >>> column_length(Application(load_n=1.0, speed_m_s=0.1, length_m=1.0, bearing_to_nut_m=0.6))
    0.6
    """
    if app.bearing_to_nut_m is None:
        return app.length_m
    return min(app.bearing_to_nut_m, app.length_m)


def column_limits(
    app: Application, t: CandidateTable, peak_n: float, torques: dict[str, Any]
) -> dict[str, Any]:
    """Critical speed over the screw's length (never above its makers' rating, a
    leadscrew's Thomson's and Roton's, a ball screw's HIWIN's:
    ``critical_speed.rated_critical_speed_rpm``), and the screw as a column (its span from
    the thrust bearing to the nut) under the peak thrust: Euler when slender, Johnson's
    parabola when short, a ball screw's never above its makers' Euler load
    (``column_rules.rated_column_load``), its allowed load never above its makers'
    (``column_rules.rated_allowed_load``: THK's P2 where a ball screw's family declares no
    buckling rule), and the stress at the root under the peak thrust and the torque the
    screw carries with it (von Mises)."""
    n_c = critical_speed.rated_critical_speed_rpm(
        t.root_diameter_m,
        app.length_m,
        t.youngs_modulus_pa,
        t.density_kg_m3,
        app.end_fixity,
        t.ball,
        (t.wave_speed_m_s, t.root_gyration_m),
        t.hiwin_speed,
    )
    column_m = column_length(app)
    s = buckling.slenderness(t.root_diameter_m, column_m, app.end_fixity, t.root_gyration_m)
    f_cr = buckling.column_critical_load(
        t.youngs_modulus_pa,
        t.root_diameter_m,
        column_m,
        app.end_fixity,
        t.yield_strength_pa,
        section=(t.root_area_m2, t.root_second_moment_m4, t.transition_slenderness),
        slenderness_ratio=s,
    )
    # never above the makers' Euler load: HIWIN's F 3.25 where its family declares it
    f_cr = column_rules.rated_column_load(
        f_cr, t.root_second_moment_m4, column_m, app.end_fixity, t.makers_modulus_pa
    )
    root_nm = root_torque(t, peak_n, torques)
    axial = buckling.root_stress(peak_n, t.root_diameter_m, t.root_area_m2)
    shear = buckling.root_shear_stress(root_nm, t.root_diameter_m, t.root_pi_d_cubed_m3)
    return {
        "critical_rpm": n_c,
        "allowed_rpm": critical_speed.allowed_speed_rpm(n_c, app.critical_speed_safety_factor),
        "critical_load_n": f_cr,
        # never above THK's P2 = 116 d1^2 where a ball screw's family declares no rule
        "allowed_load_n": column_rules.rated_allowed_load(
            f_cr, app.buckling_safety_factor, t.root_area_m2, t.makers_stress_pa
        ),
        "slenderness": s,
        "column_length_m": filled(len(t), column_m),
        "transition_slenderness": t.transition_slenderness,
        # buckling.root_von_mises_stress of the two stresses, each worked out once
        "root_stress_pa": buckling.von_mises_stress(axial, shear),
        "root_torque_nm": root_nm,
        "root_axial_stress_pa": np.asarray(axial, dtype=np.float64),
        "root_shear_stress_pa": shear,
    }
