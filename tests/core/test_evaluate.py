"""Evaluating one screw against one application (app.core.evaluate): the whole picture.

A single hand-calculated candidate is in test_worked_candidate.py; here the rules that hold
for every candidate of the catalog, and the remedies the checks propose.
"""

import math
from dataclasses import replace

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.catalog import Catalog
from app.contract.figures import bound_text
from app.contract.units import render
from app.core.checks.base import at_least
from app.core.evaluate import axial_load, evaluate
from app.core.formulas import critical_speed, efficiency, geometry
from app.core.model import PASS_UTILIZATION, STANDARD_GRAVITY_M_S2, Application, ScrewSpec
from app.core.record import Candidate
from tests.core.conftest import applications, light_app

CATALOG_IDS = ("ZBX4000-L2", "ZBX8000-L10", "B12000-L25.4-TFE", "VHD10000-L5", "KHD6000-L12")


def check(ev: Candidate, name: str):  # type: ignore[no-untyped-def]
    return next(c for c in ev.checks if c.name == name)


def test_vertical_axis_adds_the_weight_of_the_moving_mass() -> None:
    """A vertical axis carries the load plus m g (standard gravity 9.80665 m/s^2)."""
    app = light_app(orientation="vertical", moving_mass_kg=3.0)
    assert axial_load(app) == pytest.approx(50.0 + 3.0 * STANDARD_GRAVITY_M_S2)
    assert axial_load(replace(app, orientation="horizontal")) == pytest.approx(50.0)


@pytest.mark.parametrize("screw_id", CATALOG_IDS)
def test_torque_is_the_seeds_three_components(catalog: Catalog, screw_id: str) -> None:
    """Seed, "Torque": inertia + static drag + load. engineering.md section 3: the drag is the
    top of the series' range, the moving mass is its own line, and the required torque is
    the safety factor times the larger of running and break-away torque. The force m a that
    accelerates the mass passes through the thread: T = m a lead / (2 pi eta)."""
    screw = catalog.by_id[screw_id]
    app = light_app(moving_mass_kg=4.0, accel_m_s2=2.0, torque_safety_factor=1.5)
    t = evaluate(app, screw).torque
    assert t.drag_nm == screw.drag_torque_max_nm
    assert (t.drag_min_nm, t.drag_max_nm) == (screw.drag_torque_min_nm, screw.drag_torque_max_nm)
    assert t.inertia_nm == pytest.approx(t.inertia_screw_nm + t.inertia_mass_nm, rel=1e-12)
    d_p = geometry.pitch_diameter(screw.outer_diameter_m, screw.root_diameter_m)
    eta = efficiency.forward_efficiency(
        geometry.tan_lead_angle(screw.lead_m, d_p),
        screw.friction_dynamic,
        math.cos(screw.thread_half_angle_rad),
    )
    assert t.inertia_mass_nm == pytest.approx(
        4.0 * 2.0 * screw.lead_m / (2 * math.pi * eta), rel=1e-9
    )
    assert t.total_nm == pytest.approx(t.inertia_nm + t.drag_nm + t.load_nm, rel=1e-12)
    assert t.required_nm == pytest.approx(1.5 * max(t.total_nm, t.breakaway_nm), rel=1e-12)


@pytest.mark.parametrize("screw_id", CATALOG_IDS)
def test_breakaway_uses_static_friction_and_running_uses_dynamic(
    catalog: Catalog, screw_id: str
) -> None:
    """engineering.md section 2: dynamic friction for running torque, static for break-away
    and self-locking."""
    screw = catalog.by_id[screw_id]
    ev = evaluate(light_app(), screw)
    d_p = geometry.pitch_diameter(screw.outer_diameter_m, screw.root_diameter_m)
    tan_l = geometry.tan_lead_angle(screw.lead_m, d_p)
    cos_a = math.cos(screw.thread_half_angle_rad)
    eta_run = efficiency.forward_efficiency(tan_l, screw.friction_dynamic, cos_a)
    eta_static = efficiency.forward_efficiency(tan_l, screw.friction_static, cos_a)
    assert ev.efficiency == pytest.approx(eta_run, rel=1e-12)
    assert ev.torque.load_nm == pytest.approx(50.0 * screw.lead_m / (2 * math.pi * eta_run))
    # from rest with no moving mass: the load through the static efficiency, the screw's
    # own inertia torque (light_app accelerates at 1 m/s^2) and the drag
    assert ev.torque.breakaway_nm == pytest.approx(
        50.0 * screw.lead_m / (2 * math.pi * eta_static)
        + ev.torque.inertia_screw_nm
        + screw.drag_torque_max_nm
    )
    assert ev.self_locking == efficiency.is_self_locking(tan_l, screw.friction_static, cos_a)


