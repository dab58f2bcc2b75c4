"""The output table's rows of the move: the accuracy over the stroke, the move's
profile and each segment's time, speed, thrust and torque."""

from app.contract.reported.row import Formula, Reported
from app.core import duty, motion, segments
from app.core.formulas import accuracy, geometry, heat, profile
from app.core.formulas.declare import formula_of

ROWS: tuple[Reported, ...] = (
    Reported(
        "accuracy.lead_error_mm",
        formula=Formula(
            duty.lead_error,
            "e = lead accuracy x stroke (a leadscrew); e = e_p of the ISO 3408-3 class over "
            "the stroke: its table's band, or v300p max(1, 2 stroke / 300 mm) (a ball screw)",
            formula_of(accuracy.cumulative_lead_error).source
            + "; "
            + formula_of(accuracy.ball_travel_deviation).source,
        ),
    ),
    Reported("accuracy.thermal_growth_mm", formula=Formula(accuracy.thermal_growth)),
    Reported("accuracy.heat_growth_mm", formula=Formula(heat.heated_growth)),
    Reported("profile.peak_speed_mm_s", formula=Formula(profile.peak_speed)),
    Reported("profile.accel_time_s", formula=Formula(profile.ramp_time)),
    Reported("profile.decel_time_s", formula=Formula(profile.ramp_time, "t_d = v_peak / d")),
    Reported("profile.constant_time_s", formula=Formula(profile.constant_time)),
    Reported(
        "profile.move_time_s",
        formula=Formula(motion.move_profile, "t = t_a + t_c + t_d", "kinematics"),
    ),
    Reported(
        "profile.cycle_time_s",
        formula=Formula(motion.move_profile, "t = 2 (move + dwell), out and back", "kinematics"),
    ),
    Reported(
        "segments.duration_s",
        formula=Formula(
            motion.move_profile,
            "t_a, t_c, t_d of the profile for the moving segments; the dwell as given",
            "kinematics",
        ),
    ),
    Reported(
        "segments.rpm",
        formula=Formula(
            geometry.screw_speed_rpm,
            "n = 60 v_peak / lead while moving (its top speed); 0 in a dwell",
        ),
    ),
    Reported(
        "segments.thrust_n",
        formula=Formula(
            segments.segments,
            "F = s F_steady + m a, a = +a, 0, -d along the motion; F_steady = load (+ m g "
            "when vertical), s = +1 where it resists the motion (a load that opposes it; a "
            "weight or a load of fixed direction going up or out), -1 where it helps (down "
            "or back); in a dwell F_steady where a load is held at rest (vertical, or a load "
            "of fixed direction)",
            "statics and Newton's second law",
        ),
    ),
    Reported(
        "segments.torque_nm",
        formula=Formula(
            profile.thread_torque,
            "T = F lead / (2 pi eta) if F >= 0 else F lead eta_b / (2 pi), + T_drag "
            "+ (J_screw + J_coupling + J_rotor) alpha; in a dwell the holding torque where a "
            "load is held at rest, else 0",
        ),
    ),
)
