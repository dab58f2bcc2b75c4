"""A hybrid stepper's pull-out torque against speed from its datasheet's electrical
values, so a user can enter a motor's numbers instead of its curve [1, 2].

The curve the app draws (``microstep_pull_out_torque``, ``microstep_pull_out_curve``)
is the torque of a sine (microstepping) chopper drive. A datasheet's holding torque T_h
is measured with both phases at the rated current I, a current vector of sqrt(2) I, so
the torque constant is k_e = T_h / (sqrt(2) I) [4, 5]. What the drive's set current
means decides the sine's amplitude: most drives set the peak (amplitude I: T_h / sqrt(2)
= 0.71 T_h at low speed [5]); Trinamic's set the RMS (amplitude 1.41 I: the full T_h
[6]). Faster, each phase's circuit V = E + I (R + j X) limits the current the supply can
force against the back-EMF and the reactance [3, 4].

Held against makers' published pull-out curves read as numbers
(``app/report/pull_out_curves.py``: eleven curves of three makers, STEPPERONLINE,
Changzhou Songyang and Trinamic). On a microstepping drive (STEPPERONLINE 23HS32-4004S,
Leadshine DM542T at 36 V and 48 V) the phase circuit alone holds within 15 % while the
back-EMF amplitude stays below about 40 % of the supply, and then runs high: at 36 V and
390 rpm (back-EMF 48 % of the supply) the curve has fallen to 82 % of its low-speed
torque, where the circuit still gives all of it (22 % high); at 600 rpm, 39 % high. Real
curves fall sooner than the ideal circuit (the drive's voltage drop and current-loop
headroom, iron loss, mid-band resonance), so past the speed at which the back-EMF
reaches ``CONFIRMED_BACK_EMF_SHARE`` of the supply (``confirmed_range_rpm``) the model
falls as 1 / speed from its torque there (constant power), never above the circuit:
0.88 to 1.04 times every point of those curves. The makers' half-step curves scatter more
about it, 0.73 to 1.30 times their points: within 15 % of every point of Trinamic's four
QSH4218 motors but for some low (safe-side) ones, and above it at mid speeds for two of
Changzhou Songyang's three (SY35ST36-1004A from 390 rpm, up to 1.27 times; SY42STH38-1684A
at 600 rpm, 1.30 times). So the model alone is not within 15 % of every maker's curve;
over the stepper torque margin's default of 1.5 the usable torque lies below every
published point of all of them.

Validity: two-phase hybrid on a sine chopper drive set to the motor's rated current,
supply 4 to 25 times the winding's rated voltage I R (the makers' range [6]); confirmed
on the microstepping curves up to ``confirmed_range_rpm``, and past it 0.73 to 1.11
times every maker's published points as far as they reach (up to 5.7 times that speed).
A half-step drive scatters more about it, as above. A supply below 4 times I R is
outside it: two such STEPPERONLINE half-step curves (14HS17-0504S at 20 V, 17HS24-0644S
at 24 V, 2.7 and 2.6 times I R) fall far faster, the second to under a quarter of the
model's figure at 420 rpm. No resonance, iron loss or saturation: the curve is an
estimate to be confirmed on the maker's own curve.

The constant-power envelope (``corner_speed_rpm``, ``pull_out_torque``) is kept for the
corner speed it names:

A chopper drive holds the phase current at its set value I while the winding lets it:
each full step reverses the current of one phase, from -I to +I, through the winding's
inductance L, driven by what the supply V leaves over the resistive drop I R. That takes
t = 2 L I / (V - I R) [2]. While a full step lasts longer than t the motor gives its
holding torque; faster, the current (and with it the torque) reaches only the share of
I that the step's time allows, so the torque falls as 1 / speed above the corner speed
(constant power) [1]. It ignores back-EMF and gives the full holding torque below the
corner, which no microstepping drive gives: the app no longer draws curves with it.

``sine_pull_out_torque`` is the same circuit as the microstepping model with the set
current read as an RMS value (amplitude sqrt(2) I), as some drives set it; at low speed
it gives the full holding torque, so the app does not draw curves with it either.

References
----------
1. Farnell, "Stepper motor calculator": max speed = V / (2 L I_max spr) [rev/s], minimum
   time per step = 2 L I_max / V, spr full steps per revolution.
2. D. W. Jones, "Control of Stepping Motors", University of Iowa (1995), current
   limiting: the current in an L-R winding rises at (V - i R) / L.
3. MathWorks, Simscape Specialized Power Systems, "Stepper Motor" block: the electrical
   section of a permanent-magnet or hybrid stepper is one equivalent circuit per phase,
   its resistance, inductance and back-EMF in series.
4. Duet3D documentation (D. Crocker), "Back emf due to rotation", as reproduced by
   CloudrayMotor, "Back emf due to rotation": approximate peak back-EMF =
   sqrt(2) pi T_h rev/s / I_rated, holding torque T_h with both phases at the rated
   current; worked example 0.55 N m, 1.68 A, 5 rev/s: 7.3 V.
5. R. Carlyle, StepperSim issue #38 (github.com/rcarlyle/StepperSim/issues/38): the
   rated holding torque is measured with two coils on at 100 %, which a microstepping
   driver never gives; multiply it by sqrt(2) / 2 (0.707) for the microstepping torque.
6. Trinamic (ADI), QMOT QSH4218 manual V1.10, Table 2.1 (QSH4218-47-28-040: 0.40 N m,
   2.8 A, 0.5 ohm, 0.6 mH), section 2 ("0.25Nm torque at 1200 RPM with a 24V supply";
   "optimized for 2.8A RMS coil current"), section 5.4 (curve tested at 2.8 A RMS),
   section 6.5 (microstepping: "the amplitude of the waves is 1.41 times the nominal
   motor current, while the RMS values equal the nominal motor current") and Table 6.2
   (optimum driver supply 4 to 22 times, maximum 25 times, the rated coil voltage).
7. STEPPERONLINE (omc-stepperonline.com), 23HS32-4004S full datasheet (2.4 N m, 4.0 A,
   0.65 ohm, 3.2 mH, 1.8 deg) and "Pull out torque curve of 23HS32-4004S" (Leadshine
   DM542T, 2000 microsteps, peak 4.2 A, 36 V and 48 V); 14HS17-0504S and 17HS24-0644S
   datasheets and half-step pull-out curves; as kept in the public repository
   jmpz63/APM (Projects/Moveo_Bridge/Onboarding/04_Hardware_Firmware_Network_Architecture/
   joint_datasheets/, commit 411985f), read at the curves' plotted points.
8. Changzhou Songyang SY35ST36-1004A, SY42STH38-1684A and SY42STH47-1684B specifications
   with their half-step pull-out curves at 24 V, and Trinamic QSH4218 manuals V1.03
   (Figures 4.1-4.3) and V1.06 (Figure 5.4), as kept in the public repositories named in
   ``app/report/pull_out_curves.py``, read at the curves' plotted points.
"""

