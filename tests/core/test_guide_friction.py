"""The guides' friction on a horizontal axis's moving mass (``motion.guide_friction_n``):
mu_g m g against the motion in every moving segment's nut force; none at rest, none on a
vertical axis, and on a lower axis of a machine over the mass it carries too."""

from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.core import motion
from app.core.machine import Axis, size_machine
from app.core.model import STANDARD_GRAVITY_M_S2, Application, Move
from app.core.quantities import axial_load, peak_axial_load

#: 10 kg on guides of mu 0.1, a 10 N load against the motion, 3 m/s^2 up to speed and
#: 5 m/s^2 down from it.
APP = Application(
    load_n=10.0,
    speed_m_s=0.1,
    length_m=0.5,
    moving_mass_kg=10.0,
    accel_m_s2=3.0,
    decel_m_s2=5.0,
    guide_friction=0.1,
)


def test_the_nut_pushes_the_guides_friction_in_every_moving_segment() -> None:
    # the guides: 0.1 x 10 kg x 9.80665 m/s^2 = 9.80665 N against the motion; out, the
    # nut pushes m a + F + mu m g while accelerating (30 + 10 + 9.80665), F + mu m g at
    # speed, -m d + F + mu m g braking (-50 + 10 + 9.80665); back, the same mirrored; at
    # rest nothing (friction holds nothing)
    f = 0.1 * 10.0 * 9.80665
    out = [30.0 + 10.0 + f, 10.0 + f, -50.0 + 10.0 + f]
    assert motion.nut_forces(APP) == pytest.approx([*out, *(-x for x in out), 0.0], rel=1e-12)
    assert axial_load(APP) == pytest.approx(10.0 + f, rel=1e-12)
    assert peak_axial_load(APP) == pytest.approx(49.80665, rel=1e-12)


def test_without_guide_friction_the_forces_are_as_before() -> None:
    # Newton alone: 30 + 10, 10, -50 + 10 out; mirrored back
    out = [40.0, 10.0, -40.0]
    plain = replace(APP, guide_friction=0.0)
    assert motion.nut_forces(plain) == pytest.approx([*out, *(-x for x in out), 0.0], rel=1e-12)


def test_a_vertical_axis_guides_carry_no_weight() -> None:
    up = replace(APP, orientation="vertical", guide_friction=0.0)
    assert motion.nut_forces(replace(up, guide_friction=0.3)) == motion.nut_forces(up)
    assert axial_load(replace(up, guide_friction=0.3)) == axial_load(up)


def test_each_move_of_a_cycle_carries_the_friction_of_its_own_mass() -> None:
    # out with 10 kg, back with 4 kg (a part put down): mu m g is 9.80665 N then 3.92266 N
    moves = (
        Move(0.2, 0.1, 3.0, 3.0, 0.5, 10.0, 0.0, "opposes"),
        Move(-0.2, 0.1, 3.0, 3.0, 0.5, 4.0, 0.0, "opposes"),
    )
    app = replace(APP, moves=moves, load_n=0.0)
    running = [motion.running_thrust(app, m) for m in moves]
    assert running == pytest.approx([0.1 * 10.0 * 9.80665, 0.1 * 4.0 * 9.80665], rel=1e-12)


def test_a_lower_axis_guides_carry_the_axes_above_it(catalog: Catalog) -> None:
    z = Application(
        load_n=0.0, speed_m_s=0.05, length_m=0.3, moving_mass_kg=2.0,
        orientation="vertical", lead_m=0.004,
    )  # fmt: skip
    x = Application(
        load_n=0.0, speed_m_s=0.05, length_m=0.5, moving_mass_kg=3.0, guide_friction=0.05
    )
    m = size_machine([Axis("Z", z, frame_kg=1.0), Axis("X", x)], catalog.index, {}, {})
    lower = m.axes[1]
    carried = lower.carried_kg
    assert carried > 3.0  # Z's 2 kg carriage, 1 kg frame and its screw
    expected = 0.05 * (3.0 + carried) * STANDARD_GRAVITY_M_S2
    assert axial_load(lower.app) == pytest.approx(expected, rel=1e-12)
