"""The ball-screw families (catalog/hiwin/ballscrew-*.toml, app/catalog/ball.py): their
values against the maker's tables, their provenance, and the leadscrew ratings they do
not have.

Source: HIWIN GmbH, Ballscrews & Accessories, catalogue BS-08-2-EN-1704-K (www.hiwin.de):
Table 4.4 (rolled flange single nut FSCDIN/FSIDIN, p. 35-36), Table 4.5 (rolled RSIT,
p. 37), Table 6.4 (ground DIN single nut FSC, p. 48-49), sec. 3.7.6 (DN limits).
"""

import math
from pathlib import Path

import pytest

from app.catalog import Catalog, load_catalog
from app.catalog.ball import NOT_APPLICABLE
from app.catalog.errors import CatalogError
from app.core.evaluate import evaluate
from app.core.formulas.critical_speed import (
    ball_screw_critical_speed_rpm,
    critical_speed_rpm,
    leadscrew_makers_critical_speed_rpm,
)
from app.core.model import Application, ScrewSpec
from app.core.units import from_si, to_si

BALL_FAMILIES = {"HIWIN-ROLLED", "HIWIN-ROLLED-RSIT", "HIWIN-GROUND"}


def _ball(catalog: Catalog) -> list:
    return [s for s in catalog.screws if s.screw_type == "ball"]


@pytest.mark.parametrize(
    ("nut", "od_mm", "lead_mm", "length_mm", "root_mm", "ca_n", "c0a_n", "ball_mm"),
    [
        # Table 4.4: ds, P, L, dk, Cdyn, C0 (no ball diameter printed)
        pytest.param("R16-05T3-FSIDIN", 15.5, 5, 40, 12.9, 6500, 11700, None, id="rolled-16x5"),
        pytest.param("R25-10K4-FSCDIN", 24.5, 10, 61, 21.8, 16100, 44900, None, id="rolled-25x10"),
        pytest.param("R40-10K4-FSCDIN", 37.8, 10, 70, 32.8, 45000, 123000, None, id="rolled-40x10"),
        pytest.param(
            "R63-10T6-FSIDIN", 63.1, 10, 120, 58.0, 61920, 214090, None, id="rolled-63x10"
        ),
        # Table 4.5
        pytest.param("R12-04B1-RSIT", 12.0, 4, 34, 9.5, 3000, 5700, None, id="rsit-12x4"),
        # Table 6.4: ds, P, ball diameter, L, dk, Cdyn, C0
        pytest.param("R20-05K4-FSC", 20, 5, 40, 17.32, 14900, 36400, 3.175, id="ground-20x5"),
        pytest.param("R32-10K5-FSC", 32, 10, 73, 28.74, 30800, 94500, 3.969, id="ground-32x10"),
        pytest.param("R40-10K5-FSC", 40, 10, 83, 34.91, 63400, 184000, 6.35, id="ground-40x10"),
    ],
)
def test_values_are_the_makers_table(
    catalog: Catalog,
    nut: str,
    od_mm: float,
    lead_mm: float,
    length_mm: float,
    root_mm: float,
    ca_n: float,
    c0a_n: float,
    ball_mm: float | None,
) -> None:
    s = catalog.by_id[nut]
    assert s.screw_type == "ball"
    assert s.outer_diameter_m == pytest.approx(od_mm / 1e3)
    assert s.lead_m == pytest.approx(lead_mm / 1e3)
    assert s.nut_length_m == pytest.approx(length_mm / 1e3)
    assert s.root_diameter_m == pytest.approx(root_mm / 1e3)
    assert (s.dynamic_load_n, s.static_load_n) == (ca_n, c0a_n)
    assert s.ball_diameter_m == (None if ball_mm is None else pytest.approx(ball_mm / 1e3))
    table = "Table 6.4" if nut.endswith("-FSC") else "Table 4.5" if "RSIT" in nut else "Table 4.4"
    for name in ("dynamic_load", "static_load", "root_diameter", "nut_length"):
        assert s.provenance[name].kind == "vendor"
        assert (
            table in s.provenance[name].source and "BS-08-2-EN-1704-K" in s.provenance[name].source
        )


def test_at_least_twenty_sizes_and_leads_from_12x4_to_40x10(catalog: Catalog) -> None:
    pairs = {(round(s.outer_diameter_m * 1e3), round(s.lead_m * 1e3)) for s in _ball(catalog)}
    assert len(pairs) >= 20
    assert {(12, 4), (20, 5), (32, 10), (40, 10), (50, 10)} <= pairs
    assert {s.family_id for s in _ball(catalog)} == BALL_FAMILIES