import math

from app.core.formulas.declare import formula

#: Full steps per electrical cycle of a two-phase hybrid: the rotor's teeth number
#: N_r = 360 / (4 x step angle), 50 for a 1.8 deg motor.
STEPS_PER_CYCLE = 4.0

DEGREES_PER_TURN = 360.0
SECONDS_PER_MINUTE = 60.0
#: The share of the supply up to which the back-EMF amplitude may rise with the circuit
#: model confirmed: the published points lie within 15 % of it below about 40 % (the
#: 23HS32-4004S at 36 V: 37 % of the supply, 3 % high), and run high above it (48 %,
#: 22 % high) [7]. Past it the model falls as 1 / speed (``microstep_pull_out_torque``).
CONFIRMED_BACK_EMF_SHARE = 0.4
#: The least supply the model is valid for, in multiples of the winding's rated voltage
#: I R (Trinamic QSH4218 manual, Table 6.2: a supply 4 to 22 times I R) [6].
LEAST_SUPPLY_PER_IR = 4.0


def least_supply_v(current_a: float, resistance_ohm: float) -> float:
    """The least supply of the model's range [V]: ``LEAST_SUPPLY_PER_IR`` times the
    winding's rated voltage I R (``current_a`` [A], ``resistance_ohm`` [ohm]).

    >>> round(least_supply_v(0.64, 14.5), 6)
    37.12
    """
    return LEAST_SUPPLY_PER_IR * current_a * resistance_ohm


def supply_in_range(supply_v: float, current_a: float, resistance_ohm: float) -> bool:
    """The supply [V] is at least ``least_supply_v``: the model's range.

    >>> supply_in_range(24.0, 0.64, 14.5), supply_in_range(48.0, 0.64, 14.5)
    (False, True)
    """
    return supply_v >= least_supply_v(current_a, resistance_ohm)


