"""Screws of one's own through POST /evaluate, worked by hand: a Tr20x4 C45 screw of the
user's with the catalog's bronze nut on a 60 mm nut, oiled, and a 2-start 12 mm lead
aluminium screw (E 70 GPa of the user's) with the PTFE nut."""

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient

from tests.api.calls import check, evaluate

#: Tr20x4 of one's own in C45, the catalog's bronze nut, oiled friction.
TR20X4_BRONZE = {
    "outer_diameter_mm": 20, "root_diameter_mm": 15.5, "lead_mm": 4, "pitch_mm": 4,
    "thread_half_angle_deg": 15, "friction_dynamic": 0.13, "friction_static": 0.16,
    "material": "c45-steel", "nut_material": "bronze",
}  # fmt: skip
#: A horizontal axis with a stroke, duty and required life, on a 60 mm nut.
LONG_NUT_AXIS = {
    "load_n": 3000, "speed_mm_s": 30, "length_mm": 800, "accel_mm_s2": 300,
    "end_fixity": "fixed-simple", "nut_length_mm": 60, "lubrication": "oiled",
    "stroke_mm": 600, "cycles_per_day": 200, "required_life_years": 5, "moving_mass_kg": 50,
}  # fmt: skip
#: d 20, d_r 13, lead 12 on pitch 6 (2 starts), the user's aluminium, the PTFE nut.
ALUMINIUM_2_START = {
    "outer_diameter_mm": 20, "root_diameter_mm": 13, "lead_mm": 12, "pitch_mm": 6,
    "thread_half_angle_deg": 15, "friction_dynamic": 0.15, "friction_static": 0.20,
    "material": {"youngs_modulus_pa": 70e9, "density_kg_m3": 2700, "yield_strength_pa": 275e6},
    "nut_material": "ptfe",
}  # fmt: skip
FAST_AXIS = {
    "load_n": 200, "speed_mm_s": 300, "length_mm": 1000, "accel_mm_s2": 2000,
    "end_fixity": "fixed-fixed", "moving_mass_kg": 10, "stroke_mm": 800,
    "cycles_per_day": 500, "required_life_years": 3,
}  # fmt: skip


def _custom(client: TestClient, screw: dict[str, Any], **axis: Any) -> Any:
    return evaluate(client, screw, **axis)


def test_a_longer_nut_of_ones_own_is_held_to_misumis_thrust(client: TestClient) -> None:
    """MISUMI rates the Tr20x4 bronze nut at 9810 N, read over the family's 2 x d = 40 mm
    nut: 10 turns x pi x 18 x 2 mm^2 = 1131 mm^2, 8.674 MPa. A 60 mm nut (15 turns,
    1696 mm^2) was rated 8.674 x 1696 = 14,715 N, 1.5 x the maker's rating, with the
    maker's "vendor" provenance; it is held to 9810 N and says why. The contact-pressure
    check (Shigley's 1 MPa above 0.25 m/s over the 60 mm nut's 1696 mm^2 = 1696 N) is the
    handbook's and still reads the longer nut."""
    c = _custom(client, TR20X4_BRONZE, **LONG_NUT_AXIS)
    rated = check(c, "design_load")
    turn = math.pi * 18e-3 * 2e-3
    assert 9810 / (10 * turn) * 15 * turn == pytest.approx(14715.0)  # the old rating
    assert rated["limit"] == pytest.approx(9810.0)
    assert "The 60 mm nut is held to the rating of the 40 mm nut" in rated["message"]
    assert check(c, "bearing_pressure")["limit"] == pytest.approx(1e6 * 15 * turn)
    # the 60 mm nut is the user's, not the family's assumed 2 x d
    assert c["provenance"]["nut_length"]["kind"] == "user"
    assert "nut_length" not in [r["field"] for r in c["verdict"]["rests_on"]]