def test_dn_limits_grades_and_play_are_the_makers(catalog: Catalog) -> None:
    """Sec. 3.7.6: DN 70,000 rolled, 90,000 ground; Table 4.1 T7 v300p 0.052 mm; Table 6.1
    T3 e300 12 um, and Table 3.4's T3 limit deviation e_p by useful path (12 um up to
    315 mm ... 76 um at 4,000-5,000 mm); Table 4.4 max. axial play 0.04 mm of R16-05T3
    (rolled nuts come with play, sec. 3.6: no preload, no drag). v300p is the variation
    within any 300 mm, not a rate per length: no lead accuracy per metre."""
    rolled, ground = catalog.by_id["R16-05T3-FSIDIN"], catalog.by_id["R32-10K5-FSC"]
    assert (rolled.dn_limit_mm_rpm, ground.dn_limit_mm_rpm) == (70_000.0, 90_000.0)
    assert (rolled.accuracy_grade, ground.accuracy_grade) == ("T7", "T3")
    assert rolled.travel_variation_300mm_m == pytest.approx(52e-6)
    assert ground.travel_variation_300mm_m == pytest.approx(12e-6)
    assert rolled.lead_accuracy_m_per_m is None and ground.lead_accuracy_m_per_m is None
    assert rolled.travel_deviation_bands == ()  # a transport class: ISO 3408-3's rule
    table_3_4_t3_um = (12, 13, 15, 16, 18, 21, 24, 29, 35, 41, 50, 62, 76)
    upper_mm = (315, 400, 500, 630, 800, 1000, 1250, 1600, 2000, 2500, 3150, 4000, 5000)
    bands = ground.travel_deviation_bands
    assert [lu for lu, _ in bands] == pytest.approx([lu / 1e3 for lu in upper_mm])
    assert [ep for _, ep in bands] == pytest.approx([ep / 1e6 for ep in table_3_4_t3_um])
    assert "Table 3.4" in ground.provenance["travel_deviation"].source
    assert (rolled.backlash_max_m, rolled.drag_torque_max_nm) == (pytest.approx(4e-5), 0.0)
    assert not rolled.anti_backlash and ground.anti_backlash


def test_a_preloaded_nuts_drag_is_hiwins_idle_torque_at_its_largest_preload(
    catalog: Catalog,
) -> None:
    """HIWIN F 3.2, T_d = K_p F_pr P / (2000 pi), K_p 0.1 to 0.3, at the single nut's
    largest preload 5 % of Cdyn (sec. 3.6.2), an assumed upper bound: R32-10K5-FSC,
    0.3 x 1540 N x 10 mm / (2000 pi) = 0.7353 N m."""
    s = catalog.by_id["R32-10K5-FSC"]
    assert s.drag_torque_max_nm == pytest.approx(
        0.3 * 0.05 * 30800 * 10 / (2000 * 3.141592653589793)
    )
    assert s.drag_torque_min_nm == pytest.approx(s.drag_torque_max_nm / 3)
    # worked from the assumed preload: no more certain than it, and naming both inputs
    drag = s.provenance["drag_torque"]
    assert drag.kind == "assumed" and "K_p" in drag.source and "F_pr (assumed" in drag.source


def test_a_preloaded_nuts_zero_play_rests_on_its_preload(catalog: Catalog) -> None:
    """HIWIN's ground FSC table prints no axial play: the nut's zero play is its preload's
    (assumed 0-5 % of Cdyn, at 0 a nut with minimum play), and says so; a rolled nut's
    play is its table's column, and its drag (no preload, the maker's) is derived."""
    ground, rolled = catalog.by_id["R32-10K5-FSC"], catalog.by_id["R16-10K3-FSCDIN"]
    assert ground.backlash_max_m == 0.0
    play = ground.provenance["backlash"]
    assert play.kind == "assumed" and "preload" in play.source
    assert rolled.provenance["backlash"].kind == "vendor"
    assert rolled.provenance["drag_torque"].kind == "derived"


def test_a_ball_nut_has_no_leadscrew_nut_ratings(catalog: Catalog) -> None:
    """No PV, flank pressure, sliding speed, wear or design load: each says why."""
    for s in _ball(catalog):
        assert s.pv_limit_pa_m_s is None and s.design_load_n is None
        assert s.max_sliding_speed_m_s is None and s.wear_rate_m2_n is None
        assert not s.bearing_pressure_table and s.life_min_m is None
        assert s.thread_half_angle_rad == 0.0
        for name in ("pv_limit", "bearing_pressure", "max_sliding_speed", "design_load"):
            assert s.provenance[name] == NOT_APPLICABLE
    assert "not applicable to a ball screw" in NOT_APPLICABLE.source