def test_lowering_a_load_from_rest_on_a_self_locking_thread_needs_the_motor(
    catalog: Catalog,
) -> None:
    """200 kg lowered 200 mm on Tr20x4-bronze oiled (mu_s 0.16: self-locking), returned
    empty. The load pulls the nut down with W - m a = 200 (9.80665 - 0.05) = 1951.33 N,
    but the thread holds at static friction: the motor starts the lowering against it,
    Shigley's lowering torque T_L = F d2/2 (mu - cos a tan l) / (cos a + mu tan l) at
    mu_s (sec. 8-2, with the flank angle), 1.6475 N m, plus the
    screw's inertia torque and the drag. It was worked at the forward efficiency, a
    negative torque that the up move's start outweighed, and passed a 1.3 N m drive."""
    from app.core.model import Move

    down = Move(-0.2, 0.005, 0.05, 0.05, dwell_s=1.0, moving_mass_kg=200.0)
    up = Move(0.2, 0.005, 0.05, 0.05, dwell_s=1.0)
    app = Application(
        load_n=0.0, speed_m_s=0.005, length_m=0.5, orientation="vertical",
        lubrication="oiled", max_torque_nm=1.3, moves=(down, up),
    )  # fmt: skip
    screw = catalog.by_id["Tr20x4-bronze"]
    ev = evaluate(app, screw)
    force_n = 200.0 * (STANDARD_GRAVITY_M_S2 - 0.05)
    d2 = screw.flank_pitch_diameter_m  # ISO 2904's d2, which the thread's angle is taken at
    tan_l, cos_a = screw.lead_m / (math.pi * d2), math.cos(math.radians(15.0))
    mu_s = screw.friction_static
    assert (round(d2 * 1e3, 6), mu_s, screw.drag_torque_max_nm) == (18.0, 0.16, 0.0)
    lowering = force_n * d2 / 2 * (mu_s - cos_a * tan_l) / (cos_a + mu_s * tan_l)
    assert lowering == pytest.approx(1.6475, abs=5e-5)
    spin = ev.torque.inertia_screw_nm + ev.torque.inertia_motor_nm
    assert ev.torque.breakaway_nm == pytest.approx(lowering + spin, rel=1e-9)
    assert not check(ev, "torque").passed


def test_buckling_only_in_compression(zbx8000_l10: ScrewSpec) -> None:
    """engineering.md section 5: buckling applies only when the load compresses the screw:
    a vertical axis hanging from its thrust bearing (tension) never is; 50 N of friction
    on a horizontal axis marked tension pushes the screw on the move back (50 N)."""
    pushed = evaluate(light_app(orientation="vertical"), zbx8000_l10)
    pulled = evaluate(light_app(orientation="vertical", compression=False), zbx8000_l10)
    assert pushed.buckling.applies and "buckling" in {c.name for c in pushed.checks}
    assert not pulled.buckling.applies
    assert "buckling" not in {c.name for c in pulled.checks}
    back = next(c for c in evaluate(light_app(compression=False), zbx8000_l10).checks
                if c.name == "buckling")  # fmt: skip
    assert back.value == pytest.approx(50.0)


def test_a_column_that_buckles_in_compression_is_fine_in_tension(zbx8000_l10: ScrewSpec) -> None:
    """1/2 in screw, 3 m fixed-free, 400 N: far above 0.5 x Euler in compression. Hanging
    from its thrust bearing the vertical screw is only pulled; a horizontal one marked
    tension is still pushed by the 400 N on the move back and buckles."""
    app = light_app(load_n=400.0, length_m=3.0, end_fixity="fixed-free", speed_m_s=0.001,
                    orientation="vertical")  # fmt: skip
    assert "buckling" in {c.name for c in evaluate(app, zbx8000_l10).failed_checks}
    tension = evaluate(replace(app, compression=False), zbx8000_l10)
    assert "buckling" not in {c.name for c in tension.failed_checks}
    horizontal = replace(app, compression=False, orientation="horizontal")
    assert "buckling" in {c.name for c in evaluate(horizontal, zbx8000_l10).failed_checks}


