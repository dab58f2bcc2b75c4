"""The thrust bearing (issue 29, item 10): the peak thrust against its static axial rating
over the static safety factor, its ISO 281 rating life under the cycle's cube-mean thrust,
the cited library of support units, and buckling over the span from the thrust bearing to
the nut."""

from dataclasses import replace

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.catalog import Catalog
from app.catalog.supports import UnknownSupport, with_support
from app.core.checks.base import FIX_MARGIN
from app.core.column import column_length
from app.core.duty import travel_thrusts
from app.core.evaluate import evaluate
from app.core.formulas import buckling, column_rules, support
from app.core.model import Application, ScrewSpec
from app.core.phrase import Amount
from tests.core.conftest import STEEL_E, light_app

#: THK Support Unit catalog, Models EK, BK, FK, EF, BF and FF (513-2E; studylib.net/doc/
#: 18443607), table "Angular ball bearing on the fixed side", axial direction: basic
#: dynamic load rating Ca and permissible (static) load, both in kN.
THK_TABLE = [
    pytest.param("thk-fk6", 1.38, 1.76, id="EK-FK6"),
    pytest.param("thk-fk10", 6.08, 3.1, id="EK-FK-BK10"),
    pytest.param("thk-fk12", 6.66, 3.25, id="EK-FK-BK12"),
    pytest.param("thk-fk15", 7.6, 4.0, id="EK-FK-BK15"),
    pytest.param("thk-bk17", 13.7, 5.85, id="BK17"),
    pytest.param("thk-fk20", 17.9, 9.5, id="EK-FK20"),
    pytest.param("thk-bk20", 12.7, 7.55, id="BK20"),
    pytest.param("thk-fk30", 28.0, 16.3, id="FK-BK30"),
]


@pytest.mark.parametrize(("unit_id", "ca_kn", "static_kn"), THK_TABLE)
def test_the_library_holds_thks_ratings(
    catalog: Catalog, unit_id: str, ca_kn: float, static_kn: float
) -> None:
    unit = catalog.supports[unit_id]
    assert unit.value("dynamic_axial_n") == pytest.approx(ca_kn * 1000.0)
    assert unit.value("static_axial_n") == pytest.approx(static_kn * 1000.0)
    for value in unit.values.values():
        assert value.provenance.kind == "vendor"
        assert "THK Support Unit catalog" in value.provenance.source


def test_a_library_unit_rates_the_bearing_unless_the_ratings_are_typed(catalog: Catalog) -> None:
    app = light_app(support_unit="thk-fk12")
    rated = with_support(app, catalog.supports)
    assert (rated.support_dynamic_n, rated.support_static_n) == (6660.0, 3250.0)
    typed = with_support(replace(app, support_static_n=5000.0), catalog.supports)
    assert (typed.support_dynamic_n, typed.support_static_n) == (6660.0, 5000.0)
    with pytest.raises(UnknownSupport, match="thk-fk12"):
        with_support(light_app(support_unit="nk-99"), catalog.supports)


def test_iso_281_rating_life_example() -> None:
    """Sarthaks eConnect, bearing life (sarthaks.com/2642436): C = 16 kN, W = 2 kN, ball
    bearing p = 3 -> L10 = (16 / 2)^3 = 512 million revolutions."""
    assert support.rating_life_revolutions(16e3, 2e3) == pytest.approx(512e6, rel=1e-12)


@given(
    forces=st.lists(
        st.tuples(st.sampled_from([-1.0, 1.0]), st.floats(1e-3, 5e4)).map(lambda p: p[0] * p[1]),
        min_size=1,
        max_size=8,
    ),
    data=st.data(),
)
def test_the_cube_mean_lies_between_the_smallest_and_largest_thrust(
    forces: list[float], data: st.DataObject
) -> None:
    distances = data.draw(
        st.lists(st.floats(1e-3, 2.0), min_size=len(forces), max_size=len(forces))
    )
    mean = support.mean_axial_load(forces, distances)
    magnitudes = [abs(f) for f in forces]
    assert min(magnitudes) * (1 - 1e-9) <= mean <= max(magnitudes) * (1 + 1e-9)
    # one thrust throughout: the mean is that thrust
    assert support.mean_axial_load([forces[0]] * 3, [0.1, 0.2, 0.3]) == pytest.approx(
        abs(forces[0]), rel=1e-9, abs=1e-9
    )