@formula(
    "n_c = 60 (V - I R) / (2 L I x 360 / step_angle)",
    "Farnell, Stepper motor calculator; Jones, Control of Stepping Motors",
)
def corner_speed_rpm(
    supply_v: float,
    current_a: float,
    resistance_ohm: float,
    inductance_h: float,
    step_angle_deg: float,
) -> float:
    """Speed [rpm] up to which the drive reaches the set phase current every full step:
    one full step (360 / step_angle per turn) lasts the current's reversal time
    2 L I / (V - I R) [s]. supply_v [V], current_a [A] (phase current set on the
    driver), resistance_ohm [ohm] and inductance_h [H] per phase, step_angle_deg [deg].

    Valid for a chopper (constant-current) drive with V well above I R; zero when the
    supply cannot drive the set current through the winding at all.

    Farnell's form (R neglected): 24 V, 2 mH, 1.5 A, 200 steps a turn gives
    24 / (2 x 0.002 x 1.5 x 200) = 20 rev/s = 1200 rpm:

    >>> corner_speed_rpm(24.0, 1.5, 0.0, 0.002, 1.8)
    1200.0
    >>> round(corner_speed_rpm(24.0, 2.0, 1.4, 0.003, 1.8))
    530
    """
    drive_v = max(supply_v - current_a * resistance_ohm, 0.0)
    full_steps = DEGREES_PER_TURN / step_angle_deg
    reversals_per_s = drive_v / (2.0 * inductance_h * current_a)
    return SECONDS_PER_MINUTE * reversals_per_s / full_steps


@formula("T(n) = T_h if n <= n_c else T_h n_c / n", "Farnell, Stepper motor calculator")
def pull_out_torque(rpm: float, holding_torque_nm: float, corner_rpm: float) -> float:
    """Pull-out torque [N m] at ``rpm`` [rev/min]: the holding torque [N m] (at the set
    current) up to the corner speed [rpm], then falling as corner / rpm (the current a
    step reaches is in proportion to the step's time: constant power).

    >>> pull_out_torque(500.0, 0.59, 530.0), round(pull_out_torque(1060.0, 0.59, 530.0), 3)
    (0.59, 0.295)
    """
    if rpm <= corner_rpm:
        return holding_torque_nm
    return holding_torque_nm * corner_rpm / rpm


def pull_out_curve(
    holding_torque_nm: float, corner_rpm: float, max_rpm: float, points: int = 24
) -> tuple[tuple[float, float], ...]:
    """The model's curve as (rpm, N m) points from standstill to ``max_rpm`` [rpm], for
    checks that read a curve as straight lines between its points: the corner, then
    ``points`` steps in equal ratios r to ``max_rpm``.

    The 1 / n fall is convex, so a chord between two of its points lies above it, by a
    factor of at most (1 + r)^2 / 4 r (at the chord's middle); every
    point from the corner on is lowered by that factor, so the straight lines lie on or
    below the model: the safe side (0.13 % for the library's 530-3000 rpm in 24 steps).
    From 530 to 2120 rpm in two steps (r = 2, the factor 9 / 8):

    >>> [(round(n), round(t, 4)) for n, t in pull_out_curve(0.59, 530.0, 2120.0, 2)]
    [(0, 0.59), (530, 0.5244), (1060, 0.2622), (2120, 0.1311)]
    >>> pull_out_curve(0.59, 530.0, 300.0)
    ((0.0, 0.59), (300.0, 0.59))
    """
    if corner_rpm >= max_rpm:
        return ((0.0, holding_torque_nm), (max_rpm, holding_torque_nm))
    ratio = (max_rpm / corner_rpm) ** (1.0 / points)
    chord = (1.0 + ratio) ** 2 / (4.0 * ratio)
    speeds = [corner_rpm * ratio**i for i in range(points)] + [max_rpm]
    return (
        (0.0, holding_torque_nm),
        *((n, pull_out_torque(n, holding_torque_nm, corner_rpm) / chord) for n in speeds),
    )


