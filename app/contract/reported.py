"""The output table: every reported number of a candidate, declared once.

A row names the number by its path in the candidate's JSON (``CandidateOut``:
``rpm``, ``torque.total_nm``, ``utilization.pv``) and says everything the edges need
to show it: its label and help, its display quantity (or unit), which way is better,
whether it is a column of the results table (and how its cell renders), a column of
the CSV, a row of the compare page, the views it is in, and the formula behind it.
Everything that shows a number reads this table:

- the output models: a row with a ``source`` adds its field to ``CandidateOut``
  (``app.contract.schemas``), and the views take the rows that name them;
- the results table (``templates/partials/candidates.html``) loops over ``columns``:
  a plain number renders by its ``cell`` kind (``show``), a composite cell (the screw,
  the torque with a move, the breakdown, holding, life, governing) by the macro of that
  name in ``templates/partials/cells.html``;
- the CSV (``app.web.export``), the compare page (``app.web.compare``), the guide's
  column help (``app.web.guide``) and the formulas table (``app.report.formulas``).

So a new number is one row here (plus the core computing it, if it does not yet).
"""

import math
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import Annotated, Any, Literal, Optional

from pydantic import Field

from app.catalog import ordering
from app.contract.source import From, Writer
from app.contract.units import Display, Quantity, si_to_api, sig
from app.core import cycle_energy, motion, quantities, segments
from app.core.formulas import (
    accuracy,
    buckling,
    critical_speed,
    efficiency,
    energy,
    geometry,
    life,
    limits,
    profile,
    pv,
    torque,
)
from app.core.formulas.declare import SEED, SHIGLEY
from app.core.phrase import figures

Better = Literal["lower", "higher"] | None
#: How a value renders: ``show`` writes the plain kinds; the composite ones are macros of
#: ``templates/partials/cells.html`` (the compare page writes them with ``show`` too).
Cell = Literal[
    "number",  # in its display unit, ``digits`` significant figures
    "whole",  # a whole number (a speed in rpm)
    "percent",  # a share, 0-1, as a whole percentage
    "times",  # a margin: ``digits`` decimals and "×"
    "text",  # as it is
    "band",  # a [low, high] pair: "low–high", three significant figures
    "screw",  # the id with its tags (coating, anti-backlash, nut material)
    "peak",  # the peak motor torque with the torque while accelerating under it
    "breakdown",  # inertia · drag · load torque
    "holding",  # self-locking, or the brake the load needs
    "life",  # the life band in years, else the rated travel, with its model
    "governing",  # the governing check's label with the pass marks and warnings
]
#: When a results-table column is shown: always, with a move (a stroke), without one, or
#: when a motor is given (or the ranking is by motor margin).
Shown = Literal["always", "move", "no_move", "motor"]
#: The forms of a candidate a row can add its number to (``app.contract.schemas.VIEWS``).
ViewName = Literal["row", "summary", "rejected", "csv"]


@dataclass(frozen=True, slots=True)
class Formula:
    """The core function behind a number; its declared formula and source (``@formula``)
    unless ``text`` and ``source`` are given (one function computing several numbers, or
    a variant of its formula)."""

    function: Callable[..., Any]
    text: str | None = None
    source: str | None = None


@dataclass(frozen=True, slots=True)
class Reported:
    """One reported number (or value) of a candidate; see the module's docstring."""

    #: its path in the candidate's JSON, and its one name: ``torque.total_nm``
    key: str
    #: the heading of its column or row, and what it means (the heading's hover text, the
    #: guide, the field's description)
    label: str = ""
    help: str = ""
    #: the display quantity of a number in a unit (converted by the page's switches), else
    #: the unit as text ("rpm", "years"; "" for a share or a count)
    quantity: Quantity | None = None
    unit: str = ""
    #: which way is better, for the compare page's best mark and the ranked column's order
    better: Better = None
    #: how its cell renders (``Cell``), and a number's significant figures (a margin's
    #: decimals)
    cell: Cell = "number"
    digits: int = 4
    #: a column of the results table: when shown, a second line under the heading, whether
    #: the heading names the unit (a composite cell names its own), the cell's CSS class,
    #: and the rankings it shows (the ranking input's choices)
    column: bool = False
    shown: Shown = "always"
    note: str = ""
    unit_heading: bool = True
    css: str = ""
    ranks: tuple[str, ...] = ()
    #: a column of the CSV (headed by the key without its API unit, in the display unit);
    #: a row of the compare page; the candidate's views it is in besides ``full``
    csv: bool = False
    compare: bool = False
    views: tuple[ViewName, ...] = ()
    #: the core function behind it (``app.report.formulas``)
    formula: Formula | None = None
    #: for a number the hand-written models do not hold: where it comes from in the core's
    #: record, and its type; the row then adds it to ``CandidateOut``
    source: From | None = None
    type: Any = float

    def unit_label(self, d: Display) -> str:
        """The unit the number is shown in: its quantity's display unit, else ``unit``."""
        return d.label(self.quantity) if self.quantity is not None else self.unit