def test_rated_life_for_rated_series(b8000_l10: ScrewSpec, zbx8000_l10: ScrewSpec) -> None:
    """Seed life table: B series N/A (its life is the nut's wear life instead); ZBX8000
    100-150 million cm (uncoated), at 1 N where the nut's wear life (14,640 km) is longer."""
    app = light_app(load_n=1.0, stroke_m=0.1, cycles_per_day=100.0)
    worn = evaluate(app, b8000_l10).life
    assert worn is not None and worn.model == "wear"
    rated = evaluate(app, zbx8000_l10).life
    assert rated is not None and rated.model == "rated"
    assert (rated.travel_min_m, rated.travel_max_m) == pytest.approx((1.0e6, 1.5e6))
    assert rated.years_min == pytest.approx(137.0, rel=1e-3)


def test_off_table_lead_is_marked_extrapolated(catalog: Catalog) -> None:
    """engineering.md section 7: the 1 mm lead is below the 2.5-60 mm table."""
    ev = evaluate(light_app(speed_m_s=0.01), catalog.by_id["ZBX4000-L1"])
    assert ev.traverse_extrapolated
    assert ev.traverse_speed_limit_m_s == pytest.approx(0.1)
    assert "2.5 mm to 60 mm" in render(check(ev, "traverse_speed").message)


def test_holding_torques_are_labelled_seed_and_physics(catalog: Catalog) -> None:
    """engineering.md section 2: T_b = F lead eta / (2 pi) with the forward efficiency (seed)
    and with the back-drive efficiency (physics); 0 for the seed value when self-locking."""
    steep = evaluate(light_app(orientation="vertical"), catalog.by_id["ZBX8000-L25.4"])
    assert not steep.self_locking
    f, lead = steep.axial_load_n, steep.screw.lead_m
    assert steep.holding_torque_seed_nm == pytest.approx(
        f * lead * steep.efficiency / (2 * math.pi)
    )
    assert steep.holding_torque_physics_nm == pytest.approx(
        f * lead * steep.backdrive_efficiency / (2 * math.pi)
    )
    fine = evaluate(light_app(orientation="vertical"), catalog.by_id["ZBX8000-L1"])
    assert fine.self_locking
    assert fine.holding_torque_seed_nm == 0.0
    assert fine.holding_torque_physics_nm == 0.0


def test_seed_rule_never_claims_locking_the_physics_denies(catalog: Catalog) -> None:
    """engineering.md section 2: the d/8 rule is the conservative one (about 2x margin), so
    every catalog screw the rule calls non-back-drivable is self-locking by the physics."""
    app = light_app()
    for screw in catalog.screws:
        ev = evaluate(app, screw)
        if ev.seed_rule_no_backdrive:
            assert ev.self_locking, screw.id


def test_recommended_brake_holds_the_load(catalog: Catalog) -> None:
    """engineering.md section 2 calls the seed value 'the safe side for sizing a brake';
    for every back-drivable catalog candidate on a vertical axis the brake the app asks for
    must be at least the physical holding torque, times a brake's service factor 1.5.
    B4000-L25.4, 20 N: seed 0.057 N m, physics 0.068 N m."""
    app = light_app(load_n=20.0, orientation="vertical")
    short = []
    seed_below_physics = 0
    for screw in catalog.screws:
        ev = evaluate(app, screw)
        if ev.self_locking:
            continue
        seed_below_physics += ev.holding_torque_seed_nm < ev.holding_torque_physics_nm
        needed = max(ev.holding_torque_seed_nm, ev.holding_torque_physics_nm)
        if ev.brake_nm < needed:
            short.append(screw.id)
        fix = next(c.fix for c in ev.checks if c.name == "back_driving")
        # the fix asks for the brake torque with its margin, never less (rounded up)
        asked = bound_text(at_least(1.5 * ev.brake_nm), ".3g", "up")
        assert fix is not None and f"{asked} N m" in render(fix)
        assert float(asked) >= at_least(1.5 * ev.brake_nm)
    assert short == []
    assert seed_below_physics > 0  # the case that made the seed value alone unsafe


def _critical_speed_failure(screw: ScrewSpec) -> tuple[Application, Candidate]:
    app = light_app(load_n=10.0, speed_m_s=0.09, length_m=2.0, end_fixity="simple-simple")
    ev = evaluate(app, screw)
    assert not check(ev, "critical_speed").passed
    return app, ev