@formula("k_e = T_h / (sqrt(2) I)", "Duet3D documentation, back emf due to rotation (D. Crocker)")
def back_emf_constant(holding_torque_nm: float, current_a: float) -> float:
    """The back-EMF constant [V s/rad, peak per phase], equal to the torque constant
    [N m per A peak], of a two-phase stepper whose ``holding_torque_nm`` [N m] is given
    with both phases at ``current_a`` [A] (its rated current): both phases at I act as
    one phase at sqrt(2) I, so T_h = k_e sqrt(2) I.

    Valid for a hybrid or permanent-magnet stepper; if the datasheet gives the holding
    torque with one phase on, k_e is sqrt(2) times higher. Published scatter: one motor
    measured 24 V against 24.24 V from the formula (Duet3D), others measured 20-25 %
    below it (R. Carlyle, StepperSim issue #38), so it estimates k_e on the high side.

    Duet3D's worked example: 0.55 N m at 1.68 A, turning at 5 rev/s (10 pi rad/s), gives
    a peak back-EMF of sqrt(2) pi 0.55 x 5 / 1.68 = 7.3 V:

    >>> round(back_emf_constant(0.55, 1.68) * 2 * math.pi * 5, 1)
    7.3
    """
    return holding_torque_nm / (math.sqrt(2.0) * current_a)


def _rightmost_common_point(centre: complex, radius: float, limit: float) -> float | None:
    """The largest real part of a point inside both the disc |z| <= ``limit`` and the disc
    |z - centre| <= ``radius`` (None when they do not meet)."""
    gap = abs(centre)
    if gap > limit + radius:
        return None
    if abs(limit - centre) <= radius:
        return limit
    if abs(centre + radius) <= limit:
        return centre.real + radius
    along = (limit**2 - radius**2 + gap**2) / (2.0 * gap)
    across = math.sqrt(max(limit**2 - along**2, 0.0))
    unit = centre / gap
    return max((along * unit + 1j * side * across * unit).real for side in (1.0, -1.0))


@formula(
    "T = k_e max Re(I): |I| <= sqrt(2) I_set, |E + I (R + j N_r w L)| <= V, E = k_e w",
    "per-phase circuit (MathWorks, Stepper Motor block); k_e from Duet3D's back-EMF formula",
)
def sine_pull_out_torque(
    rpm: float,
    supply_v: float,
    current_a: float,
    resistance_ohm: float,
    inductance_h: float,
    step_angle_deg: float,
    holding_torque_nm: float,
) -> float:
    """Pull-out torque [N m] at ``rpm`` of a two-phase stepper on a sine (microstepping)
    chopper drive, back-EMF included. Each phase is the circuit V = E + I (R + j X):
    back-EMF E = k_e w in phase with the torque-making current, reactance X = N_r w L at
    the electrical frequency (N_r = 90 / step_angle_deg rotor teeth), current amplitude
    at most sqrt(2) ``current_a`` (the set RMS current) and phase voltage at most
    ``supply_v`` [V]. The torque is k_e times the largest in-phase current both limits
    allow (two phases in quadrature give a steady k_e |I| cos psi). ``resistance_ohm``
    [ohm] and ``inductance_h`` [H] per phase; k_e from ``back_emf_constant``.

    Valid in steady running, below saturation; no resonance, detent torque, chopper
    dead time or iron loss. At low speed it is the holding torque; fast, with R small,
    it tends to k_e V / X, falling as 1 / speed like ``pull_out_torque``.

    >>> sine_pull_out_torque(30.0, 24.0, 2.0, 1.4, 0.003, 1.8, 0.59)
    0.59
    >>> round(sine_pull_out_torque(1060.0, 24.0, 2.0, 1.4, 0.003, 1.8, 0.59), 3)
    0.275
    """
    k_e = back_emf_constant(holding_torque_nm, current_a)
    amplitude_a = math.sqrt(2.0) * current_a
    return _circuit_torque(
        rpm, supply_v, amplitude_a, resistance_ohm, inductance_h, step_angle_deg, k_e
    )


def _circuit_torque(
    rpm: float,
    supply_v: float,
    amplitude_a: float,
    resistance_ohm: float,
    inductance_h: float,
    step_angle_deg: float,
    k_e: float,
) -> float:
    """k_e times the largest in-phase current amplitude [A] the phase circuit allows at
    ``rpm``: |I| <= ``amplitude_a`` and |E + I (R + j N_r w L)| <= ``supply_v``."""
    omega = 2.0 * math.pi * rpm / SECONDS_PER_MINUTE
    teeth = DEGREES_PER_TURN / (STEPS_PER_CYCLE * step_angle_deg)
    impedance = complex(resistance_ohm, teeth * omega * inductance_h)
    if abs(impedance) == 0.0:
        return k_e * amplitude_a
    centre = -k_e * omega / impedance
    in_phase = _rightmost_common_point(centre, supply_v / abs(impedance), amplitude_a)
    return 0.0 if in_phase is None else k_e * max(in_phase, 0.0)