def test_the_leads_of_one_size_share_a_series(catalog: Catalog) -> None:
    series = catalog.series["HIWIN-ROLLED R16"]
    assert [s.id for s in series.screws] == [
        "R16-05T3-FSIDIN",
        "R16-10K3-FSCDIN",
        "R16-16K3-FSCDIN",
        "R16-20K2-FSCDIN",
    ]
    assert series.fields["leads"].value == pytest.approx([0.005, 0.01, 0.016, 0.02])


def _family_text(root_mm: float = 12.9, with_ca_source: bool = True, deviation: str = "") -> str:
    """A one-nut ball-screw family of a user's own, in the built-in file's form;
    ``deviation`` the rows of its table of e_p by useful travel, when it has one."""
    src = '{ provenance = "user", source = "test table" }'
    columns = [
        f"outer_diameter_mm = {src}",
        f"lead_mm = {src}",
        f"nut_length_mm = {src}",
        f"root_diameter_mm = {src}",
        f"static_load_n = {src}",
    ] + ([f"dynamic_load_n = {src}"] if with_ca_source else [])
    value = 'provenance = "user", source = "test"'
    return "\n".join(
        [
            "[ballscrew]",
            'id = "MY-BALL"',
            'name = "my ball screws"',
            'kind = "rolled"',
            'material = "c45-steel"',
            "anti_backlash = false",
            f'accuracy_grade = {{ value = "T7", {value} }}',
            f"lead_accuracy_mm_per_300mm = {{ value = 0.052, {value} }}",
            *(
                [f"travel_deviation_mm_by_useful_travel_mm = {{ value = {deviation}, {value} }}"]
                if deviation
                else []
            ),
            f"dn_limit_mm_rpm = {{ value = 70000.0, {value} }}",
            f"friction_dynamic = {{ value = 0.01, {value} }}",
            f"friction_static = {{ value = 0.003, {value} }}",
            f"preload_fraction = {{ value = 0.0, {value} }}",
            f"preload_friction_factor = {{ min = 0.1, max = 0.3, {value} }}",
            "[ballscrew.columns]",
            *columns,
            "[[nut]]",
            'id = "MY16-05"',
            "outer_diameter_mm = 15.5",
            "lead_mm = 5.0",
            "nut_length_mm = 40.0",
            f"root_diameter_mm = {root_mm}",
            "dynamic_load_n = 6500",
            "static_load_n = 11700",
            "",
        ]
    )


def test_a_users_ball_screw_family_loads(tmp_path: Path) -> None:
    (tmp_path / "ballscrew-mine.toml").write_text(_family_text())
    screw = load_catalog([tmp_path]).by_id["MY16-05"]
    assert (screw.screw_type, screw.dynamic_load_n, screw.family_id) == ("ball", 6500.0, "MY-BALL")
    assert screw.provenance["dynamic_load"].kind == "user"


def test_a_users_ball_screw_family_gives_its_own_deviation_table(tmp_path: Path) -> None:
    """A maker's table of e_p by useful travel (Steinmeyer's rolled T7: 52 um up to
    315 mm, 69 um to 400 mm) is read in SI with the family's provenance."""
    text = _family_text(deviation="[[315, 0.052], [400, 0.069]]")
    (tmp_path / "ballscrew-mine.toml").write_text(text)
    screw = load_catalog([tmp_path]).by_id["MY16-05"]
    travels, deviations = zip(*screw.travel_deviation_bands, strict=True)
    assert travels == pytest.approx((0.315, 0.4)) and deviations == pytest.approx((52e-6, 69e-6))
    assert screw.provenance["travel_deviation"].kind == "user"


@pytest.mark.parametrize(
    ("text", "field"),
    [
        pytest.param(_family_text(root_mm=16.0), "root_diameter_mm", id="root-above-od"),
        pytest.param(_family_text(with_ca_source=False), "columns", id="no-source-for-ca"),
        pytest.param(
            _family_text(deviation="[[315, 0.012], [400, 0.010]]"),
            "travel_deviation_mm_by_useful_travel_mm",
            id="deviation-falling-with-travel",
        ),
        pytest.param(
            _family_text(deviation="[[400, 0.012], [315, 0.013]]"),
            "travel_deviation_mm_by_useful_travel_mm",
            id="deviation-travel-not-rising",
        ),
    ],
)
def test_a_bad_ball_screw_family_is_refused_naming_the_field(
    tmp_path: Path, text: str, field: str
) -> None:
    (tmp_path / "ballscrew-mine.toml").write_text(text)
    with pytest.raises(CatalogError) as err:
        load_catalog([tmp_path])
    assert field in str(err.value)


