"""Remedies when nothing passes (app.core.remedy): 5 % past each limit, verified by
screening again, spanning inputs and mounting; and why when nothing can."""

import re
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.catalog import Catalog
from app.catalog.axis_motor import with_motor
from app.contract.units import DEFAULT_UNITS, render
from app.core.checks import BY_NAME, REGISTRY
from app.core.input_rules import inputs_hold
from app.core.model import PASS_UTILIZATION, Application
from app.core.remedy import MARGIN, impossible, part_way, past_limit
from app.core.selection import screen, select
from app.core.verdict import LEADSCREW_NUT_CHECKS
from app.report.service import INPUT_RANGES
from tests.leadscrews import leadscrew_families


def lead(catalog: Catalog) -> tuple[str, ...]:
    """The leadscrew families: these remedies are a leadscrew's (a ball screw carries the
    loads and speeds that exclude every leadscrew here)."""
    return leadscrew_families(catalog)


def test_a_proposal_lands_five_percent_past_its_limit() -> None:
    # lowering: a 420 N limit becomes 420 / 1.05 = 400 N; raising: 2 -> 2 * 1.05 = 2.1
    assert past_limit(1000.0, 420.0) == pytest.approx(400.0)
    assert past_limit(1.0, 2.0) == pytest.approx(2.1)
    # half-way, geometrically: from 1000 towards 250 -> sqrt(1000 * 250) = 500
    assert part_way(1000.0, 250.0, 0.5) == pytest.approx(500.0)


def _clears(app: Application, catalog: Catalog, change: dict[str, float | str]) -> float:
    """The lowest governing utilisation among the candidates passing with ``change``."""
    s = screen(replace(app, **change), catalog.index)  # type: ignore[arg-type]
    assert np.any(s.passed)
    return float(s.max_utilization[s.passed].min())


@settings(max_examples=25)
@given(
    load_n=st.floats(500.0, 60_000.0),
    speed_m_s=st.floats(0.05, 3.0),
    length_m=st.floats(0.3, 4.0),
    fixity=st.sampled_from(["fixed-free", "simple-simple", "fixed-simple", "fixed-fixed"]),
)
def test_every_remedy_passes_with_the_margin(
    catalog: Catalog, load_n: float, speed_m_s: float, length_m: float, fixity: str
) -> None:
    app = Application(load_n=load_n, speed_m_s=speed_m_s, length_m=length_m, end_fixity=fixity)  # type: ignore[arg-type]
    sel = select(app, catalog.index, INPUT_RANGES)
    summary = sel.summary
    if sel.passed:
        assert summary.remedies == () and summary.impossible is None
        return
    assert bool(summary.remedies) != (summary.impossible is not None)
    for remedy in summary.remedies:
        best = _clears(app, catalog, dict(remedy.inputs))
        assert best == pytest.approx(remedy.utilization)
        assert best <= PASS_UTILIZATION / (1.0 + MARGIN)
        for key, value in remedy.inputs.items():
            low, high = INPUT_RANGES.get(key, (-np.inf, np.inf))
            assert isinstance(value, str) or low <= value <= high


def test_a_change_landing_exactly_five_percent_past_its_limit_is_offered(
    catalog: Catalog,
) -> None:
    """50 kN at 2 m/s over 3.048 m: R63-20K5-FSC's critical speed allows 315.19 mm/s by
    the beam, 311.72 mm/s by HIWIN's F 3.27 (0.8 x 2.71e8 x 0.692 x 57.91 / 3048^2 rpm
    x 20 mm), the lower, so the change is that over 1.05, where its utilisation is 1 / 1.05
    to the last bit (0.9523809523809524 against 0.9523809523809523). It was refused for
    that bit, and the next speed offered, 232.8 mm/s, left the screw at 74 %."""
    app = Application(load_n=50_000.0, speed_m_s=2.0, length_m=3.048)
    summary = select(app, catalog.index, INPUT_RANGES).summary
    first = summary.remedies[0]
    allowed_m_s = 0.8 * 2.71e8 * 0.692 * 57.91 / 3048.0**2 * 0.020 / 60.0
    assert first.inputs == {"speed_m_s": pytest.approx(allowed_m_s / 1.05, rel=1e-6)}
    assert first.utilization == pytest.approx(1.0 / 1.05, rel=1e-12)


def test_remedies_span_more_than_one_dimension(catalog: Catalog) -> None:
    """10 kN at 500 mm/s over 3 m: the offered changes move two inputs together, or the
    mounting with an input, not only one input at a time."""
    app = Application(load_n=10_000.0, speed_m_s=0.5, length_m=3.0, families=lead(catalog))
    remedies = select(app, catalog.index, INPUT_RANGES).summary.remedies
    assert remedies
    assert any(len(r.inputs) >= 2 for r in remedies)