@formula(
    "T = k_e max Re(I): |I| <= a I_set (a = 1 peak-set, sqrt 2 RMS-set), "
    "|E + I (R + j N_r w L)| <= V, k_e = T_h / (sqrt(2) I_set); past n_c (k_e w_c = 0.4 V) "
    "T = T(n_c) n_c / n",
    "per-phase circuit (MathWorks, Stepper Motor block); two-coils-on holding torque "
    "(Carlyle, StepperSim #38); RMS-set drives: Trinamic QSH4218 manual sec. 6.5; the "
    "confirmed range from STEPPERONLINE's and Trinamic's published pull-out curves",
)
def microstep_pull_out_torque(
    rpm: float,
    supply_v: float,
    current_a: float,
    resistance_ohm: float,
    inductance_h: float,
    step_angle_deg: float,
    holding_torque_nm: float,
    current_is_rms: bool = False,
) -> float:
    """Pull-out torque [N m] at ``rpm`` [rev/min] of a two-phase hybrid stepper on a sine
    (microstepping) chopper drive set to ``current_a`` [A] per phase (the motor's rated
    current): the sine's amplitude is ``current_a`` where the drive sets the peak, and
    sqrt(2) ``current_a`` where it sets the RMS (``current_is_rms``, as Trinamic's do).
    The datasheet's ``holding_torque_nm`` [N m] is with both phases at the rated current,
    a current vector sqrt(2) times it, so the torque constant is k_e = T_h / (sqrt(2) I)
    (``back_emf_constant``) and at low speed the torque is k_e times the amplitude:
    T_h / sqrt(2) peak-set, T_h RMS-set. Faster, each phase is the circuit
    V = E + I (R + j X): back-EMF E = k_e w, reactance X = N_r w L (N_r = 90 /
    ``step_angle_deg`` rotor teeth), phase voltage at most ``supply_v`` [V];
    ``resistance_ohm`` [ohm] and ``inductance_h`` [H] per phase. Past
    ``confirmed_range_rpm`` n_c, where makers' curves fall sooner than the circuit, the
    torque falls as 1 / speed from the circuit's torque at n_c, never above the circuit.
    An RMS-set drive, whose current and low-speed torque are sqrt(2) times higher,
    leaves the confirmed range at n_c / sqrt(2): past it both readings fall along the
    same T n = constant, as what the supply can drive at speed does not depend on the
    current set.

    Validity: as the module states (sine drive, supply 4 to 25 times I R; confirmed up to
    n_c, 0.73 to 1.11 times the published points past it; no resonance or saturation).

    STEPPERONLINE 23HS32-4004S (2.4 N m, 4.0 A, 0.65 ohm, 3.2 mH) on a DM542T at 36 V
    [7]: k_e = 0.424 V s/rad, n_c = 0.4 x 36 / 0.424 = 33.9 rad/s = 324 rpm. At 600 rpm
    the circuit still gives 1.43 N m, 39 % above the published 1.03; the model gives
    1.697 x 324 / 600 = 0.917 N m, 11 % below:

    >>> args = (36.0, 4.0, 0.65, 0.0032, 1.8, 2.4)
    >>> round(microstep_pull_out_torque(600.0, *args), 3)
    0.917

    Trinamic QSH4218-47-28-040 (0.40 N m, 2.8 A, 0.5 ohm, 0.6 mH) gives 0.25 N m at
    1200 rpm on 24 V, its drive set to 2.8 A RMS [6]: k_e = 0.101 V s/rad, n_c =
    0.4 x 24 / 0.101 = 95.0 rad/s = 907 rpm. Read as the drive sets it (RMS) the
    low-speed torque is the whole 0.40 N m, kept to 907 / sqrt 2 = 641 rpm, then
    0.40 x 641 / 1200 = 0.214 N m (14 % low; the circuit alone gives 0.40 there, 60 %
    high); read as a peak, 0.283 N m to 907 rpm, then the same 0.214 N m:

    >>> round(microstep_pull_out_torque(1200.0, 24.0, 2.8, 0.5, 0.0006, 1.8, 0.40, True), 3)
    0.214
    >>> round(microstep_pull_out_torque(1200.0, 24.0, 2.8, 0.5, 0.0006, 1.8, 0.40), 3)
    0.214
    """
    k_e = back_emf_constant(holding_torque_nm, current_a)
    amplitude_a = current_a * (math.sqrt(2.0) if current_is_rms else 1.0)
    circuit = (supply_v, amplitude_a, resistance_ohm, inductance_h, step_angle_deg, k_e)
    torque = _circuit_torque(rpm, *circuit)
    confirmed_rpm = confirmed_range_rpm(supply_v, current_a, holding_torque_nm, current_is_rms)
    if rpm <= confirmed_rpm:
        return torque
    return min(torque, _circuit_torque(confirmed_rpm, *circuit) * confirmed_rpm / rpm)


