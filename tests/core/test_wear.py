"""Nut wear life by Archard's law (app.core.formulas.wear, the wear_life check)."""

import math
from dataclasses import replace

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.catalog import Catalog
from app.contract.units import render, to_si
from app.core.checks import BY_NAME
from app.core.evaluate import evaluate
from app.core.formulas import life, wear
from app.core.model import Application


@pytest.mark.parametrize(
    ("english", "metric"),
    [
        pytest.param(13, 26, id="POM-unfilled-vs-PA66"),
        pytest.param(61, 122, id="POM-unfilled-vs-PA66-GF30"),
        pytest.param(4, 8, id="POM-PTFE20-vs-PA66"),
        pytest.param(48, 97, id="POM-PTFE20-vs-PC"),
    ],
)
def test_rtp_wear_factors_in_both_units(english: float, metric: float) -> None:
    """RTP Company, wear factor and friction data, 800 series (acetal): the same ASTM
    D3702 tests printed in 1e-10 in^3 min/(ft lbf h) (english page) and 1e-8 mm^3/(N m)
    (metric page), each rounded to a whole number. The app's unit gives one from the
    other within that rounding."""
    k = to_si(english * 1e-10, "in³ min/(ft lbf h)")
    assert k / to_si(1e-8, "mm³/(N m)") == pytest.approx(metric, abs=1.0)


def test_rtp_wear_volume_is_archard_depth_times_area() -> None:
    """RTP's W = K F V T (metric: W mm^3, K mm^3/(N m), F N, V m/s, T s) is Archard's
    law: over a contact area A the depth is W / A = k p s. Metric test conditions of the
    800 series page: 0.90 MPa at 0.25 m/s; POM unfilled K = 26e-8 mm^3/(N m), 100 h on a
    1 cm^2 washer: W = 26e-8 x 90 N x 0.25 x 360000 s = 2.106 mm^3, depth 21.06 um."""
    k = to_si(26e-8, "mm³/(N m)")
    area_m2, pressure_pa, speed_m_s, seconds = 1e-4, 0.90e6, 0.25, 100 * 3600.0
    volume_mm3 = 26e-8 * (pressure_pa * area_m2) * speed_m_s * seconds
    assert volume_mm3 == pytest.approx(2.106, rel=1e-3)
    depth_m = wear.wear_depth(k, pressure_pa, speed_m_s * seconds)
    assert depth_m * area_m2 * 1e9 == pytest.approx(volume_mm3, rel=1e-12)


def test_skf_ptfe_composite_bushing_life_is_archards_law_in_time() -> None:
    """SKF's worked example (plain bearings, "Calculation example", skf.com): PTFE
    composite bushings PCM 202325 E in a tramway door linkage, p = 1.64 N/mm^2 at
    v = 0.01 m/s (p v = 0.0164), "p v value = 0,025 to be applied" in the life line,
    c1..c5 = 1.3 x 1 x 1 x 0.6 x 1.5, KM = 480, exponent n = 1 for PTFE composite:
    G_h = c KM / (p v) = 22 500 operating hours. With n = 1 that is Archard's law in time:
    the depth allowed over the wear rate, h / k = c KM (in Pa m: N/mm^2 -> Pa, h -> s),
    slides s = h / (k p) metres, which at v takes s / v. The published life follows, and
    doubling p v halves it in both."""
    c = 1.3 * 1 * 1 * 0.6 * 1.5
    h_over_k_pa_m = c * 480 * 1e6 * 3600  # KM [N/mm^2 m/s h] in SI
    depth_m = 0.05e-3  # any allowed depth: only h / k enters
    rate_m2_n = depth_m / h_over_k_pa_m
    speed_m_s = 0.01
    pressure_pa = 0.025e6 / speed_m_s  # the p v SKF applies, at v
    hours = wear.wear_life_sliding(depth_m, rate_m2_n, pressure_pa) / speed_m_s / 3600
    assert hours == pytest.approx(22_464, rel=1e-9)
    assert hours == pytest.approx(22_500, rel=2e-3)  # SKF rounds to 22 500 h
    doubled = wear.wear_life_sliding(depth_m, rate_m2_n, 2 * pressure_pa) / speed_m_s / 3600
    assert doubled == pytest.approx(hours / 2)