def screw_inertia(values: tuple[float, float], w: Writer) -> float:
    """The screw's rotary inertia, in the API's unit, from its inertia per length [kg m²/m]
    and the screw's length [m]."""
    return si_to_api(torque.screw_inertia(*values), "inertia")


def order_line(values: tuple[Any, float], w: Writer) -> str:
    """The line to send for a quote, from the screw and its length [m]
    (``app.catalog.ordering.ordering_line``)."""
    return ordering.ordering_line(*values)


def order_basis(screw: Any, w: Writer) -> str:
    """What the ordering line rests on (``app.catalog.ordering.ordering_basis``)."""
    return ordering.ordering_basis(screw)


def peak_power(record: Any, w: Writer) -> float:
    """The largest mechanical power at the motor shaft [W], driving or braking: with a
    move, |T ω| of each segment at its top speed (a ramp's torque reaches that speed at
    its end); without one, the accelerating torque at the screw's speed."""
    parts = record.segments
    if parts:
        return max(abs(energy.shaft_power(s.torque_nm, s.rpm)) for s in parts)
    return abs(energy.shaft_power(record.torque.total_nm, record.rpm))


REPORTED: tuple[Reported, ...] = (
    Reported(
        "id",
        "Screw",
        "Catalog id of the screw and nut; the tags say whether the screw is TFE coated and "
        "whether the nut takes up the play (anti-backlash), or that it is a ball screw "
        "(preloaded or not).",
        cell="screw",
        column=True,
        csv=True,
        type=str,
    ),
    Reported("series", csv=True, type=str),
    Reported(
        "screw_type",
        "Type",
        "The kind of screw: 'lead' (a sliding nut, rated by PV, flank pressure and wear) "
        "or 'ball' (a rolling ball nut, rated by its L10 life, static load rating and DN "
        "speed; it always back-drives).",
        cell="text",
        column=True,
        csv=True,
        compare=True,
        views=("row", "summary", "csv"),
        source=From("screw.screw_type"),
        type=str,
    ),
    Reported(
        "dynamic_load_n",
        "Ca",
        "A ball nut's basic dynamic load rating: the axial load at which 90 % of nuts run "
        "10^6 revolutions (the maker's table; empty for a leadscrew).",
        quantity="force",
        better="higher",
        csv=True,
        compare=True,
        views=("row", "csv"),
        source=From("screw.dynamic_load_n", "force"),
    ),
    Reported(
        "static_load_n",
        "C0a",
        "A ball nut's basic static load rating: the axial load that dents the ball track "
        "by 0.0001 of the ball diameter (the maker's table; empty for a leadscrew).",
        quantity="force",
        better="higher",
        csv=True,
        compare=True,
        views=("row", "csv"),
        source=From("screw.static_load_n", "force"),
    ),
    Reported("anti_backlash", csv=True, type=bool),
    Reported(
        "nut_material",
        "Nut material",
        "The nut's material, as the catalog names it.",
        cell="text",
        compare=True,
        type=str,
    ),
    Reported(
        "order_line",
        "To order",
        "The line to send a maker for a quote: the ISO 2903 designation with its tolerance "
        "class for an ISO trapezoidal screw, else the size, lead, materials, nut and length; "
        "then what to confirm with the maker where the catalog assumes a value.",
        cell="text",
        csv=True,
        compare=True,
        source=From(("screw", "app.length_m"), via=order_line),
        type=str,
    ),
    Reported(
        "order_basis",
        "Ordering basis",
        "What the ordering line rests on: the standard's designation, or why there is no "
        "maker's ordering code, and the maker where that is public.",
        cell="text",
        source=From("screw", via=order_basis),
        type=str,
    ),
    Reported(
        "outer_diameter_mm",
        "OD",
        "Outer (major) diameter of the thread.",
        quantity="length",
        column=True,
        ranks=("size",),
        csv=True,
        compare=True,
    ),
    Reported("root_diameter_mm", quantity="length", csv=True),
    Reported("pitch_diameter_mm", formula=Formula(geometry.pitch_diameter)),
    Reported(
        "lead_mm",
        "Lead",
        "Travel of the nut per turn of the screw.",
        quantity="length",
        column=True,
        css="lead",
        csv=True,
        compare=True,
    ),
    Reported("lead_angle_deg", formula=Formula(geometry.lead_angle)),
    Reported("coated", csv=True, type=bool),
    Reported(
        "rpm",
        "Speed",
        "Screw speed that gives your linear speed: 60 × speed / lead.",
        unit="rpm",
        cell="whole",
        column=True,
        csv=True,
        compare=True,
        formula=Formula(geometry.screw_speed_rpm),
        views=("summary",),
    ),
    Reported("axial_load_n", formula=Formula(quantities.axial_load)),
    Reported("peak_axial_load_n", formula=Formula(quantities.peak_axial_load)),
    Reported(
        "torque.peak_motor_nm",
        "Peak torque",
        "Given a move: the largest motor torque of any moving segment (accelerating, "
        "running, braking, either way) or of starting from rest, the rotor's inertia "
        "included, before the torque safety factor; below it, the segment it occurs in "
        "(and the torque while accelerating when that is another).",
        quantity="torque",
        better="lower",
        cell="peak",
        column=True,
        shown="move",
        ranks=("torque",),
        csv=True,
        compare=True,
        formula=Formula(
            quantities.operating_point,
            "T = max(|T_segment| over the moving segments of both moves, T_breakaway)",
            "move profile",
        ),
        views=("summary",),
    ),
    Reported(
        "torque.total_nm",
        "Torque",
        "Motor torque while accelerating: inertia + drag + load, before the torque safety factor.",
        quantity="torque",
        better="lower",
        column=True,
        shown="no_move",
        css="torque-total",
        ranks=("torque", "rms"),
        csv=True,
        compare=True,
        formula=Formula(torque.total_torque),
        views=("summary",),
    ),
    Reported(
        "torque.rms_nm",
        "RMS torque",
        "Given a move: the root-mean-square motor torque over the whole cycle, dwells "
        "included: what heats the motor, against its continuous (RMS) rating.",
        quantity="torque",
        better="lower",
        column=True,
        shown="move",
        css="torque-rms",
        ranks=("rms",),
        compare=True,
        formula=Formula(profile.rms_torque),
        views=("summary",),
    ),
    Reported(
        "motor_use",
        "Motor used",
        "Given a motor: the largest share of it the screw uses (its maximum torque, its "
        "torque curve, its RMS rating, its top speed); the motor margin is the rest.",
        better="lower",
        cell="percent",
        column=True,
        shown="motor",
        css="motor-use",
        ranks=("motor_margin",),
        csv=True,
        views=("summary",),
    ),
    Reported(
        "torque.inertia_nm",
        "Breakdown",
        "The torque's parts: accelerating the screw and the moving mass, the nut's drag, "
        "and pushing the load through the thread.",
        quantity="torque",
        cell="breakdown",
        column=True,
        note="inertia · drag · load",
        csv=True,
        formula=Formula(
            quantities.operating_point,
            "T = T_inertia_screw + T_inertia_mass + T_inertia_motor",
            SEED,
        ),
    ),
    Reported(
        "screw_inertia_kg_m2",
        "Screw inertia",
        "The screw's rotary inertia over its length: the catalog's inertia per length × "
        "the screw length. The motor accelerates it with the moving mass and its rotor.",
        quantity="inertia",
        better="lower",
        column=True,
        csv=True,
        compare=True,
        formula=Formula(torque.screw_inertia),
        source=From(("screw.inertia_kg_m2_per_m", "app.length_m"), via=screw_inertia),
    ),
    Reported("torque.inertia_screw_nm", formula=Formula(torque.inertia_torque)),
    Reported(
        "torque.inertia_mass_nm",
        formula=Formula(
            torque.load_torque,
            "T = m a lead / (2 pi eta): the accelerating force through the thread",
            SEED + " (Torque To Move Load) with the force m a",
        ),
    ),
    Reported(
        "torque.inertia_motor_nm",
        formula=Formula(
            torque.inertia_torque,
            "T = J_motor alpha: the rotor's inertia times the screw's angular acceleration",
            SEED + " (Inertia Torque T = I alpha) with the rotor's I",
        ),
    ),
    Reported(
        "torque.drag_nm",
        quantity="torque",
        csv=True,
        formula=Formula(
            quantities.operating_point,
            "top of the series' static drag range",
            SEED + " (Static Frictional Torque)",
        ),
    ),
    Reported("torque.load_nm", quantity="torque", csv=True, formula=Formula(torque.load_torque)),
    Reported(
        "torque.breakaway_nm",
        formula=Formula(
            torque.load_torque,
            "T = (F + m a) lead / (2 pi eta_static) + J_screw alpha + T_drag, starting from rest",
            SEED + " with static friction",
        ),
    ),
    Reported(
        "torque.required_nm",
        formula=Formula(
            quantities.operating_point, "T = SF x max(T_total, T_breakaway)", "user torque margin"
        ),
    ),
    Reported(
        "torque.peak_nm",
        formula=Formula(segments.segments, "T = max |T_segment| over the cycle", "move profile"),
        views=("summary",),
    ),
    Reported(
        "efficiency",
        "Efficiency",
        "Share of the motor's work that reaches the load (running friction, thread flank "
        "angle included).",
        better="higher",
        cell="percent",
        column=True,
        csv=True,
        compare=True,
        formula=Formula(efficiency.forward_efficiency),
        views=("summary",),
    ),
    Reported(
        "peak_power_w",
        "Peak power",
        "The largest mechanical power at the motor shaft, torque × angular speed, driving "
        "or braking: with a move, each segment's torque at its top speed; without one, "
        "the accelerating torque at the screw's speed. Before the torque safety factor.",
        quantity="power",
        better="lower",
        csv=True,
        compare=True,
        formula=Formula(
            energy.shaft_power,
            "P = max |T_segment 2 pi n_segment / 60| over the cycle (T 2 pi n / 60 without a move)",
            "power of a torque at a shaft's angular speed",
        ),
        source=From(via=peak_power),
    ),
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
            "max(lead_max / lead, T_unpowered / (f T_needed)); holds at 1 or more",
        ),
    ),
    Reported("holds_by", csv=True, type=str),
    Reported(
        "holding_torque.brake_nm",
        "Holds the load?",
        "Whether the load alone can turn the screw with the motor off. “Self-locking” "
        "holds it; “back-drives” needs a brake of at least the torque shown.",
        quantity="torque",
        better="lower",
        cell="holding",
        column=True,
        note="motor off",
        unit_heading=False,
        css="backdrive",
        compare=True,
        formula=Formula(
            quantities.operating_point,
            "T = max(seed method, physics); 0 when self-locking with the friction margin",
            "safe side of both",
        ),
    ),
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
    Reported("critical_speed.theoretical_rpm", formula=Formula(critical_speed.critical_speed_rpm)),
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
    Reported("buckling.allowed_load_n", formula=Formula(buckling.allowed_buckling_load)),
    Reported("buckling.slenderness", formula=Formula(buckling.slenderness)),
    Reported("buckling.transition_slenderness", formula=Formula(buckling.transition_slenderness)),
    Reported("buckling.root_stress_mpa", formula=Formula(buckling.root_von_mises_stress)),
    Reported("pv.value_mpa_m_s", formula=Formula(pv.pv_value)),
    Reported("pv.pressure_mpa", formula=Formula(pv.contact_pressure)),
    Reported("pv.surface_speed_m_s", formula=Formula(pv.surface_speed)),
    Reported("pv.max_load_n", formula=Formula(pv.max_load_for_pv)),
    Reported("pv.max_speed_mm_s", formula=Formula(pv.max_rpm_for_pv)),
    Reported("traverse_speed_limit_mm_s", formula=Formula(limits.band_limit)),
    Reported(
        "life.years",
        "Life",
        "Expected wear life: years at your stroke and cycles per day, else million cm of travel.",
        unit="years",
        better="higher",
        cell="life",
        column=True,
        note="years or travel",
        unit_heading=False,
        css="life",
        ranks=("life",),
        csv=True,
        compare=True,
        formula=Formula(life.life_years),
        views=("summary",),
    ),
    Reported(
        "life.travel_million_cm",
        "Rated travel",
        "The nut's life as travel: the seed's rating, else its wear life by Archard's law.",
        unit="million cm",
        better="higher",
        cell="band",
        compare=True,
    ),
    *(
        Reported(
            key,
            label,
            help,
            quantity="energy",
            better="lower" if key != "cycle_regen_j" else None,
            csv=True,
            compare=True,
            formula=Formula(function, text, source) if text else Formula(function),
            source=From("quantities." + key, "energy"),
        )
        for key, label, help, function, text, source in (
            (
                "cycle_motor_work_j",
                "Motor work per cycle",
                "Given a move: the work the motor gives at its shaft in one cycle, summed over "
                "the segments where it drives (torque times the turns).",
                energy.shaft_energy,
                "E = sum max(0, T_i 2 pi x_i / lead) over the segments",
                "work of a constant torque over the turns",
            ),
            (
                "cycle_regen_j",
                "Braking energy per cycle",
                "Given a move: the energy braking gives back to the drive in one cycle, where "
                "the motor holds back a decelerating mass or a descending load, before the "
                "drive's own losses (a drive without a regenerative path burns it in a "
                "resistor).",
                energy.shaft_energy,
                "E = sum max(0, -T_i 2 pi x_i / lead) over the segments",
                "work of a constant torque over the turns",
            ),
            (
                "cycle_load_work_j",
                "Work on the load per cycle",
                "Given a move: the work done on the load in one cycle, sum F x over the "
                "segments: the external loads and the weight raised less the weight lowered "
                "(the moving mass's kinetic energy cancels over each move).",
                cycle_energy.cycle_energy,
                "W = sum F_i x_i over the moving segments",
                "work of a force",
            ),
            (
                "cycle_thread_loss_j",
                "Thread friction loss per cycle",
                "Given a move: the energy the thread's friction turns into heat in one cycle, "
                "F x (1/eta - 1) where the motor drives and |F| x (1 - eta_b) where the load "
                "does.",
                energy.thread_loss,
                "",
                "",
            ),
            (
                "cycle_drag_loss_j",
                "Drag loss per cycle",
                "Given a move: the nut's drag torque times the turns of one cycle (the top of "
                "the series' drag range).",
                energy.shaft_energy,
                "E = T_drag 2 pi sum x_i / lead",
                "work of a constant torque over the turns",
            ),
            (
                "cycle_copper_loss_j",
                "Copper loss per cycle",
                "Given a move and a stepper's phase current and winding resistance: the heat "
                "of its two windings over the whole cycle, 2 I_rms² R t, the drive holding "
                "the current at rest too (empty for a servo, whose torque constant is not an "
                "input).",
                energy.stepper_copper_loss,
                "",
                "",
            ),
        )
    ),
    Reported("accuracy.lead_error_mm", formula=Formula(accuracy.cumulative_lead_error)),
    Reported("accuracy.thermal_growth_mm", formula=Formula(accuracy.thermal_growth)),
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
            "when vertical), s = +1 out, back and up, -1 down; in a dwell F_steady when "
            "vertical",
            "statics and Newton's second law",
        ),
    ),
    Reported(
        "segments.torque_nm",
        formula=Formula(
            profile.thread_torque,
            "T = F lead / (2 pi eta) if F >= 0 else F lead eta_b / (2 pi), + T_drag "
            "+ (J_screw + J_rotor) alpha; in a dwell the holding torque when vertical, else 0",
        ),
    ),
    Reported(
        "utilization",
        help="Each check's demand over its capacity; above 1 fails.",
        unit="demand/capacity",
        csv=True,
    ),
    Reported(
        "verdict.utilization",
        "Governing utilization",
        "The governing check's demand over its capacity.",
        better="lower",
        cell="percent",
        compare=True,
    ),
    Reported(
        "governing_check",
        "Governing",
        "The check closest to its limit for this screw.",
        cell="governing",
        column=True,
        ranks=("margin",),
        csv=True,
        type=str,
    ),
    Reported("verdict.governs_label", csv=True, type=str),
    Reported("fix", csv=True, type=str),
)

