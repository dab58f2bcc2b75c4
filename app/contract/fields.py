"""Every application input, declared once.

One ``InputField`` per input of the core's ``Application`` says everything the edges need:
the API name (unit in the name), the page and share-link name, the core attribute and its
dimension (whose API unit and factor to SI ``app.contract.units`` holds), how the page shows it
(label, help, form group, choices with their texts) and how it is validated (kind,
default, bounds). The API model (``app.contract.inputs``), the page form and its parser
(``app.contract.form``), the form templates, the printed inputs summary and the CSV export are
all generated from ``FIELDS``; none of them names an input.

Choices come from the core's ``Literal`` types (``typing.get_args``); the table only adds
their display texts (``texts``), and a text table that misses or invents a value is
refused when the table is built.

>>> BY_API["speed_mm_s"].core, BY_API["speed_mm_s"].si_factor, BY_PAGE["speed"].api
('speed_m_s', 0.001, 'speed_mm_s')
>>> [choice.value for choice in BY_PAGE["end_fixity"].choices]
['fixed-free', 'simple-simple', 'fixed-simple', 'fixed-fixed']
"""

from app.contract.input_field import InputField
from app.core.model import (
    AdvicePolicy,
    CoatingChoice,
    EndFixity,
    HoldingSource,
    LoadDirection,
    Lubrication,
    Orientation,
    RankBy,
)