def test_critical_speed_remedies_bring_utilization_to_one(catalog: Catalog) -> None:
    """engineering.md section 4 / seed: "use a longer lead, choose a larger diameter or increase
    bearing mount support"; each remedy the core computes lands exactly on the limit."""
    screw = catalog.by_id["ZBX4000-L2.5"]
    app, ev = _critical_speed_failure(screw)
    c = ev.critical_speed
    lead = critical_speed.min_lead_for_speed(app.speed_m_s, c.allowed_rpm)
    d_r = critical_speed.min_root_diameter_for_speed(screw.root_diameter_m, c.allowed_rpm, ev.rpm)
    length = critical_speed.max_length_for_speed(app.length_m, c.allowed_rpm, ev.rpm)
    for fixed_app, fixed_screw in (
        (app, replace(screw, lead_m=lead)),
        (app, replace(screw, root_diameter_m=d_r)),
        (replace(app, length_m=length), screw),
    ):
        u = check(evaluate(fixed_app, fixed_screw), "critical_speed").utilization
        assert u == pytest.approx(1.0, rel=1e-9)


def test_critical_speed_fix_names_the_three_remedies(catalog: Catalog) -> None:
    """The failed check says which of lead, diameter, support would fix it, and by how much."""
    _, ev = _critical_speed_failure(catalog.by_id["ZBX4000-L2.5"])
    phrase = check(ev, "critical_speed").fix
    assert phrase is not None
    fix = render(phrase)
    assert "lead of at least" in fix and "root diameter of at least" in fix
    assert "unsupported length at most" in fix


def test_too_steep_a_lead_is_refused() -> None:
    """A lead whose friction angle forbids driving (eta <= 0) cannot be evaluated."""
    steep = ScrewSpec(
        id="steep",
        series_id="X",
        series_name="X",
        anti_backlash=False,
        coated=False,
        outer_diameter_m=0.01,
        root_diameter_m=0.008,
        lead_m=2.0,
        thread_half_angle_rad=math.radians(14.5),
        friction_static=0.9,
        friction_dynamic=0.9,
        youngs_modulus_pa=193e9,
        density_kg_m3=8000.0,
        screw_expansion_per_k=17.3e-6,
        inertia_kg_m2_per_m=1e-6,
    )
    with pytest.raises(ValueError, match="too steep"):
        evaluate(light_app(), steep)


@settings(max_examples=60, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(app=applications, pick=st.integers(0, 10_000))
def test_checks_are_consistent_with_their_numbers(
    catalog: Catalog, app: Application, pick: int
) -> None:
    """Every numeric check: utilization = value / limit and it passes iff <= 1 (to the
    rounding PASS_UTILIZATION allows); the result passes iff no limit failed (failed
    advice only warns); the governing utilization is the largest of the limits'."""
    ev = evaluate(app, catalog.screws[pick % len(catalog.screws)])
    for c in ev.checks:
        if c.utilization is not None:
            assert c.value is not None and c.limit is not None
            assert c.utilization == pytest.approx(c.value / c.limit, rel=1e-12)
            assert c.passed == (c.utilization <= PASS_UTILIZATION), c.name
        assert (c.fix is None) == c.passed, c.name
    rejecting = [c for c in ev.checks if c.kind == "limit" or app.advice == "reject"]
    assert ev.passed == all(c.passed for c in rejecting)
    assert {c.name for c in ev.warnings} <= {c.name for c in ev.checks if c.kind == "advice"}
    numeric = [c.utilization for c in rejecting if c.utilization is not None]
    if ev.passed:
        assert ev.max_utilization == pytest.approx(max(numeric, default=0.0))
    else:
        assert ev.max_utilization > 1.0


@settings(max_examples=60, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(app=applications, pick=st.integers(0, 10_000))
def test_each_input_remedy_clears_its_check(catalog: Catalog, app: Application, pick: int) -> None:
    """Check.input_limits: setting any one of the offered inputs to the offered value makes
    that check pass (it lands on its limit)."""
    screw = catalog.screws[pick % len(catalog.screws)]
    ev = evaluate(app, screw)
    for c in ev.failed_checks:
        for key, value in (c.input_limits or {}).items():
            if value <= 0:
                continue  # e.g. the weight alone exceeds the limit: no load can help
            again = check(evaluate(replace(app, **{key: value}), screw), c.name)
            assert again.utilization is not None
            assert again.utilization <= 1.0 + 1e-9, (c.name, key, value)
