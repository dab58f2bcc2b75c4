"""A cycle of moves: out and back typed as moves gives today's answers; a pick-and-place
cycle's torques, wear thrust and energy against arithmetic done by hand."""

import math
from dataclasses import replace

import numpy as np
import pytest

from app.core import motion
from app.core.evaluate import evaluate
from app.core.model import STANDARD_GRAVITY_M_S2, Application, Move, ScrewSpec
from app.core.quantities import NAMES, Quantities, operating_point, quantity
from app.core.table import CandidateTable
from tests.core.conftest import light_app

#: Numbers that differ by design between the scalar inputs and the same cycle as moves:
#: the acceleration and the top speed that would fit the curve are remedies of the scalar
#: acceleration and speed.
SCALAR_ONLY = {
    "motor_fitting_accel_m_s2",
    "motor_fitting_speed_m_s",
    "motor_fix_accel_m_s2",
    "motor_fix_speed_m_s",
}


def _same_numbers(a: Quantities[np.ndarray], b: Quantities[np.ndarray]) -> None:
    for name in NAMES:
        if name not in SCALAR_ONLY:
            assert np.array_equal(quantity(a, name), quantity(b, name), equal_nan=True), name


@pytest.mark.parametrize(
    "changes",
    [
        {},
        {"orientation": "vertical", "moving_mass_kg": 8.0},
        {"load_direction": "fixed", "decel_m_s2": 3.0, "dwell_s": 0.4},
        {"orientation": "vertical", "load_direction": "opposes", "moving_mass_kg": 3.0},
        {"stroke_m": 0.01, "speed_m_s": 0.3, "accel_m_s2": 2.0},  # a triangle
    ],
    ids=["horizontal", "vertical", "fixed-load", "vertical-opposing", "triangle"],
)
def test_out_and_back_typed_as_moves_gives_the_same_numbers(
    changes: dict[str, object], zbx8000_l10: ScrewSpec, b8000_l10: ScrewSpec
) -> None:
    """The two moves ``motion.cycle`` builds from the scalar inputs, typed as moves, give
    every number of the operating point the scalar inputs give, to the last bit."""
    base = {"stroke_m": 0.2, "accel_m_s2": 1.5, "moving_mass_kg": 2.0, "dwell_s": 0.1}
    app = light_app(
        **{**base, **changes}, motor_inertia_kg_m2=3e-6, cycles_per_day=500.0,
        required_life_years=1.0, support_dynamic_n=5000.0, step_angle_deg=1.8,
        motor_phase_current_a=2.0, motor_resistance_ohm=1.4,
    )  # fmt: skip
    typed = replace(app, moves=motion.cycle(app))
    table = CandidateTable.build([zbx8000_l10, b8000_l10])
    _same_numbers(operating_point(app, table), operating_point(typed, table))


def _pick_and_place(**changes: object) -> Application:
    """A horizontal pick-and-place: 2.5 kg out (a 2 kg part on a 0.5 kg carriage), the
    carriage alone back, 300 mm each way at 250 mm/s, 2.5 m/s^2 both ramps, 0.2 s dwell
    after each, a 10 N drag (cable chain) against the motion both ways."""
    out = Move(0.3, 0.25, 2.5, 2.5, 0.2, 2.5, 10.0, "opposes")
    back = Move(-0.3, 0.25, 2.5, 2.5, 0.2, 0.5, 10.0, "opposes")
    app = light_app(load_n=10.0, speed_m_s=0.25, stroke_m=0.3, moves=(out, back))
    return replace(app, **changes)  # type: ignore[arg-type]


