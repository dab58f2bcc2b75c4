"""A servo maker's multi-segment sizing example through the app's own cycle: Weihong, WISE
servo (WSDV) user manual, sec. 3.5.2.1 "Example of Motor Selection for Ball Screw System",
pp. 25-27 (https://www.easymanua.ls/weihong/wise-wsdv-6r820psb/manual?p=31,
https://manualshive.com/ru/manual/weihong/wise-wsdv-11020psb/952565?page=32,
https://www.easymanua.ls/weihong/wise-wsdv-2r820psb/manual?p=33).

The maker's numbers, as printed: load inertia J_L = 1.73e-4 kg m^2 (p. 26, step 4), the
constant torque T_f = 0.035 N m, acceleration torque T_a = 0.231, deceleration torque
T_d = 0.161 N m and the effective torque T_rms = 0.067 N m (p. 27, steps 9 and 11)."""

import math
from dataclasses import replace

import numpy as np
import pytest

from app.core import motion, segments
from app.core.formulas import torque
from app.core.table import CandidateTable
from app.core.timeline import Segment
from app.report import maker_examples as examples

#: Each published value, and the published rounding it is held to (1 %).
WITHIN = 0.01


def _parts() -> list[Segment[np.ndarray]]:
    app = examples.weihong_application()
    return segments.segments(app, CandidateTable.build([examples.weihong_screw()]), np.zeros(1))


def test_the_screw_carries_the_stated_efficiency_and_the_maker_load_inertia() -> None:
    """J_L = J_C + W B_P^2 / (4 pi^2) + W_B B_D^2 / 8 with W_B = pi (0.01)^2 x 7900 x 0.5 =
    1.24 kg: 1e-5 + 1.013e-4 + 0.620e-4 = 1.733e-4 kg m^2, printed 1.73e-4."""
    table = CandidateTable.build([examples.weihong_screw()])
    assert table.efficiency[0] == pytest.approx(0.9, abs=1e-12)
    app = examples.weihong_application()
    screw = torque.screw_inertia(table.inertia_kg_m2_per_m[0], app.length_m)
    load_inertia = screw + (app.motor_inertia_kg_m2 or 0.0) - examples.WEIHONG_J_MOTOR
    assert load_inertia == pytest.approx(1.73e-4, rel=WITHIN)


def test_every_segment_torque_matches_the_maker() -> None:
    """Speed 0.3 / 0.9 = 1/3 m/s (printed 0.334), 1000 rpm (printed 1002); the ramp
    a = 10/3 m/s^2, alpha = 2 pi a / lead = 1047 rad/s^2 (the maker's 2 pi 16.7 / 0.1 =
    1049). T_f = 9.8 x 0.02 / (2 pi 0.9) = 0.03466 (printed 0.035, its rounding);
    (J_L + J_M) alpha = 1.874e-4 x 1047 = 0.1962; T_a = 0.1962 + 0.0347 = 0.2309
    (printed 0.231); T_d = 0.1962 - 0.0347 = 0.1616 (printed 0.161), braking. The stop
    holds nothing (a horizontal axis with friction alone)."""
    parts = _parts()
    assert [s.name for s in parts] == list(motion.ORDER) * 2
    assert [s.duration_s for s in parts] == pytest.approx([0.1, 0.8, 0.1, 1.0] * 2)
    torques = [float(s.torque_nm[0]) for s in parts]
    published = [0.231, 0.035, -0.161, 0.0] * 2
    for got, want in zip(torques, published, strict=True):
        assert got == pytest.approx(want, rel=WITHIN, abs=1e-12)


def test_rms_and_peak_match_the_maker_through_the_selection_path() -> None:
    """T_rms = sqrt((0.2309^2 x 0.1 + 0.0347^2 x 0.8 + 0.1616^2 x 0.1) / 2) = 0.0667
    (printed 0.067): the same from ``segments.rms`` over the segments and from the
    operating point the selection reports; the peak is T_a."""
    q = examples.weihong_cycle()
    assert float(segments.rms(_parts())[0]) == pytest.approx(
        float(q.motor.motor_rms_nm[0]), rel=1e-12
    )
    assert q.motor.motor_rms_nm[0] == pytest.approx(0.067, rel=WITHIN)
    assert q.motor.motor_peak_nm[0] == pytest.approx(0.231, rel=WITHIN)
    by_hand = math.sqrt((0.2309**2 * 0.1 + 0.03466**2 * 0.8 + 0.1616**2 * 0.1) / 2.0)
    assert q.motor.motor_rms_nm[0] == pytest.approx(by_hand, rel=1e-3)


def test_the_app_own_model_asks_more_than_the_maker() -> None:
    """The app passes m a through the thread at its efficiency, where the maker adds the
    table's reflected inertia outside it: the peak is T_a + (1/0.9 - 1) x 10 x 10/3 x
    0.02 / (2 pi) = 0.2309 + 0.0118 = 0.2427 N m; the braking segment lets the load drive
    the screw, so the RMS rises less (0.0682 against 0.0667)."""
    maker, own = examples.weihong_cycle(), examples.weihong_cycle(mass_as_inertia=False)
    extra = (1 / 0.9 - 1) * 10.0 * (10.0 / 3.0) * 0.02 / (2 * math.pi)
    assert own.motor.motor_peak_nm[0] == pytest.approx(
        maker.motor.motor_peak_nm[0] + extra, rel=1e-9
    )
    assert (
        maker.motor.motor_rms_nm[0] < own.motor.motor_rms_nm[0] < 1.03 * maker.motor.motor_rms_nm[0]
    )


def test_a_longer_stop_lowers_the_rms_as_the_square_root_of_the_cycle() -> None:
    """Doubling the cycle (each stop 1 s -> 3 s, the cycle 2 s -> 4 s a half) halves the
    mean square: the RMS falls by sqrt 2. A property of the cycle's timing that would fail
    if the stop were left out of the cycle time."""
    app = examples.weihong_application()
    longer = replace(app, moves=tuple(replace(m, dwell_s=3.0) for m in app.moves))
    table = CandidateTable.build([examples.weihong_screw()])
    base = segments.rms(segments.segments(app, table, np.zeros(1)))[0]
    slow = segments.rms(segments.segments(longer, table, np.zeros(1)))[0]
    assert slow == pytest.approx(base / math.sqrt(2.0), rel=1e-12)