BY_KEY = {r.key: r for r in REPORTED}


def value_of(model: Any, key: str) -> Any:
    """The value at ``key`` (a row's dotted path) of a candidate's output model; None
    where a part on the way is missing (no life, no stroke) or a dict has no such key.

    >>> value_of({"utilization": {"pv": 0.5}}, "utilization.pv"), value_of({}, "life.years")
    (0.5, None)
    """
    value = model
    for name in key.split("."):
        if value is None:
            return None
        value = value.get(name) if isinstance(value, Mapping) else getattr(value, name)
    return value


def show(row: Reported, value: Any, d: Display) -> str:
    """A plain cell's text in the display units; an em dash where there is no value.

    >>> from app.contract.units import DEFAULT_UNITS
    >>> d = Display(dict(DEFAULT_UNITS))
    >>> show(BY_KEY["lead_mm"], 10.0, d), show(BY_KEY["efficiency"], 0.456, d)
    ('10', '46 %')
    >>> show(BY_KEY["critical_speed.margin"], 3.14159, d), show(BY_KEY["life.years"], None, d)
    ('3.14×', '—')
    >>> show(BY_KEY["life.travel_million_cm"], [1.5, 4.5], d)
    '1.5–4.5'
    >>> show(BY_KEY["life.years"], [21.8, 21.8], d)  # one value (a ball nut's L10)
    '21.8'
    """
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "—"
    if isinstance(value, list):
        return "–".join(dict.fromkeys(figures(v) for v in value))
    if row.cell == "whole":
        return f"{value:.0f}"
    if row.cell == "percent":
        return f"{value * 100:.0f} %"
    if row.cell == "times":
        return f"{value:.{row.digits}f}×"
    if isinstance(value, float):
        return d.text(value, row.quantity, row.digits) if row.quantity else sig(value, row.digits)
    return str(value)