def check_of(app: Application, screw: ScrewSpec, name: str) -> object:
    return next(c for c in evaluate(app, screw).checks if c.name == name)


def test_the_peak_thrust_is_judged_against_the_static_rating(catalog: Catalog) -> None:
    """1500 N against the motion with a 20 kg carriage accelerating at 5 m/s^2: the peak
    thrust 1500 + 20 x 5 = 1600 N. THK FK12's permissible static load 3.25 kN over THK's
    static safety factor 2 (LM Guide Actuator selection, "Static Safety Factor": fs >= 2
    without vibration or impact) allows 1625 N: 1600 / 1625 = 0.9846, a pass; at fs 2.5
    it allows 1300 N and fails at 1.2308."""
    screw = catalog.by_id["ZBX8000-L10"]
    app = with_support(
        light_app(load_n=1500.0, moving_mass_kg=20.0, accel_m_s2=5.0, support_unit="thk-fk12"),
        catalog.supports,
    )
    result = check_of(app, screw, "support_static")
    assert result.passed and result.demand == pytest.approx(1600.0)
    assert result.capacity == pytest.approx(1625.0)
    assert result.utilization == pytest.approx(1600.0 / 1625.0, rel=1e-9)
    strict = check_of(replace(app, support_static_safety_factor=2.5), screw, "support_static")
    assert not strict.passed and strict.utilization == pytest.approx(1600.0 / 1300.0)
    fix = strict.fix
    assert fix is not None
    needed = fix.values["c0a"]
    assert isinstance(needed, Amount)
    assert needed.value == pytest.approx(1600.0 * 2.5 * (1 + FIX_MARGIN))
    rated = replace(app, support_static_safety_factor=2.5, support_static_n=needed.value)
    assert check_of(rated, screw, "support_static").utilization <= 1 / (1 + FIX_MARGIN) + 1e-9
    # the peak thrust the fix asks for, 0.95 x 1300 = 1235 N (a load of 1235 - 100 N),
    # passes at 0.95
    cap = fix.values["cap"]
    assert isinstance(cap, Amount) and cap.value == pytest.approx(1235.0)
    lighter = replace(app, support_static_safety_factor=2.5, load_n=cap.value - 100.0)
    assert check_of(lighter, screw, "support_static").utilization == pytest.approx(0.95)
    # the load that meets the allowed thrust, the input a remedy moves past
    limits = strict.input_limits
    assert limits is not None and limits["load_n"] == pytest.approx(1300.0 - 100.0)


def test_no_rating_no_check(catalog: Catalog) -> None:
    names = {c.name for c in evaluate(light_app(), catalog.by_id["ZBX8000-L10"]).checks}
    assert not {"support_static", "support_life"} & names


def test_the_rating_life_in_years_of_the_duty(catalog: Catalog) -> None:
    """1000 N of friction-like load both ways, no moving mass: every segment thrusts
    1000 N, so the cube mean is 1000 N. THK FK12, Ca 6.66 kN: L10 = 6.66^3 x 10^6 =
    295.4 million revolutions (ISO 281, load factor 1); on a 10 mm lead 2954 km, over
    2 x 0.5 m x 1000 cycles x 365 days = 365 km a year: 8.09 years, short of 10 (0.809),
    enough for 8."""
    screw = catalog.by_id["ZBX8000-L10"]
    assert screw.lead_m == pytest.approx(0.01)
    duty = light_app(
        ball_load_factor=1.0,
        load_n=1000.0,
        support_unit="thk-fk12",
        stroke_m=0.5,
        cycles_per_day=1000.0,
        required_life_years=10.0,
    )
    app = with_support(duty, catalog.supports)
    years = 6.66**3 * 1e6 * 0.01 / (2 * 0.5 * 1000 * 365)
    assert years == pytest.approx(8.09, abs=0.005)
    result = check_of(app, screw, "support_life")
    assert result.capacity == pytest.approx(years, rel=1e-9)
    assert not result.passed and result.utilization == pytest.approx(10.0 / years)
    assert check_of(replace(app, required_life_years=8.0), screw, "support_life").passed
    # the fix's rating gives the required life with the margin: L10 grows as Ca^3
    asked = result.fix.values["ca"]
    assert isinstance(asked, Amount)
    assert asked.value == pytest.approx(6660.0 * (10.0 / years) ** (1 / 3) * 1.05)
    fixed = check_of(replace(app, support_dynamic_n=asked.value), screw, "support_life")
    assert fixed.utilization == pytest.approx(1 / 1.05**3)