@formula(
    "n_c = 60 (0.4 V) / (2 pi k_e), k_e = T_h / (sqrt(2) I)",
    "back-EMF amplitude k_e w (Duet3D); the share 0.4 from STEPPERONLINE's published "
    "23HS32-4004S curves (within 15 % below it, 22 % high above it)",
)
def confirmed_range_rpm(
    supply_v: float, current_a: float, holding_torque_nm: float, current_is_rms: bool = False
) -> float:
    """The speed [rpm] at which the back-EMF amplitude k_e w reaches
    ``CONFIRMED_BACK_EMF_SHARE`` (0.4) of the supply ``supply_v`` [V], k_e from the
    ``holding_torque_nm`` [N m] at the rated ``current_a`` [A] (``back_emf_constant``):
    the top of the range where the phase circuit is confirmed by the published curves;
    past it ``microstep_pull_out_torque`` falls as 1 / speed. A drive that sets the RMS
    (``current_is_rms``) leaves it at 1 / sqrt(2) of that speed (its current and
    low-speed torque sqrt(2) times higher: the same T n past it).

    The 23HS32-4004S (2.4 N m, 4.0 A) on 36 V: k_e = 2.4 / (sqrt 2 x 4.0) =
    0.424 V s/rad, n_c = 60 x 0.4 x 36 / (2 pi x 0.424) = 324 rpm:

    >>> round(confirmed_range_rpm(36.0, 4.0, 2.4))
    324
    """
    k_e = back_emf_constant(holding_torque_nm, current_a)
    rms = math.sqrt(0.5) if current_is_rms else 1.0
    return rms * SECONDS_PER_MINUTE * CONFIRMED_BACK_EMF_SHARE * supply_v / (2.0 * math.pi * k_e)


def microstep_pull_out_curve(
    args: tuple[float, float, float, float, float, float],
    max_rpm: float,
    points: int = 48,
    first_rpm: float = 30.0,
    current_is_rms: bool = False,
) -> tuple[tuple[float, float], ...]:
    """``microstep_pull_out_torque`` as (rpm, N m) points from standstill to ``max_rpm``,
    for checks that read a curve as straight lines between its points. ``args`` are that
    function's arguments after the speed (supply, current, resistance, inductance, step
    angle, holding torque), ``current_is_rms`` its last. The speeds are 0, then
    ``points`` steps in equal ratios from ``first_rpm`` to ``max_rpm``; each point
    carries the torque of the next speed, so (the torque never rising with speed) the
    straight lines lie on or below the model everywhere: the safe side. The curve ends
    before the first speed at which the model gives no torque (the back-EMF alone takes
    the supply).

    >>> curve = microstep_pull_out_curve((24.0, 2.8, 0.5, 0.0006, 1.8, 0.40), 3000.0, 4)
    >>> [(round(n), round(t, 3)) for n, t in curve]
    [(0, 0.283), (30, 0.283), (95, 0.283), (300, 0.271), (949, 0.086), (3000, 0.086)]
    """
    ratio = (max_rpm / first_rpm) ** (1.0 / points)
    speeds = [0.0] + [first_rpm * ratio**i for i in range(points)] + [max_rpm]
    torques = [microstep_pull_out_torque(n, *args, current_is_rms) for n in speeds]
    curve = []
    for i, rpm in enumerate(speeds):
        torque = torques[min(i + 1, len(speeds) - 1)]
        if torque <= 0.0:
            break
        curve.append((rpm, torque))
    return tuple(curve)