def test_every_ball_screw_has_an_assumed_operating_range(
    catalog: Catalog,
) -> None:
    """HIWIN BS-08-2-EN-1704-K gives no operating range; the families take THK's 80 C
    limit for products with resin and rubber parts (THK Ball Spline Precautions on Use,
    item 3), labelled assumed, so the temperature check runs (400 C: test_advice)."""
    for screw in _ball(catalog):
        assert (screw.temperature_min_c, screw.temperature_max_c) == (-20.0, 80.0), screw.id
        prov = screw.provenance["temperature_range"]
        assert prov.kind == "assumed" and "80 C" in prov.source, screw.id


def _with_rule(text: str, key: str, rule: str | None) -> str:
    """A family's ``text`` with its ``key`` set to the maker's ``rule``, as a user's file
    gives it (None: left out)."""
    if rule is None:
        return text
    line = f'{key} = {{ value = "{rule}", provenance = "user", source = "test" }}'
    return text.replace("[ballscrew.columns]", line + "\n[ballscrew.columns]")


def _user_screw(tmp_path: Path, text: str) -> ScrewSpec:
    """The nut of the user's family ``text``, loaded as a catalog directory of its own."""
    (tmp_path / "ballscrew-mine.toml").write_text(text)
    return load_catalog([tmp_path]).by_id["MY16-05"]


@pytest.mark.parametrize("rule", [None, "HIWIN F 3.27"])
def test_a_ball_screw_families_critical_speed_rule(tmp_path: Path, rule: str | None) -> None:
    """A family that names its maker's rule (HIWIN F 3.27) is rated by it and the beam,
    the lower of the two: 2.71e8 x 0.692 x 12.9 / 1000^2 = 2419 rpm fixed-simple over 1 m,
    shown with its provenance. One that names none is held to the lowest published rule:
    also at most the makers' C_s 1.47 times simple-simple (Rockford, Thomson, Roton),
    5.6 % less, and at most Thomson's steel constant, 4.76e6. A rule the app does not
    know is refused, naming the field."""
    text = _with_rule(_family_text(), "critical_speed_rule", rule)
    screw = _user_screw(tmp_path, text)
    app = Application(load_n=100.0, speed_m_s=0.05, length_m=1.0, end_fixity="fixed-simple")
    allowed = evaluate(app, screw).critical_speed.allowed_rpm
    rated = allowed / app.critical_speed_safety_factor
    hiwin = ball_screw_critical_speed_rpm(screw.root_diameter_m, 1.0, "fixed-simple")
    assert hiwin == pytest.approx(2419.0, rel=1e-3)
    simple = critical_speed_rpm(
        screw.root_diameter_m, 1.0, screw.youngs_modulus_pa, screw.density_kg_m3, "simple-simple"
    )
    # and at most Thomson's C_s x 4.76e6 d_r / L^2 [rpm, in], its constant a steel's
    thomson = leadscrew_makers_critical_speed_rpm(screw.root_diameter_m, 1.0, "fixed-simple")
    assert rated == pytest.approx(hiwin if rule else min(1.47 * simple, thomson), rel=1e-9)
    check = next(c for c in evaluate(app, screw).checks if c.name == "critical_speed")
    said = "HIWIN rates it" if rule else "the lowest published rule, the makers'"
    assert said in check.message.template
    assert (screw.critical_speed_rule, "critical_speed_rule" in screw.provenance) == (
        rule,
        rule is not None,
    )
    bad = text.replace("HIWIN F 3.27", "THK") if rule else ""
    if bad:
        (tmp_path / "ballscrew-mine.toml").write_text(bad)
        with pytest.raises(CatalogError) as err:
            load_catalog([tmp_path])
        assert "critical_speed_rule" in str(err.value)