def columns(move: bool, motor: bool) -> list[Reported]:
    """The results table's columns shown for this result, in table order."""
    shown = {"always": True, "move": move, "no_move": not move, "motor": motor}
    return [r for r in REPORTED if r.column and shown[r.shown]]


def view_of(name: ViewName) -> dict[str, Any]:
    """The fields the rows put in a view (results-table columns: ``row``; CSV columns:
    ``csv``; and each row's ``views``), nested as ``VIEWS`` holds them: a dotted key
    takes its field of the section, a dict's key (``utilization.pv``) the whole dict."""
    view: dict[str, Any] = {}
    for row in REPORTED:
        if name in row.views or (name == "row" and row.column) or (name == "csv" and row.csv):
            head, _, rest = row.key.partition(".")
            if not rest or head == "utilization":
                view[head] = True
            elif view.get(head) is not True:
                view.setdefault(head, {})[rest] = True
    return view


def merged(*views: Mapping[str, Any]) -> dict[str, Any]:
    """Views together: a field whole in any of them is whole.

    >>> merged({"a": True, "t": {"x": True}}, {"t": {"y": True}}, {"a": {"z": True}})
    {'a': True, 't': {'x': True, 'y': True}}
    """
    out: dict[str, Any] = {}
    for view in views:
        for name, part in view.items():
            have = out.get(name)
            if have is True or part is True:
                out[name] = True
            else:
                out[name] = merged(have or {}, part)
    return out


def added_fields(declared: Iterable[str]) -> dict[str, Any]:
    """``create_model`` definitions of the rows that give a ``source`` for a number
    ``declared`` (the hand-written fields) does not hold: name -> (type, field)."""
    fields: dict[str, Any] = {}
    for row in REPORTED:
        if row.source is None:
            continue
        if "." in row.key or row.key in declared:
            raise ValueError(f"{row.key}: a row's own field is a new top-level field")
        annotation: Any = Annotated[Optional[row.type], row.source]  # noqa: UP045 (a run-time type)
        fields[row.key] = (annotation, Field(default=None, description=row.help))
    return fields
