"""The output table's rows of the screw's and nut's limits: critical speed, PV,
buckling and the root stress, the traverse speed limit."""

from app.contract.reported.row import Formula, Reported
from app.core import quantities
from app.core.formulas import buckling, column_rules, critical_speed, efficiency, limits, pv
from app.core.formulas.declare import SHIGLEY

#: The point the PV is judged at (``quantities.pv_point``), for both of its numbers.
PV_POINT = (
    "F_pv, v_pv = the peak thrust at the top speed; in a cycle of moves, each move's "
    "largest thrust at its own top speed, of the move whose F v is largest",
    "statics of the moving mass; the seed's PV is proportional to F v",
)

ROWS: tuple[Reported, ...] = (
    Reported(
        "holding_torque.seed_method_nm",
        quantity="torque",
        csv=True,
        formula=Formula(efficiency.holding_torque, "T_b = F lead eta / (2 pi), forward eta"),
    ),
    Reported(
        "holding_torque.physics_nm",
        quantity="torque",
        csv=True,
        formula=Formula(
            efficiency.holding_torque, "T_b = F lead eta_b / (2 pi), back-drive eta", SHIGLEY
        ),
    ),
    Reported(
        "holding_torque.physics_with_margin_nm",
        quantity="torque",
        csv=True,
        formula=Formula(
            efficiency.holding_torque,
            "T_b = F lead eta_b / (2 pi), back-drive eta at f mu_s",
            SHIGLEY,
        ),
    ),
    Reported(
        "critical_speed.margin",
        "Critical speed margin",
        "Allowed speed (whirling speed × your critical-speed factor) over the operating "
        "speed; above 1× passes.",
        better="higher",
        cell="times",
        digits=2,
        column=True,
        compare=True,
        formula=Formula(critical_speed.speed_margin),
        views=("summary",),
    ),
    Reported(
        "critical_speed.allowed_rpm",
        unit="rpm",
        csv=True,
        formula=Formula(critical_speed.allowed_speed_rpm),
    ),
    Reported(
        "critical_speed.theoretical_rpm", formula=Formula(critical_speed.rated_critical_speed_rpm)
    ),
    Reported(
        "utilization.pv",
        "PV used",
        "Nut contact pressure × sliding speed as a share of the nut material's PV limit; up "
        "to 100 % passes.",
        better="lower",
        cell="percent",
        column=True,
    ),
    Reported("buckling.critical_load_n", formula=Formula(buckling.column_critical_load)),
    Reported("buckling.allowed_load_n", formula=Formula(column_rules.rated_allowed_load)),
    Reported("buckling.slenderness", formula=Formula(buckling.slenderness)),
    Reported("buckling.transition_slenderness", formula=Formula(buckling.transition_slenderness)),
    Reported("buckling.root_stress_mpa", formula=Formula(buckling.root_von_mises_stress)),
    Reported("pv.judged_thrust_n", formula=Formula(quantities.pv_point, *PV_POINT)),
    Reported("pv.judged_speed_mm_s", formula=Formula(quantities.pv_point, *PV_POINT)),
    Reported("pv.value_mpa_m_s", formula=Formula(pv.pv_value)),
    Reported("pv.pressure_mpa", formula=Formula(pv.contact_pressure)),
    Reported("pv.surface_speed_m_s", formula=Formula(pv.surface_speed)),
    Reported("pv.max_load_n", formula=Formula(pv.max_load_for_pv)),
    Reported("pv.max_speed_mm_s", formula=Formula(pv.max_rpm_for_pv)),
    Reported("traverse_speed_limit_mm_s", formula=Formula(limits.band_limit)),
)