def test_a_named_materials_conductivity_keeps_its_provenance(client: TestClient) -> None:
    """The nut heat of the Tr20x4 runs on C45's 50.7 W/(m K) (Incropera, handbook), which
    the answer called "not checked". By hand: the mean speed over a 600 mm move with
    0.1 s ramps at 0.3 m/s^2 is 600 / 20.1 = 29.85 mm/s; eta = (cos 15 - 0.13 x 0.070736)
    / (cos 15 + 0.13 / 0.070736) = 0.34124; Q = 3000 x 0.02985 x (1 / 0.34124 - 1) =
    172.9 W; the screw's two fins, each sqrt(10 x pi 0.0155 x 50.7 x pi 0.0155^2 / 4) =
    0.068253 W/K were it endless, here 70 and 670 mm long each side of the nut at the end
    of the 600 mm stroke centred on the 800 mm screw, insulated at their ends (Incropera
    Table 3.4, case B: times tanh(m L), m = sqrt(4 x 10 / (50.7 x 0.0155)) = 7.1344 /m):
    0.068253 (0.46165 + 0.99986) = 0.09975 W/K, and the nut's surface
    10 x pi x 0.04 x 0.06 = 0.07540 W/K: 987 K."""
    c = _custom(client, TR20X4_BRONZE, **LONG_NUT_AXIS)
    heat = check(c, "nut_heat")
    q = 3000 * (0.6 / 20.1) * (1 / 0.34124 - 1)
    endless = math.sqrt(10 * math.pi * 0.0155 * 50.7 * math.pi * 0.0155**2 / 4)
    m = math.sqrt(4 * 10 / (50.7 * 0.0155))
    fins = endless * (math.tanh(m * 0.07) + math.tanh(m * 0.67))
    assert heat["value"] == pytest.approx(q / (fins + 10 * math.pi * 0.04 * 0.06), rel=1e-3)
    assert heat["value"] == pytest.approx(987.0, abs=1.0)
    assert c["provenance"]["thermal_conductivity"]["kind"] == "handbook"
    assert "50.7" in c["provenance"]["thermal_conductivity"]["source"]


def test_nut_heat_without_a_conductivity_is_named_not_checked(client: TestClient) -> None:
    """The user's own material gives no thermal conductivity: the nut heat check cannot
    run on the 800 mm stroke, and the summary says so (it listed only the traverse speed
    and the length)."""
    c = _custom(client, ALUMINIUM_2_START, **FAST_AXIS)
    assert "nut_heat" not in [x["name"] for x in c["checks"]]
    assert "Nut heat (no screw thermal conductivity)" in c["verdict"]["summary"]


def test_an_own_materials_expansion_is_said_to_be_steels(client: TestClient) -> None:
    """The thermal growth of the aluminium screw takes steel's 11.7e-6 1/K, not asked of
    the user: 11.7e-6 x 30 K x 0.8 m = 0.2808 mm (aluminium's 23e-6 would give 0.552 mm).
    Its provenance says so, "assumed" (there was none; the candidate listed no
    screw_expansion)."""
    c = _custom(client, ALUMINIUM_2_START, **FAST_AXIS, ambient_c=50, positioning_tolerance_mm=0.5)
    assert c["accuracy"]["thermal_growth_mm"] == pytest.approx(11.7e-6 * 30 * 800)
    expansion = c["provenance"]["screw_expansion"]
    assert expansion["kind"] == "assumed" and "steel's" in expansion["source"]


