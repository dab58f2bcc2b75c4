"""The output table's rows of the drive: the screw's speed, the loads, the motor's
torques and their parts, the share of the motor used, the efficiency, the peak power."""

from typing import Any

from app.contract.reported.row import Formula, Reported
from app.contract.source import From, Writer
from app.contract.units import si_to_api
from app.core import drive, quantities, segments
from app.core.formulas import efficiency, energy, geometry, profile, torque
from app.core.formulas.declare import SEED, SHIGLEY


def screw_inertia(values: tuple[float, float], w: Writer) -> float:
    """The screw's rotary inertia, in the API's unit, from its inertia per length [kg m²/m]
    and the screw's length [m]."""
    return si_to_api(torque.screw_inertia(*values), "inertia")


def peak_power(record: Any, w: Writer) -> float:
    """The largest mechanical power at the motor shaft [W], driving or braking: with a
    move, |T ω| of each segment at its top speed (a ramp's torque reaches that speed at
    its end); without one, the accelerating torque at the screw's speed."""
    parts = record.segments
    if parts:
        return max(abs(energy.shaft_power(s.torque_nm, s.rpm)) for s in parts)
    return abs(energy.shaft_power(record.torque.total_nm, record.rpm))


ROWS: tuple[Reported, ...] = (
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
        "The largest motor torque of the move, either way, braking included (without a "
        "stroke at the top speed), or of the start from rest; rotor included, before the "
        "safety factor. Below it, where it occurs.",
        quantity="torque",
        better="lower",
        cell="peak",
        column=True,
        shown="always",
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
        css="torque-total",
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
        csv=True,
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
        "The torque's parts: accelerating the screw, coupling, rotor and mass, the nut's "
        "drag, and the load through the thread.",
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
        "The screw's rotary inertia: the catalog's inertia per length × the screw length.",
        quantity="inertia",
        better="lower",
        column=True,
        csv=True,
        compare=True,
        formula=Formula(torque.screw_inertia),
        source=From(("screw.inertia_kg_m2_per_m", "app.length_m"), via=screw_inertia),
    ),
    Reported(
        "torque.inertia_screw_nm",
        formula=Formula(
            torque.inertia_torque,
            "T = (J/L x L + J_coupling) x 2 pi a / lead: the screw's and its coupling's inertia",
            SEED + " (Inertia Torque T = I alpha) with the coupling's I",
        ),
    ),
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
            drive.breakaway,
            "T = (F + m a) lead / (2 pi eta_static) + (J_screw + J_coupling + J_rotor) alpha "
            "+ T_drag, starting from rest (the largest of every move's start; where the "
            "load drives the move, (F + m a) lead eta_b_static / (2 pi): positive where "
            "the thread self-locks at static friction, the motor starting the lowering)",
            SEED + " with static friction; " + SHIGLEY + " (lowering torque)",
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
)