def test_pick_and_place_thrusts_torques_and_rms_by_hand(b8000_l10: ScrewSpec) -> None:
    """Each ramp 0.1 s and 12.5 mm, the cruise 1.1 s, the cycle 2 (1.3 + 0.2) = 3 s.
    Thrusts out: 10 + 2.5 x 2.5 = 16.25, 10, 10 - 6.25 = 3.75 N; back: 11.25, 10, 8.75 N.
    Torques F lead / (2 pi eta) driving, F lead eta_b / (2 pi) driven (none here: every
    thrust is positive), plus (J_screw + J_rotor) alpha on the ramps."""
    app = _pick_and_place(motor_inertia_kg_m2=8.2e-6)
    ev = evaluate(app, b8000_l10)
    assert ev.motion is not None
    lead, eta = b8000_l10.lead_m, ev.efficiency
    j = b8000_l10.inertia_kg_m2_per_m * app.length_m + 8.2e-6
    alpha = 2 * math.pi * 2.5 / lead
    thrusts = [16.25, 10.0, 3.75, 0.0, 11.25, 10.0, 8.75, 0.0]
    spins = [j * alpha, 0.0, -j * alpha, 0.0] * 2
    times = [0.1, 1.1, 0.1, 0.2] * 2
    hand = [
        (f * lead / (2 * math.pi * eta) + spin if k % 4 != 3 else 0.0)
        for k, (f, spin) in enumerate(zip(thrusts, spins, strict=True))
    ]
    assert [s.thrust_n for s in ev.motion.segments] == pytest.approx(thrusts)
    assert [s.duration_s for s in ev.motion.segments] == pytest.approx(times)
    assert [s.torque_nm for s in ev.motion.segments] == pytest.approx(hand)
    rms = math.sqrt(sum(t * t * d for t, d in zip(hand, times, strict=True)) / 3.0)
    assert ev.motion.rms_nm == pytest.approx(rms)
    assert ev.motion.peak_nm == pytest.approx(max(abs(t) for t in hand))
    assert ev.peak_axial_load_n == pytest.approx(16.25)


def test_pick_and_place_wear_thrust_and_life_by_hand(b8000_l10: ScrewSpec) -> None:
    """Archard over the cycle's segments: sum |F| x / sum x = (16.25 + 3.75 + 11.25 +
    8.75) 0.0125 + 4 x 10 x 0.275 ... over 0.6 m = 10 N; the travel of the cycle is
    0.6 m, so a life of L metres is L / (0.6 x cycles/day x 365) years."""
    app = _pick_and_place(cycles_per_day=10_000.0)
    q = evaluate(app, b8000_l10).quantities
    ramps = (16.25 + 3.75 + 11.25 + 8.75) * 0.0125
    assert q.life.wear_force_n == pytest.approx((ramps + 2 * 10.0 * 0.275) / 0.6)
    assert q.life.wear_life_years == pytest.approx(q.life.wear_travel_m / (0.6 * 10_000.0 * 365.0))


def test_a_heavier_return_wears_more_than_the_empty_one(b8000_l10: ScrewSpec) -> None:
    """A property that can fail: a return with 6 kg raises the RMS torque; its braking
    (6 x 2.5 = 15 N, above the 10 N drag) turns the thrust around, so the flanks wear on
    both sides and the wear life shortens (with less mass the ramps' +m a and -m a cancel
    in Archard's sum, and the wear is the same)."""
    empty = evaluate(_pick_and_place(cycles_per_day=10_000.0), b8000_l10)
    out, back = _pick_and_place().moves
    full_app = _pick_and_place(
        cycles_per_day=10_000.0, moves=(out, replace(back, moving_mass_kg=6.0))
    )
    full = evaluate(full_app, b8000_l10)
    assert full.motion is not None and empty.motion is not None
    assert full.motion.rms_nm > empty.motion.rms_nm
    assert full.quantities.life.wear_life_years < empty.quantities.life.wear_life_years