def test_a_long_fast_axis_is_offered_a_stiffer_mounting(catalog: Catalog) -> None:
    """Critical speed excludes everything at 2 m, 400 mm/s, fixed-free: a stiffer end
    fixity (alone or with one input) is among the remedies."""
    app = Application(load_n=100.0, speed_m_s=0.4, length_m=2.0, end_fixity="fixed-free")
    app = replace(app, families=lead(catalog))
    sel = select(app, catalog.index, INPUT_RANGES)
    assert sel.passed == 0 and sel.summary.most_excluding_check == "critical_speed"
    remedies = sel.summary.remedies
    assert any("end_fixity" in r.inputs for r in remedies)
    assert any(set(r.inputs) == {"length_m"} for r in remedies)  # a shorter screw alone
    both = [r for r in remedies if set(r.inputs) == {"length_m", "speed_m_s"}]
    assert both  # shorter and slower, each part of the way
    alone = {next(iter(r.inputs)): r.inputs for r in remedies if len(r.inputs) == 1}
    for key in ("length_m", "speed_m_s"):
        # part of the way: less of a change than the input alone needs
        assert alone[key][key] < both[0].inputs[key] < getattr(app, key)


def test_when_no_change_helps_it_says_no_leadscrew_can_and_why(catalog: Catalog) -> None:
    """400 deg C ambient: no nut is rated for it and no input change helps."""
    app = Application(load_n=100.0, speed_m_s=0.05, length_m=0.3, ambient_c=400.0)
    app = replace(app, families=lead(catalog))
    summary = select(app, catalog.index, INPUT_RANGES).summary
    assert summary.remedies == ()
    assert summary.impossible is not None
    text = summary.impossible.template
    # the leadscrew families asked for, and no others, were screened: the claim is theirs
    assert text.startswith("No leadscrew of the families asked for can do this")
    # no check that fails names an input: no change was tried, and none is claimed
    assert "temperature" in text and "no change of the inputs was tried" in text
    assert "speed" not in text and "acceleration" not in text


def test_when_only_ball_screws_were_screened_it_names_ball_screws(catalog: Catalog) -> None:
    """A 30 kg vertical axis on the HIWIN rolled ball screws alone, no brake: every ball
    screw back-drives, and the sentence names the kind screened, not leadscrews."""
    app = Application(
        load_n=0.0,
        speed_m_s=0.1,
        length_m=0.8,
        stroke_m=0.6,
        accel_m_s2=2.0,
        moving_mass_kg=30.0,
        orientation="vertical",
        families=("HIWIN-ROLLED",),
    )
    summary = select(app, catalog.index, INPUT_RANGES).summary
    assert summary.impossible is not None
    text = summary.impossible.template
    assert text.startswith("No ball screw of the families asked for can do this"), text
    assert "leadscrew" not in text


def test_when_some_screws_are_excluded_otherwise_it_does_not_say_no_leadscrew_can(
    catalog: Catalog,
) -> None:
    """A vertical 5 kg axis with 200 N on a 17HS19 stepper: back-driving excludes 44 of the
    62 screws of lead 4 mm, not all, and the motor's curve excludes every one (its usable
    torque from standstill is 0.59 / sqrt 2 / 1.5 = 0.278 N m, under the 249 N x 4 mm /
    (2 pi eta) the thread takes at any eta below 0.57). No duty change helps, but a larger
    motor would: the summary says it is this motor, and names the larger motor."""
    app = Application(
        load_n=200.0,
        speed_m_s=0.05,
        length_m=0.5,
        lead_m=0.004,
        stroke_m=0.2,
        moving_mass_kg=5.0,
        orientation="vertical",
        families=lead(catalog),
    )
    motor_app = with_motor(replace(app, motor="17hs19-2004s1"), catalog.motors)
    summary = select(motor_app, catalog.index, INPUT_RANGES).summary
    assert summary.remedies == ()
    assert summary.impossible is not None
    text = summary.impossible.template
    assert text.startswith(
        "No leadscrew of lead {lead}, of the families asked for can do this with this motor"
    )
    assert text.endswith("leave the choice open to screen the rest of the catalog.")
    assert "a larger motor or a gearbox" in text


#: an axis that asks for no lead, family, nut or coating: every screw of the catalog
ANY_SCREW = Application(load_n=100.0, speed_m_s=0.05, length_m=0.5)


def test_why_none_is_the_excluding_checks_own_text() -> None:
    """The sentence for a check that excludes every screw is the one its module gives
    (``Check.why_none``), and only a motor check adds 'with this motor'."""
    speed = impossible(ANY_SCREW, "critical_speed", "Critical speed", True, (), "leadscrew")
    assert BY_NAME["critical_speed"].why_none[1:] in speed.template
    assert speed.template.startswith("No leadscrew in the catalog can do this")
    assert "with this motor" not in speed.template
    rms = impossible(ANY_SCREW, "motor_rms", "Motor RMS torque", True, (), "leadscrew")
    assert "with this motor" in rms.template
    assert BY_NAME["motor_rms"].why_none[1:] in rms.template