# fmt: off
FIELDS: tuple[InputField, ...] = (
    InputField(
        api="load_n", page="load", core="load_n", label="Axial load",
        help="External axial force; a payload's mass goes in Moving mass", group="Axis",
        kind="number", required=True, bounds=(0.0, 1e6), dimension="force",
    ),
    InputField(
        api="load_direction", page="load_direction", core="load_direction",
        label="Load direction", help="Automatic: down if vertical, else opposing",
        group="Axis", kind="choice", default="auto", options=LoadDirection,
        texts={"auto": "Automatic", "opposes": "Opposes move", "fixed": "Down (in)"},
    ),
    InputField(
        api="moving_mass_kg", page="moving_mass_kg", core="moving_mass_kg",
        label="Moving mass", help="Carried by the nut", group="Axis",
        kind="number", default=0.0, bounds=(0.0, 1e5), dimension="mass",
    ),
    InputField(
        api="orientation", page="orientation", core="orientation", label="Orientation",
        help="Vertical adds the weight of the moving mass", group="Axis",
        kind="choice", default="horizontal", options=Orientation,
        texts={"horizontal": "Horizontal", "vertical": "Vertical"},
    ),
    InputField(
        api="lead_mm", page="lead", core="lead_m", label="Lead",
        help="Travel per turn; empty or “any” for every lead", group="Axis", kind="number",
        api_help="Travel per turn; left out (or null in a body) for every lead",
        bounds=(0.01, 1000.0), dimension="length",
        none_word="any",
        catalog_only=True,
    ),
    InputField(
        api="speed_mm_s", page="speed", core="speed_m_s", label="Linear speed",
        help="Top speed of the nut along the screw", group="Axis", kind="number",
        required=True,
        bounds=(1e-3, 1e5), dimension="speed",
    ),
    InputField(
        api="length_mm", page="length", core="length_m", label="Screw length",
        help="Between the supports", group="Axis", kind="number", required=True,
        bounds=(1.0, 1e5), dimension="length",
    ),
    InputField(
        api="accel_mm_s2", page="accel", core="accel_m_s2", label="Acceleration",
        help="Linear, to reach the speed; 0 for constant speed", group="Motion and load",
        kind="number", default=1000.0, bounds=(0.0, 1e6), dimension="accel",
    ),
    InputField(
        api="coupling_inertia_kg_m2", page="coupling_inertia", core="coupling_inertia_kg_m2",
        label="Coupling inertia", help="Turns with the screw, counted as load; empty for none",
        group="Motion and load", kind="number", bounds=(0.0, 10.0), dimension="inertia",
    ),
    InputField(
        api="guide_friction", page="guide_friction", core="guide_friction",
        label="Guide friction", help="Friction coefficient of the guides carrying the "
        "moving mass on a horizontal axis (μ m g more on the nut). Ball carriages "
        "0.002–0.003, roller 0.001–0.002 (Thomson); 0: none",
        group="Motion and load", kind="number", default=0.0, bounds=(0.0, 1.0),
    ),
    InputField(
        api="compression", page="compression", core="compression", label="Thrust bearing",
        help="Compression up: the thrust bearing at the end the nut leaves going up (out); "
        "tension up: at the end it approaches. Only a pushed screw can buckle; a reversing "
        "load pushes it on one move",
        group="Motion and load", kind="yes-no",
        default=True,
        texts={"true": "Compression up", "false": "Tension up"},
    ),
    InputField(
        api="bearing_to_nut_mm", page="bearing_to_nut", core="bearing_to_nut_m",
        label="Thrust bearing to nut", help="The longest span from the thrust bearing to "
        "the nut (the nut at the end of its travel farthest from the bearing): the column "
        "that buckles; at most the screw length; empty for the whole screw",
        group="Motion and load", kind="number", bounds=(1.0, 1e5), dimension="length",
    ),
    InputField(
        api="support_id", page="support_id", core="support_unit",
        label="Support unit", help="The thrust bearing's support unit from the library "
        "(supports.toml: THK FK/BK fixed-side units with their axial ratings), unless the "
        "ratings are typed below; empty or “none” for none",
        group="Motion and load", kind="text", none_word="none",
    ),
    InputField(
        api="support_static_n", page="support_static", core="support_static_n",
        label="Thrust bearing static rating", help="The thrust bearing's static axial load "
        "rating C0a (or its maker's permissible static axial load): the peak thrust must "
        "stay within it over the static safety factor; empty for no check",
        group="Motion and load", kind="number", bounds=(1e-3, 1e8), dimension="force",
    ),
    InputField(
        api="support_dynamic_n", page="support_dynamic", core="support_dynamic_n",
        label="Thrust bearing dynamic rating", help="The thrust bearing's basic dynamic "
        "axial load rating Ca, for its L10 life (needs a stroke, cycles per day and a "
        "required life); empty for no life check",
        group="Motion and load", kind="number", bounds=(1e-3, 1e8), dimension="force",
    ),
    InputField(
        api="end_fixity", page="end_fixity", core="end_fixity", label="End fixity",
        help="How the two screw ends are supported", group="Ends", kind="choice",
        default="fixed-simple", options=EndFixity, drawn=True,
        texts={
            "fixed-free": "Fixed – free", "simple-simple": "Simple – simple",
            "fixed-simple": "Fixed – simple", "fixed-fixed": "Fixed – fixed",
        },
    ),
    InputField(
        api="require_anti_backlash", page="require_anti_backlash",
        core="require_anti_backlash", label="Anti-backlash nut required",
        help="Only nuts that take up the play", group="Nut and environment", kind="yes-no",
        default=False,
    ),
    InputField(
        api="coating", page="coating", core="coating", label="Coating",
        help="TFE lowers the friction", group="Nut and environment", kind="choice",
        default="auto", options=CoatingChoice,
        texts={
            "auto": "Auto (coated or not)", "tfe": "TFE coated", "none": "Uncoated",
        },
        catalog_only=True,
    ),
    InputField(
        api="family", page="family", core="families", label="Families",
        help="Catalog family ids, comma-separated; empty for every family",
        api_help="Catalog family ids: the parameter repeated (family=B&family=ZBX), or a "
        "list in a body; left out for every family",
        group="Nut and environment", kind="list",
        catalog_only=True,
    ),
    InputField(
        api="nut_material", page="nut_material", core="nut_material", label="Nut material",
        help="e.g. bronze, acetal or polyacetal; empty or “any” for every nut",
        group="Nut and environment", kind="text", none_word="any",
        catalog_only=True,
    ),
    InputField(
        api="nut_length_mm", page="nut_length", core="nut_length_m", label="Nut length",
        help="Trapezoidal screws: the nut's length, whose engaged turns (length over pitch) "
        "carry the load; empty for the catalog's (2 x d)",
        group="Nut and environment", kind="number", bounds=(0.1, 1e4), dimension="length",
    ),
    InputField(
        api="oil_present", page="oil_present", core="oil_present", label="Oil present",
        help="Some nut plastics do not take oil", group="Nut and environment", kind="yes-no",
        default=False,
    ),
    InputField(
        api="vacuum", page="vacuum", core="vacuum", label="Vacuum",
        help="Warns of nuts whose outgassing is not measured (an oiled nut loses its "
        "lubricant, a polymer outgasses) and ranks them last", group="Nut and environment",
        kind="yes-no", default=False,
    ),
    InputField(
        api="lubrication", page="lubrication", core="lubrication", label="Nut lubrication",
        help="Raises a polymer nut's permissible PV: dry x1 (the rating's own), greased "
        "x1.3 (igus, greased at assembly), oiled x2 (a maker's “as much as 100 %”); a "
        "dry-film coated screw must then not be used; a bronze nut is rated lubricated: "
        "run dry, its numbers are at its dry friction and it is flagged",
        group="Nut and environment", kind="choice", default="dry", options=Lubrication,
        texts={"dry": "Dry", "greased": "Greased", "oiled": "Oiled"},
    ),
    InputField(
        api="ambient_c", page="ambient_c", core="ambient_c", label="Ambient temperature",
        help="Around the screw", group="Nut and environment", kind="number", default=20.0,
        bounds=(-273.15, 1000.0), dimension="temperature",
    ),
    InputField(
        api="stroke_mm", page="stroke", core="stroke_m", label="Stroke",
        help="Travel of one move, for life and accuracy", group="Duty and requirements",
        kind="number", bounds=(0.01, 1e5), dimension="length",
    ),
    InputField(
        api="cycles_per_day", page="cycles_per_day", core="cycles_per_day",
        label="Cycles per day", help="Full cycles, out and back, for life; or give hours per "
        "day instead",
        group="Duty and requirements", kind="number", bounds=(1e-3, 1e7), unit="/day",
    ),
    InputField(
        api="hours_per_day", page="hours_per_day", core="hours_per_day",
        label="Hours per day", help="Running hours a day instead of cycles per day (not "
        "both): the cycles follow from the cycle's time, both moves and dwells; needs a "
        "stroke or moves",
        group="Duty and requirements", kind="number", bounds=(1e-3, 24.0), unit="h/day",
        needs=("stroke_mm",),
    ),
    InputField(
        api="required_life_years", page="required_life_years", core="required_life_years",
        label="Required life", help="Needs a stroke or moves, and cycles or hours per day",
        group="Duty and requirements", kind="number", bounds=(1e-3, 1000.0), dimension="years",
        needs=("stroke_mm",),
    ),
    InputField(
        api="positioning_tolerance_mm", page="positioning_tolerance",
        core="positioning_tolerance_m", label="Positioning tolerance",
        help="Allowed positioning error; empty for no check", group="Duty and requirements",
        kind="number", bounds=(1e-4, 1000.0), dimension="length",
    ),
    InputField(
        api="brake_torque_nm", page="brake_torque", core="brake_torque_nm",
        label="Holding torque at the screw", group="Duty and requirements", kind="number",
        help="Vertical axis (or a load of fixed direction): a brake's, or a stepper's "
        "energised holding torque (say which below), at the screw; empty when the screw "
        "must hold the load by itself, or, when the motor holds it energised, for the "
        "stepper's own (the library's, or the datasheet's typed below)",
        bounds=(0.0, 1e5), dimension="torque",
    ),
    InputField(
        api="holding_source", page="holding_source", core="holding_source",
        label="Holding torque is", help="A brake holds with the power off; a stepper's "
        "holding torque only while it is energised (then the detent torque, or the "
        "thread, must hold with the power off)",
        group="Duty and requirements", kind="choice", default="brake", options=HoldingSource,
        texts={"brake": "A brake's", "energised": "The energised motor's"},
    ),
    InputField(
        api="detent_torque_nm", page="detent_torque", core="detent_torque_nm",
        label="Detent torque", help="The stepper's unpowered detent torque at the screw: "
        "what holds with the power off; empty when unknown",
        group="Duty and requirements", kind="number", bounds=(0.0, 1e5), dimension="torque",
    ),
    InputField(
        api="hold_power_off", page="hold_power_off", core="hold_power_off",
        label="Must hold with the power off", help="Where the axis holds a load at rest "
        "(vertical, or a load of fixed direction): yes, each screw must hold it unpowered, "
        "by the thread self-locking with the friction margin, a brake or the detent torque "
        "(answered yes or no with its margin, the surest holds ranked first); no, the "
        "energised motor holds it and a drop with the power off is accepted",
        group="Duty and requirements", kind="yes-no", default=True,
        texts={"true": "Yes", "false": "No: the motor holds it"},
    ),
    InputField(
        api="motor", page="motor", core="motor", label="Library motor",
        help="A motor of the library (motors.toml; GET /api/v1/motors lists them): a "
        "stepper's pull-out curve, rotor inertia and step angle, or a servo's peak "
        "envelope, rated torque and rotor inertia, unless given here; “any” to rank every "
        "screw with every library motor (GET /api/v1/pairs); empty or “none” for no motor",
        group="Motor and move", kind="text", none_word="none",
    ),
    InputField(
        api="max_torque_nm", page="max_torque", core="max_torque_nm",
        label="Max drive torque", help="What the motor gives; empty for no limit",
        group="Motor and move", kind="number", bounds=(1e-6, 1e5),
        dimension="torque",
    ),
    InputField(
        api="motor_curve", page="motor_curve", core="motor_curve", label="Motor curve",
        help="Torque the motor gives against speed: one point “rpm torque” per line, rpm "
        "ascending, torque in the torque unit chosen; linear between points, nothing past "
        "the last",
        api_help="Torque the motor gives against speed: points [rpm, N m] in a body, "
        "rpm:torque,rpm:torque in a query, rpm ascending; linear between points, nothing "
        "past the last",
        group="Motor and move", kind="curve", unit="rpm : N m",
    ),
    InputField(
        api="motor_rms_torque_nm", page="motor_rms_torque", core="motor_rms_torque_nm",
        label="Continuous torque", help="The motor's rating for the RMS torque of the "
        "cycle (needs a stroke or moves); empty for no check",
        group="Motor and move", kind="number", bounds=(1e-6, 1e5), dimension="torque",
        needs=("stroke_mm",),
    ),
    InputField(
        api="motor_rms_curve", page="motor_rms_curve", core="motor_rms_curve",
        label="Continuous torque curve",
        help="The continuous duty zone of the maker's chart, “rpm torque” per line, for "
        "the RMS torque; empty: the continuous torque at every speed",
        api_help="The motor's continuous duty zone against speed: points [rpm, N m] in a "
        "body, rpm:torque,rpm:torque in a query, rpm ascending. The cycle's RMS torque is "
        "held to it segment by segment; none given: the continuous torque at every speed "
        "(a library servo brings its own)",
        group="Motor and move", kind="curve", unit="rpm : N m",
    ),
    InputField(
        api="motor_inertia_kg_m2", page="motor_inertia", core="motor_inertia_kg_m2",
        label="Rotor inertia", help="The motor's own, at the screw; empty for none",
        group="Motor and move", kind="number", bounds=(0.0, 10.0), dimension="inertia",
    ),
    InputField(
        api="step_angle_deg", page="step_angle", core="step_angle_deg", label="Step angle",
        help="The stepper's full step: 1.8 for 200 steps a turn, 0.9 for 400; empty for "
        "no step rate or resolution check",
        group="Motor and move", kind="number", bounds=(0.01, 90.0), unit="deg",
    ),
    InputField(
        api="microsteps", page="microsteps", core="microsteps", label="Microsteps",
        help="Step pulses per full step, as the driver is set: 1 for full steps",
        group="Motor and move", kind="whole number", default=1, bounds=(1, 256),
    ),
    InputField(
        api="max_step_rate_hz", page="max_step_rate", core="max_step_rate_hz",
        label="Max step rate", help="The controller's highest step pulse rate, per "
        "second; needs a step angle or a library motor",
        group="Motor and move", kind="number", bounds=(1.0, 1e8), dimension="frequency",
    ),
    InputField(
        api="motor_supply_v", page="motor_supply", core="motor_supply_v",
        label="Drive voltage", help="A stepper's drive supply, for its pull-out curve from "
        "the datasheet values below, or a library stepper's at this voltage (its maker's "
        "published curve lowered where the model says this voltage gives less, never "
        "raised)", group="Motor and move",
        kind="number",
        bounds=(1.0, 400.0), unit="V",
    ),
    InputField(
        api="motor_phase_current_a", page="motor_phase_current",
        core="motor_phase_current_a", label="Phase current",
        help="Set on the driver, per phase; a library stepper's holding torque scales with "
        "it, up to its rated current", group="Motor and move", kind="number",
        bounds=(0.01, 50.0), unit="A",
    ),
    InputField(
        api="motor_current_rms", page="motor_current_rms", core="motor_current_rms",
        label="Phase current set as RMS",
        help="Yes where the driver sets the phase current as an RMS value, as Trinamic's "
        "do (the sine's amplitude 1.41 times it, QSH4218 manual sec. 6.5): a "
        "microstepping drive then gives the full holding torque at low speed. No (the "
        "safe side): the set current is the sine's peak, giving the holding torque over "
        "sqrt 2. Read for a library stepper too",
        group="Motor and move", kind="yes-no", default=False,
    ),
    InputField(
        api="motor_resistance_ohm", page="motor_resistance", core="motor_resistance_ohm",
        label="Winding resistance", help="Per phase, from the datasheet",
        group="Motor and move", kind="number", bounds=(0.0, 1000.0), unit="Ω",
    ),
    InputField(
        api="motor_inductance_mh", page="motor_inductance", core="motor_inductance_h",
        label="Winding inductance", help="Per phase, from the datasheet",
        group="Motor and move", kind="number", bounds=(0.01, 1000.0), dimension="inductance",
    ),
    InputField(
        api="motor_holding_torque_nm", page="motor_holding_torque",
        core="motor_holding_torque_nm", label="Motor holding torque",
        help="At the phase current: with the step angle and the four values above it "
        "draws the stepper's pull-out curve (when no curve is given)",
        group="Motor and move", kind="number", bounds=(1e-4, 100.0), dimension="torque",
        needs=(
            "step_angle_deg", "motor_supply_v", "motor_phase_current_a",
            "motor_resistance_ohm", "motor_inductance_mh",
        ),
    ),
    InputField(
        api="decel_mm_s2", page="decel", core="decel_m_s2", label="Deceleration",
        help="Linear, to stop at the end of the stroke; empty for the acceleration",
        group="Motor and move", kind="number", bounds=(0.0, 1e6), dimension="accel",
    ),
    InputField(
        api="dwell_s", page="dwell", core="dwell_s", label="Dwell",
        help="Rest after each move, out and back (needs a stroke)", group="Motor and move",
        kind="number", default=0.0, bounds=(0.0, 1e6), dimension="time", needs=("stroke_mm",),
    ),
    InputField(
        api="critical_speed_safety_factor", page="critical_speed_safety_factor",
        core="critical_speed_safety_factor", label="Critical-speed factor",
        help="Share of the theoretical whirling speed the screw may run at: 0.8 allows "
        "80 %. A fraction, 1 or below; smaller is safer",
        group="Safety factors", kind="number", default=0.8, bounds=(0.01, 1.0),
    ),
    InputField(
        api="buckling_safety_factor", page="buckling_safety_factor",
        core="buckling_safety_factor", label="Buckling factor",
        help="Share of the column's critical load (Euler, or Johnson for short screws) and "
        "of the root's yield strength the screw may carry: 0.5 allows half. A fraction, 1 "
        "or below; smaller is safer",
        group="Safety factors", kind="number", default=0.5, bounds=(0.01, 1.0),
    ),
    InputField(
        api="support_static_safety_factor", page="support_static_safety_factor",
        core="support_static_safety_factor", label="Thrust bearing static factor",
        help="Static safety factor fs on the thrust bearing: its static rating over the "
        "peak thrust must be at least this. THK's lower limits: 2 without vibration or "
        "impact, 5 with",
        group="Safety factors", kind="number", default=2.0, bounds=(1.0, 20.0),
    ),
    InputField(
        api="ball_load_factor", page="ball_load_factor",
        core="ball_load_factor", label="Load factor (ball nut, thrust bearing)",
        help="Operating factor f_w on the mean load of the rolling parts, a ball nut and "
        "the thrust bearing, for their L10 lives, which fall as its cube: HIWIN 1.1 to 1.2 "
        "without impact, 1.3 to 1.8 in normal operation, 2 to 3 with impact and vibration "
        "(IKO, bearings: 1 to 1.2 smooth, 1.2 to 1.5 ordinary, 1.5 to 3 with shocks)",
        group="Safety factors", kind="number", default=1.2, bounds=(1.0, 5.0),
    ),
    InputField(
        api="ball_static_safety_factor", page="ball_static_safety_factor",
        core="ball_static_safety_factor", label="Ball nut static safety factor",
        help="Static safety factor f_s on a ball nut's peak thrust against its static load "
        "rating C0a: 2, THK's lower limit without vibration or impact; with them (fast "
        "starts and sudden stops count) THK asks up to 5",
        group="Safety factors", kind="number", default=2.0, bounds=(1.0, 10.0),
    ),
    InputField(
        api="torque_safety_factor", page="torque_safety_factor",
        core="torque_safety_factor", label="Torque safety factor",
        help="Multiplier on the computed drive torque before it is compared with the "
        "motor: 1.5 asks for 50 % reserve. 1 or more; larger is safer",
        group="Safety factors",
        kind="number", default=1.0, bounds=(1.0, 10.0),
    ),
    InputField(
        api="stepper_torque_margin", page="stepper_torque_margin",
        core="stepper_torque_margin", label="Stepper torque margin",
        help="A stepper's pull-out torque is divided by this before the move is held "
        "against it (a stepper that slips loses its position). 1.5, the 50 % margin "
        "Parker recommends for steppers (Parker Motion knowledge base, Torque Margin); "
        "Trinamic's QSH manuals ask for 30-50 % plus 10 %. The pull-out model runs up to "
        "1.30 times makers' published half-step curves: below 1.3 a drawn curve may rate "
        "the motor above its maker's chart. 1 or more",
        group="Safety factors",
        kind="number", default=1.5, bounds=(1.0, 10.0),
    ),
    InputField(
        api="self_locking_friction_factor", page="self_locking_friction_factor",
        core="self_locking_friction_factor", label="Self-locking friction factor",
        help="Fraction of the static friction trusted to hold a vertical load, 1 or below: "
        "0.5 matches the seed's rule (lead under diameter / 8); friction falls with "
        "vibration and lubrication",
        group="Safety factors", kind="number", default=0.5, bounds=(0.01, 1.0),
    ),
    InputField(
        api="brake_safety_factor", page="brake_safety_factor", core="brake_safety_factor",
        label="Holding safety factor", help="Multiplier on the torque needed to hold the "
        "load (brake, holding or detent torque); empty for the torque safety factor, for "
        "a brake at least 1.5 (the service factor Machine Design gives a brake holding a "
        "ball or lead screw, for its wear). 1 or more; larger is safer",
        group="Safety factors", kind="number", bounds=(1.0, 10.0),
    ),
    InputField(
        api="rank_by", page="rank_by", core="rank_by", label="Rank by",
        help="Order of the passing screws", group="Results", kind="choice",
        default="torque", options=RankBy,
        texts={
            "torque": "Lowest torque", "rms": "Lowest RMS torque", "margin": "Largest margin",
            "life": "Longest life",
            "size": "Smallest size", "motor_margin": "Largest motor margin",
        },
        catalog_only=True,
    ),
    InputField(
        api="advice", page="advice", core="advice", label="Advice",
        help="A failed recommendation (e.g. the traverse speed for a lead): a warning (such "
        "screws always rank after those without one), or reject them",
        group="Results", kind="choice", default="warn", options=AdvicePolicy,
        texts={"warn": "Warn and rank them last", "reject": "Reject them"},
        retired={"rank": "warn"},
        catalog_only=True,
    ),
    InputField(
        api="limit", page="limit", core="limit", label="Number of results",
        help="How many passing screws to list, 1–100", group="Results",
        kind="whole number", default=10, bounds=(1, 100),
        catalog_only=True,
    ),
)
# fmt: on

BY_API = {field.api: field for field in FIELDS}
BY_PAGE = {field.page: field for field in FIELDS}
#: The moving mass's field: a machine adds the axes an axis carries to it
#: (``app.report.machine``).
MOVING_MASS = BY_API["moving_mass_kg"]
#: The load and its direction: a machine adds to them the loads the vertical axes above a
#: vertical axis stand on its nut (``app.report.machine``).
LOAD, LOAD_DIRECTION = BY_API["load_n"], BY_API["load_direction"]