def test_energy_balance_and_hand_values(b8000_l10: ScrewSpec) -> None:
    """No mass, 10 N against the motion both ways, 0.3 m out and back: the load takes
    10 x 0.6 = 6 J a cycle, the thread 6 (1/eta - 1) J, and nothing comes back."""
    moves = tuple(replace(m, moving_mass_kg=0.0) for m in _pick_and_place().moves)
    q = evaluate(_pick_and_place(moves=moves), b8000_l10).quantities
    eta = evaluate(_pick_and_place(moves=moves), b8000_l10).efficiency
    assert q.energy.cycle_load_work_j == pytest.approx(6.0)
    assert q.energy.cycle_thread_loss_j == pytest.approx(6.0 * (1 / eta - 1))
    assert q.energy.cycle_motor_work_j == pytest.approx(6.0 / eta)
    assert q.energy.cycle_regen_j == pytest.approx(0.0)


@pytest.mark.parametrize("orientation", ["horizontal", "vertical"])
def test_energy_balances_over_the_cycle(orientation: str, zbx8000_l10: ScrewSpec) -> None:
    """Work in less work given back = work on the load + thread + drag: the inertia's
    kinetic energy cancels over each move (a property that fails if a segment's travel or
    torque is wrong). On a vertical axis the load's net work is W (0) over the round
    trip, less than the motor's; the lowering gives energy back."""
    app = _pick_and_place(orientation=orientation, motor_inertia_kg_m2=8.2e-6)
    q = evaluate(app, zbx8000_l10).quantities
    assert q.energy.cycle_drag_loss_j > 0.0  # the anti-backlash nut drags
    balance = q.energy.cycle_load_work_j + q.energy.cycle_thread_loss_j + q.energy.cycle_drag_loss_j
    assert q.energy.cycle_motor_work_j - q.energy.cycle_regen_j == pytest.approx(balance)
    if orientation == "vertical":
        # up with 2.5 kg, down with 0.5 kg: the net work on the weight is (2.5 - 0.5) g 0.3
        weight_work = (2.5 - 0.5) * STANDARD_GRAVITY_M_S2 * 0.3
        assert q.energy.cycle_load_work_j == pytest.approx(6.0 + weight_work)


def test_lowering_gives_energy_back(b8000_l10: ScrewSpec) -> None:
    """Vertical, no external load, B8000-L10 (no drag, it back-drives): lowering 2.5 kg
    at constant speed gives back W x eta_b over the cruise, 2.5 g x 0.275 m x eta_b,
    and its deceleration more; raising it takes W x / eta and more."""
    moves = tuple(replace(m, load_n=0.0, moving_mass_kg=2.5) for m in _pick_and_place().moves)
    app = _pick_and_place(orientation="vertical", moves=moves)
    ev = evaluate(app, b8000_l10)
    weight = 2.5 * STANDARD_GRAVITY_M_S2
    cruise_back = weight * 0.275 * ev.backdrive_efficiency_running
    assert ev.quantities.energy.cycle_regen_j > cruise_back
    assert ev.quantities.energy.cycle_motor_work_j > weight * 0.275 / ev.efficiency
    # the weight raised and lowered again does no work: 0, not the sum's rounding
    assert ev.quantities.energy.cycle_load_work_j == 0.0


def test_stepper_copper_loss_over_the_cycle(b8000_l10: ScrewSpec) -> None:
    """A stepper at 2 A, 1.4 ohm over the 3 s cycle. Microstepping, the 2 A the sine's peak:
    the two windings lose I_p^2 R = 5.6 W together, 16.8 J. At full steps both windings
    carry the full 2 A all the time: 2 x 2^2 x 1.4 = 11.2 W, 33.6 J. The same 2 A set as
    RMS and microstepped: 2 I_rms^2 R, 33.6 J too. A servo (no step angle) has no copper
    loss to report."""
    stepper = _pick_and_place(
        step_angle_deg=1.8, motor_phase_current_a=2.0, motor_resistance_ohm=1.4, microsteps=16
    )
    assert evaluate(stepper, b8000_l10).quantities.energy.cycle_copper_loss_j == pytest.approx(16.8)
    for app in (replace(stepper, microsteps=1), replace(stepper, motor_current_rms=True)):
        assert evaluate(app, b8000_l10).quantities.energy.cycle_copper_loss_j == pytest.approx(33.6)
    servo = replace(stepper, step_angle_deg=None)
    assert math.isnan(evaluate(servo, b8000_l10).quantities.energy.cycle_copper_loss_j)


