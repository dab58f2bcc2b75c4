"""The output table's rows of holding the load with the motor off: the back-drive
efficiencies, self-locking and its margin, the brake torque."""

from app.contract.reported.row import Formula, Reported
from app.core import holding
from app.core.formulas import efficiency

ROWS: tuple[Reported, ...] = (
    Reported("efficiency_square_thread", formula=Formula(efficiency.square_thread_efficiency)),
    Reported("backdrive_efficiency", formula=Formula(efficiency.backdrive_efficiency)),
    Reported(
        "backdrive_efficiency_running",
        formula=Formula(efficiency.backdrive_efficiency, "eta_b at the running (dynamic) friction"),
    ),
    Reported(
        "self_locking",
        csv=True,
        type=bool,
        formula=Formula(efficiency.is_self_locking),
        views=("summary",),
    ),
    Reported(
        "self_locking_with_margin",
        type=bool,
        formula=Formula(efficiency.self_locking_limit_friction),
        views=("row",),
    ),
    Reported("seed_rule_no_backdrive", type=bool, formula=Formula(efficiency.seed_backdrive_rule)),
    Reported(
        "max_self_locking_lead_mm",
        formula=Formula(efficiency.max_self_locking_lead, "lead = pi d_p mu_s / cos a_n"),
    ),
    Reported(
        "max_self_locking_lead_with_margin_mm",
        formula=Formula(efficiency.max_self_locking_lead, "lead = pi d_p f mu_s / cos a_n"),
    ),
    Reported("holds_power_off", csv=True, type=bool),
    Reported(
        "hold_margin",
        csv=True,
        formula=Formula(
            efficiency.hold_margin,
            "lead_max / lead where the thread holds at it, else T_unpowered / (f T_needed) "
            "where a brake or detent torque is given, else lead_max / lead; holds at 1 or more",
        ),
    ),
    Reported("holds_by", csv=True, type=str),
    Reported(
        "holding_torque.brake_to_fit_nm",
        "Holds the load?",
        "Whether the load alone turns the screw with the motor off: “self-locking” holds "
        "at the static friction times the self-locking factor; otherwise a brake of at "
        "least the torque shown is needed.",
        quantity="torque",
        better="lower",
        cell="holding",
        column=True,
        note="motor off",
        unit_heading=False,
        css="backdrive",
        compare=True,
        formula=Formula(
            holding.holding,
            "T = SF_brake x max(seed method, physics at f mu_s); 0 when self-locking with "
            "the friction margin; SF_brake the brake safety factor given, else the torque "
            "safety factor and at least a brake's service factor 1.5, whatever holds the "
            "load now",
            "safe side of both; the brake's service factor: Machine Design, \"Mechatronics "
            'Q & A: Hold It Steady" (2007)',
        ),
    ),
)