@given(
    depth=st.floats(1e-5, 1e-3),
    rate=st.floats(1e-18, 1e-14),
    pressure=st.floats(1e4, 2e7),
    factor=st.floats(1.1, 10.0),
)
def test_life_is_the_inverse_of_the_depth(
    depth: float, rate: float, pressure: float, factor: float
) -> None:
    """The sliding life wears exactly the allowed depth; twice the pressure or the wear
    rate halves it (wear is linear in both, Neale A5)."""
    s = wear.wear_life_sliding(depth, rate, pressure)
    assert wear.wear_depth(rate, pressure, s) == pytest.approx(depth, rel=1e-12)
    assert wear.wear_life_sliding(depth, rate, factor * pressure) == pytest.approx(s / factor)
    assert wear.wear_life_sliding(depth, factor * rate, pressure) == pytest.approx(s / factor)


def test_a_multi_start_screw_slides_less_per_metre() -> None:
    """Per metre of travel the flanks slide one helix per lead: Tr8x2 (d2 = 7 mm) slides
    sqrt(2^2 + (7 pi)^2) / 2 = 11.04 m, Tr8x8(P2) sqrt(8^2 + (7 pi)^2) / 8 = 2.93 m."""
    d2 = 0.007
    for lead, expected in ((0.002, 11.04), (0.008, 2.93)):
        helix = math.hypot(lead, math.pi * d2)
        assert wear.sliding_per_travel(helix, lead) == pytest.approx(expected, abs=0.01)


@pytest.mark.parametrize("screw_id", ["Tr12x3-bronze", "Tr20x4-acetal", "Tr16x8(P4)-ptfe"])
def test_the_allowed_wear_is_a_quarter_of_the_pitch_off_the_thread(
    catalog: Catalog, screw_id: str
) -> None:
    """Helix Linear ("Identifying wear with follower nut assemblies"): a nut has lived its
    full life when its thread is worn halfway through its tooth thickness, a quarter of the
    pitch. The catalog's allowed depth, normal to a 15 deg flank of height H1 = P/2,
    thins the thread along the axis by h / cos 15 deg: Tr12x3, 0.483 x 1.5 mm = 0.7245 mm
    deep, 0.7245 / 0.9659 = 0.750 mm = 3 mm / 4. The low end of its range, 0.1, is for an
    axis that tolerates little added play."""
    screw = catalog.by_id[screw_id]
    assert screw.pitch_m is not None and screw.flank_height_m is not None
    assert screw.allowed_wear_fraction is not None
    depth_m = screw.allowed_wear_fraction * screw.flank_height_m
    thinning_m = depth_m / math.cos(math.radians(15.0))
    assert thinning_m == pytest.approx(screw.pitch_m / 4.0, rel=1e-3)
    low, high = screw.assumption_ends["allowed_wear_to_flank_height"]
    assert (low["allowed_wear_fraction"], high["allowed_wear_fraction"]) == (0.1, 0.483)


TR14 = Application(
    load_n=1962.0,
    speed_m_s=0.02,
    length_m=0.6,
    stroke_m=0.5,
    cycles_per_day=50.0,
    required_life_years=5.0,
)


def test_wear_life_of_a_tr14_acetal_nut_by_hand(catalog: Catalog) -> None:
    """Tr14x3 (d2 12.5 mm, H1 1.5 mm), acetal nut 2 d = 28 mm long, 1962 N (200 kg):
    flank area 28 / 3 x pi x 12.5 x 1.5 = 549.8 mm^2, p = 3.569 MPa; allowed wear
    0.483 x 1.5 = 0.7245 mm (a quarter of the pitch off the thread's thickness, Helix
    Linear; wear.wear_life_sliding); k = 1e-6 mm^3/(N m): sliding life 0.7245e-3 /
    (1e-15 x 3.569e6) = 203.0 km; sliding per metre sqrt(3^2 + (12.5 pi)^2) / 3 = 13.13;
    travel 15.46 km; at 2 x 0.5 m x 50 a day, 0.8473 years."""
    screw = catalog.by_id["Tr14x3-acetal"]
    result = {c.name: c for c in evaluate(TR14, screw).checks}["wear_life"]
    area = 28 / 3 * math.pi * 12.5 * 1.5 * 1e-6
    sliding = 0.483 * 1.5e-3 / (1e-15 * 1962.0 / area)
    travel = sliding / (math.hypot(3.0, 12.5 * math.pi) / 3.0)
    assert travel == pytest.approx(15464.0, rel=1e-3)
    assert result.limit == pytest.approx(life.life_years(travel, 0.5, 50.0), rel=1e-9)
    assert result.limit == pytest.approx(0.8473, rel=1e-3)
    assert not result.passed