def test_fastest_move_sets_the_step_rate_and_speed_checks(b8000_l10: ScrewSpec) -> None:
    """A slow out move and a fast return: the peak rpm is the fast one's, 0.5 m/s over a
    10 mm lead = 3000 rpm = 50 turns/s, 50 x 200 full steps x 2 microsteps = 20000 steps/s."""
    out, back = _pick_and_place().moves
    app = _pick_and_place(
        moves=(out, replace(back, speed_m_s=0.5, accel_m_s2=5.0, decel_m_s2=5.0)),
        step_angle_deg=1.8,
        microsteps=2,
    )
    q = evaluate(app, b8000_l10).quantities
    assert motion.reached_speed(app) == pytest.approx(0.5)
    assert q.motor.peak_rpm == pytest.approx(3000.0)
    assert q.motor.step_rate_hz == pytest.approx(20_000.0)


def test_a_dwell_holds_the_heavier_of_the_moves_beside_it(zbx8000_l10: ScrewSpec) -> None:
    """Vertical: the 2.5 kg move up, then the 0.5 kg move down (the part placed at the
    top). The dwell after the move up holds 2.5 g; the one after the move down, before
    the next move up with 2.5 kg, holds 2.5 g too, not 0.5 g: the part picked in that
    dwell may weigh on the nut for all of it (it held 0.5 g, and the RMS read low)."""
    app = _pick_and_place(orientation="vertical")
    ev = evaluate(app, zbx8000_l10)
    assert ev.motion is not None
    dwells = [s for s in ev.motion.segments if s.name == "dwell"]
    assert [d.thrust_n for d in dwells] == pytest.approx([2.5 * STANDARD_GRAVITY_M_S2] * 2)
    assert dwells[1].torque_nm == pytest.approx(dwells[0].torque_nm)


def test_the_inertia_ratio_takes_the_heaviest_move(b8000_l10: ScrewSpec) -> None:
    """Out empty and fast (0.5 kg at 10 m/s^2: 10 + 5 = 15 N to start, the move that
    starts hardest), back with a 6 kg part and slowly (0.5 m/s^2: 10 + 3 = 13 N): the
    motor controls the 6 kg on the way back, so the load's inertia at the motor is
    J_screw + 6 (lead / 2 pi)^2 (Oriental Motor, Motor Sizing Calculations: the load
    inertia of the moving mass). It took the lead move's 0.5 kg, a ratio of 4.2 that
    passed the guide of 10 where the 6 kg gives 11.2."""
    out, back = _pick_and_place().moves
    moves = (
        replace(out, moving_mass_kg=0.5, accel_m_s2=10.0, decel_m_s2=10.0),
        replace(back, moving_mass_kg=6.0, accel_m_s2=0.5, decel_m_s2=0.5),
    )
    rotor = 2e-6
    app = _pick_and_place(moves=moves, motor_inertia_kg_m2=rotor)
    ev = evaluate(app, b8000_l10)
    assert motion.lead_move(app) is moves[0]
    j_screw = b8000_l10.inertia_kg_m2_per_m * app.length_m
    load = j_screw + 6.0 * (b8000_l10.lead_m / (2.0 * math.pi)) ** 2
    assert ev.quantities.torque.inertia_kg_m2 == pytest.approx(load, rel=1e-12)
    ratio = next(c for c in ev.checks if c.name == "inertia_ratio")
    assert ratio.value == pytest.approx(load / rotor, rel=1e-12)
    assert ratio.value == pytest.approx(11.2, abs=0.05)
    assert not ratio.passed
