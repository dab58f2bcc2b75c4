"""Drive torque: inertia + static drag + load, and break-away (seed, "Torque") [1]."""

import math

from app.core.formulas.declare import SEED, formula


def angular_acceleration(linear_accel_m_s2: float, lead_m: float) -> float:
    """Screw angular acceleration alpha = 2 pi a / lead [rad/s^2].

    Source: seed [1] "Inertia Torque" (T = I alpha) with the screw kinematics v = n lead.

    >>> round(angular_acceleration(1.0, 0.002 * math.pi), 3)
    1000.0
    """
    return 2.0 * math.pi * linear_accel_m_s2 / lead_m


@formula("J = (J/L) x L", SEED + " (screw inertia table, per inch of length)")
def screw_inertia(inertia_per_length_kg_m2_per_m: float, length_m: float) -> float:
    """Screw rotary inertia I = (inertia per length) x length [kg m^2].

    Source: seed [1] screw-inertia table (per inch; the catalog loader converts to per m).

    >>> screw_inertia(2.0e-6, 0.5)
    1e-06
    """
    return inertia_per_length_kg_m2_per_m * length_m


def solid_rod_inertia_per_length(density_kg_m3: float, diameter_m: float) -> float:
    """Rotary inertia per length of a solid round rod, J / L = rho pi d^4 / 32 [kg m^2/m].

    A screw without a given inertia is taken as a solid rod at its pitch diameter
    (``app.catalog.own.screw_inertia``, the ISO family's rule 9). Source: mass moment of a
    cylinder, m d^2 / 8 with m = rho pi d^2 / 4 per length.

    >>> round(solid_rod_inertia_per_length(8000.0, 0.0127) * 0.0254, 10)
    5.19e-07
    """
    return density_kg_m3 * math.pi * diameter_m**4 / 32.0


def reflected_mass_inertia(mass_kg: float, lead_m: float, per_kg_m2: float | None = None) -> float:
    """Moving mass reflected to the screw, J = m (lead / 2 pi)^2 [kg m^2]; ``per_kg_m2``:
    (lead / 2 pi)^2 when already worked out (the candidate table's column, this function
    at 1 kg), the same number.

    Source: standard kinematic equivalence, e.g. Shigley [2] ch. 8 / any motion-control
    sizing guide (the mass moves lead / 2 pi metres per radian).

    >>> round(reflected_mass_inertia(10.0, 2 * math.pi * 0.001), 9)
    1e-05
    """
    return mass_kg * ((lead_m / (2.0 * math.pi)) ** 2 if per_kg_m2 is None else per_kg_m2)


@formula("T = (J/L x L) x 2 pi a / lead", SEED + " (Inertia Torque T = I alpha)")
def inertia_torque(inertia_kg_m2: float, angular_accel_rad_s2: float) -> float:
    """Inertia torque T = I alpha [N m].

    Source: seed [1], "Inertia Torque: T = I alpha, where I = screw inertia".

    >>> inertia_torque(1e-6, 1000.0)
    0.001
    """
    return inertia_kg_m2 * angular_accel_rad_s2


@formula("T = F lead / (2 pi eta)", SEED + " (Torque To Move Load)")
def load_torque(
    load_n: float, lead_m: float, efficiency: float, turn_rad: float | None = None
) -> float:
    """Torque to move the load, T = F lead / (2 pi eta) [N m].

    load_n: axial force [N]; lead_m [m]; efficiency [-] in (0, 1]; turn_rad: 2 pi eta
    when already worked out (``efficient_turn``: the candidate table's column), the same
    number.
    Source: seed [1], "Torque To Move Load: TORQUE = Load x Lead / (2 pi x Efficiency)".

    >>> round(load_torque(100.0, 0.002, 0.5), 6)
    0.063662
    """
    return load_n * lead_m / (efficient_turn(efficiency) if turn_rad is None else turn_rad)


def efficient_turn(efficiency: float) -> float:
    """One turn of the screw [rad] times the thread's efficiency, 2 pi eta: what divides
    F lead in the torque that drives a load (``load_torque``,
    ``profile.thread_torque``).

    >>> round(efficient_turn(0.5), 6)
    3.141593
    """
    return 2.0 * math.pi * efficiency


@formula(
    "T_root = F_peak lead / (2 pi eta) + T_drag + |J_screw alpha|",
    SEED + " (torque components), at the peak thrust",
)
def root_torque(
    peak_force_n: float,
    lead_m: float,
    efficiency: float,
    drag_nm: float,
    screw_inertia_nm: float,
) -> float:
    """The largest torque a section of the screw carries with the peak thrust [N m]:
    T_root = F_peak lead / (2 pi eta) + T_drag + |J_screw alpha|.

    peak_force_n: the peak thrust [N]; lead_m [m]; efficiency: the thread's, eta in
    (0, 1] (the lower of running and static: the thrust of a start from rest passes the
    thread at static friction); drag_nm: the nut's drag torque [N m]; screw_inertia_nm:
    the whole screw's inertia torque J_screw alpha [N m]. That is the section beside the
    drive end, taken with the full thrust (the thrust bearing at the drive end, as usual):
    the thread's torque and the nut's drag pass through every section between the motor
    and the nut, the screw's own inertia torque adds up towards the drive end, and the
    rotor's inertia torque stays in the motor shaft. The thread's term is the driving
    one even where the load helps (back-driving needs less): the safe side.
    Source: seed [1], torque components (``load_torque``, ``total_torque``).

    >>> round(root_torque(6400.0, 0.008, 0.311, 0.0, 0.0), 2)
    26.2
    >>> round(root_torque(100.0, 0.002, 0.5, 0.03, -0.001), 6)
    0.094662
    """
    thread_nm = peak_force_n * lead_m / (2.0 * math.pi * efficiency)
    return thread_nm + drag_nm + abs(screw_inertia_nm)


@formula("T = T_inertia + T_drag + T_load", SEED + " (Torque: sum of three components)")
def total_torque(inertia_nm: float, drag_nm: float, load_nm: float) -> float:
    """Drive torque, the sum of the seed's three components [N m].

    T_total = T_inertia + T_drag + T_load. Bearings, motor, misalignment are extra.
    Source: seed [1], "Torque ... is the sum of three components".

    >>> total_torque(0.001, 0.03, 0.05)
    0.081
    """
    return inertia_nm + drag_nm + load_nm