def test_the_cube_mean_weights_each_segment_by_its_travel() -> None:
    """0.1 m/s over 0.2 m at 1 m/s^2, 10 kg against 1000 N of friction: each ramp covers
    v^2 / 2a = 5 mm (0.1 s), the constant segment 190 mm; the thrust is 1010 N
    accelerating, 1000 N running and 990 N braking, both ways:
    F_m = ((1010^3 x 5 + 1000^3 x 190 + 990^3 x 5) / 200)^(1/3) = (1.000015e9)^(1/3)
    = 1000.005 N."""
    app = light_app(load_n=1000.0, moving_mass_kg=10.0, accel_m_s2=1.0, speed_m_s=0.1, stroke_m=0.2)
    forces, distances = travel_thrusts(app)
    assert [abs(f) for f in forces] == pytest.approx([1010.0, 1000.0, 990.0] * 2)
    assert distances == pytest.approx([0.005, 0.19, 0.005] * 2)
    expected = ((1010**3 * 5 + 1000**3 * 190 + 990**3 * 5) / 200) ** (1 / 3)
    assert support.mean_axial_load(forces, distances) == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(1000.005, abs=1e-4)


def test_buckling_over_the_span_from_the_thrust_bearing_to_the_nut(catalog: Catalog) -> None:
    """MISUMI, Economy Series e-catalog 2025, "Selection of Ball Screws 2", 4. Allowable
    Axial Load (p. 1676): root 12.5 mm, fixed-support, 820 mm between the buckling points
    (THK, "Method for Mounting the Ball Screw Shaft": the distance between the mounting
    surfaces, the bearing and the nut), E 2.06e5 N/mm^2, factor 0.5 -> 3630 N. On a
    1200 mm screw the column is the 820 mm span, not the screw: 3630 N; without the span
    the whole 1200 mm buckles at 3630 x (820 / 1200)^2 = 1695 N."""
    screw = replace(
        catalog.by_id["ZBX8000-L10"],
        root_diameter_m=0.0125,
        youngs_modulus_pa=STEEL_E,
        yield_strength_pa=None,
    )
    app = light_app(length_m=1.2, end_fixity="fixed-simple", load_n=100.0)
    spanned = replace(app, bearing_to_nut_m=0.82)
    assert column_length(spanned) == pytest.approx(0.82)
    # a steel leadscrew is held to its makers' column rule (Thomson's and Nook's 14.03e6,
    # E_m = 199.7 GPa), 199.7 / 206 of MISUMI's 2.06e5 N/mm^2: 3519 N
    held = column_rules.LOWEST_COLUMN_MODULUS_PA / STEEL_E
    assert check_of(spanned, screw, "buckling").capacity == pytest.approx(3630.0 * held, rel=0.01)
    whole = check_of(app, screw, "buckling").capacity
    assert whole == pytest.approx(3630.0 * held * (0.82 / 1.2) ** 2, rel=0.01)
    # the critical speed still whirls the whole screw between its supports
    assert check_of(spanned, screw, "critical_speed").capacity == pytest.approx(
        check_of(app, screw, "critical_speed").capacity
    )


def test_a_span_fix_names_the_span_and_keeps_the_margin(catalog: Catalog) -> None:
    """A buckling failure over a given span: the fix's length is the span's, and the
    input it clears is the span, each with the 5 % margin."""
    screw = catalog.by_id["ZBX8000-L10"]
    app = light_app(length_m=1.5, bearing_to_nut_m=1.2, load_n=2000.0)
    result = check_of(app, screw, "buckling")
    assert not result.passed and result.fix is not None
    assert "from the thrust bearing to the nut" in result.fix.template
    span = result.fix.values["length"]
    assert isinstance(span, Amount) and span.value > 0
    shortened = check_of(replace(app, bearing_to_nut_m=span.value), screw, "buckling")
    assert shortened.utilization <= 1 / (1 + FIX_MARGIN) + 1e-9
    limits = result.input_limits
    assert limits is not None and "bearing_to_nut_m" in limits and "length_m" not in limits
    f_cr = buckling.column_critical_load(
        float(column_rules.leadscrew_column_modulus(screw.youngs_modulus_pa)),
        screw.root_diameter_m, limits["bearing_to_nut_m"],
        "fixed-simple", screw.yield_strength_pa or float("nan"),
    )  # fmt: skip
    assert 0.5 * f_cr == pytest.approx(result.demand, rel=1e-6)