def test_bronze_outlasts_acetal_by_the_ratio_of_wear_rates(catalog: Catalog) -> None:
    """Same screw, same thrust, both greased (a bronze nut's wear rate is a lubricated
    nut's): life scales with 1 / k (catalog: acetal 1e-6, bronze 1e-8 mm^3/(N m)), so the
    bronze nut lasts 100 times longer and passes 5 years."""
    greased = replace(TR14, lubrication="greased")
    results = {
        nut: {c.name: c for c in evaluate(greased, catalog.by_id[f"Tr14x3-{nut}"]).checks}
        for nut in ("acetal", "bronze")
    }
    acetal, bronze = results["acetal"]["wear_life"], results["bronze"]["wear_life"]
    assert bronze.limit == pytest.approx(100.0 * acetal.limit, rel=1e-9)
    assert bronze.passed


def test_the_life_band_spans_the_wear_rates_scatter(catalog: Catalog) -> None:
    """The message gives the travel at both ends of the wear rate's range (3.3e-7 to
    3e-6 mm^3/(N m) for acetal): 15.46 km x 1e-6 / 3e-6 = 5.155 km to 46.86 km."""
    from app.contract.units import DEFAULT_UNITS, render

    result = {c.name: c for c in evaluate(TR14, catalog.by_id["Tr14x3-acetal"]).checks}
    text = render(result["wear_life"].message)
    # no moving mass, and a load against the motion both ways: every segment carries the
    # 1962 N, so the cycle's wear thrust is the load
    assert "15.46 km of travel at the cycle's wear thrust of 1962 N (5.155 km to 46.86 km" in text
    assert (
        render(result["wear_life"].message, {**DEFAULT_UNITS, "length_unit": "in"}).count(" mi")
        == 3
    )  # 9.609 mi (3.203 mi to 29.12 mi): travel in miles with inches
    assert "falls short of the 5 years required" in text


def test_a_wear_rated_nut_is_no_longer_unrated_for_the_life_check(catalog: Catalog) -> None:
    """The seed's life check (rated travel) leaves a nut rated by its wear rate to the
    wear check; a nut with neither still fails it as unrated."""
    greased = replace(TR14, lubrication="greased")
    by_name = {c.name: c for c in evaluate(greased, catalog.by_id["Tr14x3-bronze"]).checks}
    assert "life" not in by_name or by_name["life"].passed
    assert BY_NAME["wear_life"].kind == "limit"


def test_a_bronze_nut_run_dry_has_no_rated_wear(catalog: Catalog) -> None:
    """A bronze nut's wear rate is a lubricated nut's (Archard's mild-wear K of lubricated
    metals, catalog/iso-trapezoidal/common.toml); run dry (the lubrication input's
    default) none is given, and a dry copper alloy on steel wears orders of magnitude
    faster. Its wear life was worked at the oiled rate whatever the lubrication (Tr22x10
    bronze run dry under 1500 N passed a 5 year life with 399 years). Run dry, its wear
    is not rated, and a life required of it is not met: grease or oil it."""
    screw = catalog.by_id["Tr14x3-bronze"]
    dry = evaluate(TR14, screw)
    assert math.isnan(dry.quantities.life.wear_travel_m)
    life_check = {c.name: c for c in dry.checks}["life"]
    assert not life_check.passed
    assert render(life_check.message).startswith("The nut's wear rate is a lubricated nut's")
    assert render(life_check.fix).startswith("Grease or oil the nut")
    greased = evaluate(replace(TR14, lubrication="greased"), screw)
    checks = {c.name: c for c in greased.checks}
    assert greased.quantities.life.wear_travel_m > 0.0 and checks["wear_life"].passed


def test_no_thrust_no_wear_check(catalog: Catalog) -> None:
    """Without thrust the life is unbounded: the check does not apply (no inf leaves)."""
    idle = Application(
        load_n=0.0,
        speed_m_s=0.02,
        length_m=0.6,
        stroke_m=0.5,
        cycles_per_day=50.0,
        required_life_years=5.0,
    )
    names = {c.name for c in evaluate(idle, catalog.by_id["Tr14x3-acetal"]).checks}
    assert "wear_life" not in names


def test_the_offered_load_gives_the_required_life(catalog: Catalog) -> None:
    """Life is inversely proportional to the thrust: the load the check offers makes the
    Tr14x3 acetal nut last exactly the 5 years required (1962 N x 0.8473 / 5 = 332.5 N)."""
    screw = catalog.by_id["Tr14x3-acetal"]
    failed = {c.name: c for c in evaluate(TR14, screw).checks}["wear_life"]
    assert failed.input_limits is not None
    load = failed.input_limits["load_n"]
    assert load == pytest.approx(1962.0 * 0.8473 / 5.0, rel=1e-3)
    again = {c.name: c for c in evaluate(replace(TR14, load_n=load), screw).checks}
    assert again["wear_life"].passed