def test_the_aluminium_screw_by_hand(client: TestClient) -> None:
    """d2 = 20 - 6 / 2 = 17 mm; tan(lambda) = 12 / (pi 17) = 0.224689 (12.663 deg);
    eta = (cos 15 - 0.15 x 0.224689) / (cos 15 + 0.15 / 0.224689) = 0.57068; back-driving
    at static 0.20: (cos 15 x 0.224689 - 0.2) / (0.224689 (cos 15 + 0.2 x 0.224689)) =
    0.07499; 1500 rpm; T_load = 200 x 0.012 / (2 pi 0.57068) = 0.66933 N m; critical
    2.23 x pi^2 / 1^2 x sqrt(70e9 / 2700) x 0.013 / 4 = 364.22 rad/s = 3478 rpm; Euler
    fixed-fixed 4 pi^2 x 70e9 x pi 0.013^4 / 64 = 3874 N; PV 0.2 MPa m/s over the sliding
    speed 25 x sqrt(12^2 + (17 pi)^2) = 1368.5 mm/s = 0.14615 MPa over 40 / 6 turns of
    pi 17 x 3 mm^2 (1068.1 mm^2) = 156.1 N; MISUMI's Tr32x6 plastic nut 2050 N x 0.7 over
    its 64 mm nut (2915.5 mm^2) = 0.4922 MPa, over 1068.1 mm^2 = 525.75 N."""
    c = _custom(client, ALUMINIUM_2_START, **FAST_AXIS)
    tan = 12 / (math.pi * 17)
    cos = math.cos(math.radians(15))
    assert c["pitch_diameter_mm"] == pytest.approx(17.0)
    assert c["efficiency"] == pytest.approx((cos - 0.15 * tan) / (cos + 0.15 / tan))
    assert c["backdrive_efficiency"] == pytest.approx((cos * tan - 0.2) / (tan * (cos + 0.2 * tan)))
    assert c["torque"]["load_nm"] == pytest.approx(200 * 0.012 / (2 * math.pi * 0.570685), 1e-5)
    omega = 2.23 * math.pi**2 * math.sqrt(70e9 / 2700) * 0.013 / 4
    assert c["critical_speed"]["theoretical_rpm"] == pytest.approx(omega * 60 / (2 * math.pi))
    euler = 4 * math.pi**2 * 70e9 * math.pi * 0.013**4 / 64
    assert c["buckling"]["critical_load_n"] == pytest.approx(euler)
    area = 40 / 6 * math.pi * 17e-3 * 3e-3
    sliding = 25 * math.hypot(12e-3, 17e-3 * math.pi)
    assert check(c, "bearing_pressure")["limit"] == pytest.approx(0.2e6 / sliding * area)
    tr32 = 64 / 6 * math.pi * 29e-3 * 3e-3
    assert check(c, "design_load")["limit"] == pytest.approx(0.7 * 2050 / tr32 * area)


def test_an_own_material_gives_its_thermal_expansion(client: TestClient) -> None:
    """An aluminium screw of one's own (23e-6 1/K typed) over an 800 mm stroke at 50 °C
    ambient (30 K above the 20 °C the screw is measured at): it grows 23e-6 x 800 mm x 30 K
    = 0.552 mm; left out, steel's 11.7e-6 is taken (assumed): 0.2808 mm."""
    material = {"youngs_modulus_pa": 70e9, "density_kg_m3": 2700.0, "yield_strength_pa": 275e6}
    screw = {
        "outer_diameter_mm": 20.0, "root_diameter_mm": 13.0, "lead_mm": 12.0, "pitch_mm": 6.0,
        "thread_half_angle_deg": 15.0, "friction_static": 0.2, "friction_dynamic": 0.15,
        "nut_material": "ptfe",
    }  # fmt: skip
    axis = {"load_n": 200.0, "speed_mm_s": 100.0, "length_mm": 1000.0, "stroke_mm": 800.0}
    typed = {**screw, "material": {**material, "expansion_per_k": 23e-6}}
    grown = evaluate(client, typed, **axis, ambient_c=50.0)["accuracy"]["thermal_growth_mm"]
    assert grown == pytest.approx(23e-6 * 800.0 * 30.0, rel=1e-9)
    steel = evaluate(client, {**screw, "material": material}, **axis, ambient_c=50.0)
    assert steel["accuracy"]["thermal_growth_mm"] == pytest.approx(11.7e-6 * 800.0 * 30.0)


def test_the_named_steel_carries_a_conductivity_so_its_nut_heat_runs(client: TestClient) -> None:
    """The catalog's "steel" (the C45 class, as its yield strength) now gives Incropera's
    AISI 1042 50.7 W/(m K): the Tr20x4 of "steel" is checked for nut heat as the same
    screw of "c45-steel" is, with the same figure (both 50.7 W/(m K)); it was left
    unchecked."""
    steel = _custom(client, {**TR20X4_BRONZE, "material": "steel"}, **LONG_NUT_AXIS)
    c45 = _custom(client, TR20X4_BRONZE, **LONG_NUT_AXIS)
    assert check(steel, "nut_heat")["value"] == pytest.approx(check(c45, "nut_heat")["value"])
    conductivity = steel["provenance"]["thermal_conductivity"]
    assert conductivity["kind"] == "handbook" and "50.7" in conductivity["source"]