@pytest.mark.parametrize("rule", [None, "HIWIN F 3.25"])
def test_a_ball_screw_families_buckling_rule(tmp_path: Path, rule: str | None) -> None:
    """A user's family of C45 steel (E 207 GPa), root 12.9 mm, over 1000 mm, fixed-
    supported. Its Euler column, 5,554 N, is below HIWIN's F_k = 4.072e5 x 0.5 x 12.9^4 /
    1000^2 = 5,638 N (BS-08-2-EN-1704-K F 3.25): a family that names HIWIN's rule keeps
    it. One that names none is held to the lowest published rule, Rockford's and
    Thomson's 14.03e6 x 2 x d^4 / L^2 [lb, in] = 5,358 N; the allowed half of it, 2,679 N,
    is then within THK's permissible P1 = 10 x 12.9^4 / 1000^2 x 10^4 = 2,769 N (General
    Catalog, Ball Screw, A15-30, formula 5, 0.5 of Euler built in), where half the
    column's own, 2,777 N, was 0.29 % above it. A rule the app does not know is refused."""
    text = _with_rule(_family_text(), "buckling_rule", rule)
    screw = _user_screw(tmp_path, text)
    app = Application(load_n=100.0, speed_m_s=0.05, length_m=1.0, end_fixity="fixed-simple")
    column = evaluate(app, screw).buckling
    root_mm, span_mm = from_si(screw.root_diameter_m, "mm"), 1000.0
    hiwin = 4.072e5 * 0.5 * root_mm**4 / span_mm**2
    assert hiwin == pytest.approx(5638.0, rel=1e-3)
    assert column.critical_load_n < hiwin
    root_in, span_in = from_si(screw.root_diameter_m, "in"), from_si(1.0, "in")
    rockford = to_si(14.03e6 * 2.0 * root_in**4 / span_in**2, "lbf")
    thk = 10.0 * root_mm**4 / span_mm**2 * 1e4
    if rule is None:
        assert column.critical_load_n == pytest.approx(rockford, rel=1e-9)
        assert column.allowed_load_n <= thk
    else:
        assert column.allowed_load_n > thk  # HIWIN's own rule allows its screws more
    assert (screw.buckling_rule, "buckling_rule" in screw.provenance) == (rule, bool(rule))
    if rule:
        (tmp_path / "ballscrew-mine.toml").write_text(text.replace("HIWIN F 3.25", "THK"))
        with pytest.raises(CatalogError) as err:
            load_catalog([tmp_path])
        assert "buckling_rule" in str(err.value)


@pytest.mark.parametrize("rule", [None, "HIWIN F 3.25"])
def test_a_ball_screw_families_axial_stress_is_held_to_thks_p2(
    tmp_path: Path, rule: str | None
) -> None:
    """THK's permissible tensile/compressive load of a ball screw shaft, P2 = 116 d1^2
    [N, mm] (General Catalog, Ball Screw, A15-30, formula 6), is an axial stress of
    116 x 4 / pi = 147.7 MPa on the root area, 4.7 % below 0.5 x 310 MPa, C45's yield at
    the default buckling factor. A user's family of C45 that names no buckling rule has
    its root stress held to it, and its short column (root 12.9 mm, 50 mm, fixed-
    supported: 0.5 x Johnson = 0.5 x 130.7 mm^2 x 308.6 MPa = 20,170 N) to
    P2 = 116 x 12.9^2 = 19,304 N. One that names HIWIN's rule (HIWIN publishes no such
    cap) keeps 0.5 x 310 MPa and 0.5 x its Johnson load."""
    text = _with_rule(_family_text(), "buckling_rule", rule)
    screw = _user_screw(tmp_path, text)
    assert screw.yield_strength_pa == pytest.approx(to_si(310.0, "MPa"))
    app = Application(load_n=4000.0, speed_m_s=0.05, length_m=0.05, end_fixity="fixed-simple")
    result = evaluate(app, screw)
    names = ("root_stress", "buckling")
    root_mm = from_si(screw.root_diameter_m, "mm")
    p2 = 116.0 * root_mm**2
    assert p2 == pytest.approx(19304.0, rel=1e-4)
    thk_pa = to_si(116.0 * 4.0 / math.pi, "MPa")
    assert thk_pa == pytest.approx(to_si(147.7, "MPa"), rel=1e-3)
    check, buckled = (next(c for c in result.checks if c.name == n) for n in names)
    assert check.utilization is not None
    allowed_pa = result.buckling.root_stress_pa / check.utilization
    column = result.buckling
    assert column.mode == "johnson"
    half_johnson = 0.5 * column.critical_load_n
    assert half_johnson == pytest.approx(20170.0, rel=1e-3)
    if rule is None:
        assert allowed_pa == pytest.approx(thk_pa, rel=1e-9)
        assert column.allowed_load_n == pytest.approx(p2, rel=1e-9)
        assert "THK's P2" in check.message.template
        assert "THK's P2" in buckled.message.template
    else:
        assert allowed_pa == pytest.approx(0.5 * to_si(310.0, "MPa"), rel=1e-9)
        assert column.allowed_load_n == pytest.approx(half_johnson, rel=1e-12)
        assert "THK" not in check.message.template + buckled.message.template