def test_a_duty_in_hours_a_day_rates_the_thrust_bearing_too(catalog: Catalog) -> None:
    """The duty given as hours of running a day instead of cycles: the thrust bearing's
    life runs on the cycles those hours hold, as the nut's lives do. 1000 N both ways at
    0.05 m/s over 0.5 m (1 m/s^2 ramps: 0.05 + 9.95 + 0.05 s a move, 20.1 s a cycle), 8 h
    a day: 28,800 / 20.1 = 1432.8 cycles; THK FK12 (Ca 6.66 kN) on a 10 mm lead:
    6.66^3 x 10^6 x 0.01 m / (2 x 0.5 m x 1432.8 x 365) = 5.65 years, short of 10. The
    check once did not run at all (it read the cycles a day alone) and was not listed as
    not checked."""
    screw = catalog.by_id["ZBX8000-L10"]
    duty = light_app(
        ball_load_factor=1.0,
        load_n=1000.0,
        accel_m_s2=1.0,
        support_unit="thk-fk12",
        stroke_m=0.5,
        hours_per_day=8.0,
        required_life_years=10.0,
    )
    app = with_support(duty, catalog.supports)
    cycles = 8.0 * 3600.0 / 20.1
    years = 6.66**3 * 1e6 * 0.01 / (2 * 0.5 * cycles * 365)
    assert years == pytest.approx(5.65, abs=0.005)
    result = check_of(app, screw, "support_life")
    assert not result.passed
    assert result.capacity == pytest.approx(years, rel=1e-6)
    # the same duty as cycles a day rates the same life
    counted = replace(app, hours_per_day=None, cycles_per_day=cycles)
    assert check_of(counted, screw, "support_life").capacity == pytest.approx(years, rel=1e-9)


def test_the_thrust_bearing_life_takes_the_load_factor(catalog: Catalog) -> None:
    """The bearing's load is the calculated load times the load factor fw (IKO, Needle
    Roller Bearings catalog, eq. (10), Table 6: 1 to 1.2 in smooth operation), as the
    ball nut's life takes it. R25-10K3-FSC on THK FK20 (Ca 17.9 kN), 2 kN against the
    motion, 20 kg at 1 m/s^2 over 800 mm at 0.3 m/s, 2000 cycles a day: the cube-mean
    thrust is 2000.0 N; at fw 1 L10 = 8.95^3 x 10^6 rev x 10 mm = 7169 km over 3200 m a
    day, 6.14 years, which passed 5 years; at the default fw 1.2 (the ball nut's) it is
    6.14 / 1.2^3 = 3.55 years and fails."""
    screw = catalog.by_id["R25-10K3-FSC"]
    duty = light_app(
        load_n=2000.0,
        moving_mass_kg=20.0,
        accel_m_s2=1.0,
        speed_m_s=0.3,
        length_m=1.0,
        stroke_m=0.8,
        cycles_per_day=2000.0,
        required_life_years=5.0,
        support_unit="thk-fk20",
    )
    app = with_support(duty, catalog.supports)
    unfactored = (17.9e3 / 2000.0) ** 3 * 1e6 * 0.01 / (2 * 0.8 * 2000 * 365)
    assert unfactored == pytest.approx(6.14, abs=0.005)
    assert app.ball_load_factor == 1.2
    result = check_of(app, screw, "support_life")
    assert result.capacity == pytest.approx(unfactored / 1.2**3, rel=1e-4)
    assert result.capacity == pytest.approx(3.55, abs=0.005)
    assert not result.passed
    assert "load factor" in result.message.template
    smooth = check_of(replace(app, ball_load_factor=1.0), screw, "support_life")
    assert smooth.passed and smooth.capacity == pytest.approx(unfactored, rel=1e-4)