def test_a_check_without_its_own_text_is_named() -> None:
    checks = [c for c in REGISTRY if not c.why_none]
    assert checks, "every check has a text: this test has nothing to try"
    text = impossible(ANY_SCREW, checks[0].name, checks[0].label, True, (), "screw").template
    assert f"{checks[0].label[1:]} excludes every screw" in text


@pytest.mark.parametrize(
    ("change", "holds"),
    [
        ({"length_m": 0.8}, True),
        ({"length_m": 0.35}, False),  # the stroke 0.3 m and the nut 0.06 m need 0.36 m
        ({"length_m": 0.5}, False),  # shorter than the 0.6 m from the bearing to the nut
        ({"bearing_to_nut_m": 0.25}, False),  # a span to the bearing below the 0.3 m stroke
        ({"speed_m_s": 0.05}, True),  # 0.3 m at 0.05 m/s: a cycle of 12.1 s, 7,140 a day
        ({"speed_m_s": 0.02}, False),  # 30.04 s: 2,876 a day, fewer than the 5,000 asked
    ],
    ids=[
        "longer",
        "below-the-stroke",
        "below-the-bearing-span",
        "span-below-the-stroke",
        "slower",
        "too-slow",
    ],
)
def test_a_change_keeps_the_inputs_own_rules(change: dict[str, float], holds: bool) -> None:
    """The rules the input model refuses an application by (the stroke and the nut on
    the screw, the span from the thrust bearing within it, the cycles within a day) are
    the ones a change or a remedy must keep (``input_rules.inputs_hold``)."""
    app = Application(
        load_n=100.0, speed_m_s=0.2, length_m=1.0, stroke_m=0.3, nut_length_m=0.06,
        bearing_to_nut_m=0.6, accel_m_s2=1.0, cycles_per_day=5000.0,
    )  # fmt: skip
    assert inputs_hold(replace(app, **change)) is holds


def test_a_ball_screw_only_screening_is_not_told_to_consider_a_ball_screw(
    catalog: Catalog,
) -> None:
    """20 kN at 250 mm/s over 800 mm on HIWIN's RSIT ball screws alone: no size reaches
    the critical speed at any mounting. The advice read "consider a ball screw", the
    leadscrews' words; a ball screw's drive past it is a rotating nut, a support or a belt.
    Every check a ball screw runs that suggests one has its own words for a ball-only
    screening (the sliding nut's checks never exclude a ball screw)."""
    app = Application(
        load_n=20_000.0, speed_m_s=0.25, length_m=0.8, stroke_m=0.5, moving_mass_kg=50.0,
        families=("HIWIN-ROLLED-RSIT",), cycles_per_day=2000.0, required_life_years=5.0,
    )  # fmt: skip
    summary = select(app, catalog.index, INPUT_RANGES).summary
    assert summary.impossible is not None
    text = summary.impossible.template
    assert "no ball screw of this length reaches" in text and "ball screw, a" not in text
    for check in REGISTRY:
        if (
            re.search(r"\ba ball screw\b", check.why_none)
            and check.name not in LEADSCREW_NUT_CHECKS
        ):
            assert check.why_none_ball and "consider a ball" not in check.why_none_ball


def test_a_fix_that_offers_another_lead_says_how_that_screw_fares(catalog: Catalog) -> None:
    """A fix may offer a lead of the same size; halving it doubles the screw's speed, which
    other checks judge. 10 kg lifted 500 mm at 100 mm/s: Tr20x8(P4)-ptfe back-drives, and
    its fix offers the 4 mm lead, which self-locks with margin but slides its nut at
    1417 mm/s, over PTFE's 1000: the fix says so. 5 kg at 50 mm/s on 500 mm: B4000-L1-TFE
    whirls, and its fix's 2 mm lead, B4000-L2-TFE, passes: the fix says that too."""
    lift = Application(
        load_n=0.0, moving_mass_kg=10.0, orientation="vertical", speed_m_s=0.1,
        length_m=0.6, stroke_m=0.5, hold_power_off=True, limit=100,
        families=("TR-C45",), cycles_per_day=100.0, required_life_years=3.0,
    )  # fmt: skip
    fix = _rejected_fix(select(lift, catalog.index), "Tr20x8(P4)-ptfe", "back_driving")
    assert "use a lead of {" in fix.template
    assert render(fix, DEFAULT_UNITS).endswith("Tr20x4-ptfe fails Nut sliding speed on this axis.")
    slow = Application(load_n=0.0, moving_mass_kg=5.0, speed_m_s=0.05, length_m=0.5,
                       stroke_m=0.3, limit=100)  # fmt: skip
    fix = _rejected_fix(select(slow, catalog.index), "B4000-L1-TFE", "critical_speed")
    assert render(fix, DEFAULT_UNITS).endswith("B4000-L2-TFE passes every check of this axis.")


def _rejected_fix(sel, screw_id: str, check: str):  # type: ignore[no-untyped-def]
    rejected = next(c for c in sel.rejected if c.screw.id == screw_id)
    return next(c.fix for c in rejected.failed_checks if c.name == check)
