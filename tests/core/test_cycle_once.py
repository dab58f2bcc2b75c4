"""The cycle worked out once per query (``motion.cycle_of``): each of its numbers is what
the function it names gives for the same application, to the bit, so handing it down
in place of those calls moves no number."""

import pytest

from app.core import motion
from app.core.model import Application, Move
from app.core.quantities import axial_load, peak_axial_load

BASE = Application(load_n=100.0, speed_m_s=0.05, length_m=0.5)
#: name -> application: no stroke, a stroke with hours a day (a trapezoid), a short
#: vertical stroke (a triangle) with a fixed load, and moves of the user's own.
CASES = {
    "no stroke": BASE,
    "stroke, hours a day": Application(
        load_n=100.0,
        speed_m_s=0.3,
        length_m=0.6,
        moving_mass_kg=5.0,
        accel_m_s2=2.0,
        stroke_m=0.4,
        dwell_s=0.5,
        hours_per_day=8.0,
    ),
    "vertical triangle": Application(
        load_n=40.0,
        speed_m_s=0.5,
        length_m=0.6,
        moving_mass_kg=12.0,
        accel_m_s2=2.0,
        decel_m_s2=3.0,
        stroke_m=0.05,
        orientation="vertical",
        load_direction="fixed",
        cycles_per_day=2000.0,
    ),
    "moves of the user's own": Application(
        load_n=10.0,
        speed_m_s=0.25,
        length_m=0.5,
        moves=(
            Move(0.3, 0.25, 2.5, 2.5, 0.2, 0.5, 10.0, "opposes"),
            Move(-0.3, 0.25, 2.5, 2.5, 0.2, 2.5, 10.0, "opposes"),
        ),
    ),
}


@pytest.mark.parametrize("app", CASES.values(), ids=CASES.keys())
def test_each_number_of_the_cycle_is_the_function_it_names(app: Application) -> None:
    c = motion.cycle_of(app)
    assert c.moves == motion.cycle(app)
    assert c.profiles == motion.profiles(app)
    assert c.fastest == motion.move_profile(app)
    assert c.moving_n == motion.at_load(motion.moving_forms(app), app.load_n)
    assert c.forces == motion.nut_forces(app)
    assert c.steady_n == motion.steady_load(app)
    assert c.travels == motion.wear_forms(app)[1]
    assert c.wear_n == motion.wear_thrust(app)
    assert c.lead == motion.lead_move(app)
    assert c.reached_m_s == motion.reached_speed(app)
    assert c.cycles_per_day == motion.cycles_per_day(app)
    # the thrusts read from it, as the operating point reads them
    assert peak_axial_load(app, c.forces) == peak_axial_load(app)


def test_the_cases_take_each_path() -> None:
    """The cases above reach a triangle, a trapezoid, no profile, hours turned into
    cycles, and a lead move that is not the first (the user's moves' back move starts
    hardest: it carries the larger mass, 2.5 kg x 2.5 m/s^2 + 10 N = 16.25 N against the
    out move's 0.5 x 2.5 + 10 = 11.25 N), so each branch of ``cycle_of`` is compared."""
    kinds = {name: motion.cycle_of(app).fastest for name, app in CASES.items()}
    assert kinds["no stroke"] is None
    assert kinds["stroke, hours a day"] is not None
    assert kinds["stroke, hours a day"].kind == "trapezoid"
    assert kinds["vertical triangle"] is not None
    assert kinds["vertical triangle"].kind == "triangle"
    assert motion.cycle_of(CASES["stroke, hours a day"]).cycles_per_day is not None
    own = CASES["moves of the user's own"]
    assert motion.cycle_of(own).lead is own.moves[1]
    assert axial_load(own) > 0.0
