"""What a real axis feels, through the API (issue 21): the inertia of the moving mass and
the rotor in every check, the load's direction, holding with a brake or a stepper, ranking
and fixes. Each figure is worked out here by hand from the reference formulas
(engineering.md; Shigley, Mechanical Engineering Design, 9th ed., sec. 8-2; Newton's
second law on the moving mass), never read back from the app."""

import math
from typing import Any

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from tests.api.calls import check, evaluate, names

G = 9.80665
COS_ACME = math.cos(math.radians(14.5))
COS_ISO = math.cos(math.radians(15.0))
API = "/api/v1"


def eta(tan_l: float, mu: float, cos_a: float) -> float:
    """Shigley's forward efficiency of a thread of flank half-angle a_n."""
    return (cos_a - mu * tan_l) / (cos_a + mu / tan_l)


def eta_back(tan_l: float, mu: float, cos_a: float) -> float:
    """Shigley's back-drive efficiency (signed: negative when the thread self-locks)."""
    return (cos_a * tan_l - mu) / (tan_l * (cos_a + mu * tan_l))


# B4000 (1/4 in, root 0.78 OD assumed), 12 mm lead, TFE: mu 0.09 running, 0.08 static;
# screw inertia 2.11e-8 kg m^2 per inch (seed, exponent corrected); free-wheeling, no drag.
B4_OD, B4_RD, B4_LEAD = 6.35e-3, 0.78 * 6.35e-3, 0.012
B4_TAN = B4_LEAD / (math.pi * (B4_OD + B4_RD) / 2)
B4_J_PER_M = 2.11e-8 / 0.0254

# --- 1. inertia everywhere ------------------------------------------------------------------

PICK_AND_PLACE = {
    "load_n": 0, "speed_mm_s": 250, "length_mm": 300, "stroke_mm": 200, "accel_mm_s2": 10000,
    "moving_mass_kg": 0.5, "motor_inertia_kg_m2": 5.4e-6, "max_torque_nm": 0.05,
}  # fmt: skip


def test_max_torque_check_includes_rotor_inertia(client: TestClient) -> None:
    """B4000-L12-TFE, 0.5 kg at 10 m/s^2, rotor 5.4e-6 kg m^2 (a NEMA 17 stepper's 54 g cm^2):
    alpha = 2 pi a / lead = 5236 rad/s^2;
    m a through the thread 5 x 0.012 / (2 pi x 0.8239) = 0.01159 N m,
    screw J alpha = 8.31e-7 x 0.3 x 5236 = 0.00130 N m, rotor J alpha = 0.02827 N m:
    the accelerating segment needs 0.04117 N m, not the 0.01289 N m without the rotor, and
    the check judges the same figure as the move's own peak segment."""
    c = evaluate(client, "B4000-L12-TFE", **PICK_AND_PLACE)
    alpha = 2 * math.pi * 10.0 / B4_LEAD
    t_mass = 0.5 * 10.0 * B4_LEAD / (2 * math.pi * eta(B4_TAN, 0.09, COS_ACME))
    t_screw = B4_J_PER_M * 0.3 * alpha
    t_rotor = 5.4e-6 * alpha
    hand = t_mass + t_screw + t_rotor
    tan_l = B4_TAN
    assert tan_l == pytest.approx(0.6759, abs=1e-4)
    assert eta(B4_TAN, 0.09, COS_ACME) == pytest.approx(0.8239, abs=1e-4)
    assert (t_mass, t_screw, t_rotor) == pytest.approx((0.01159, 0.001305, 0.02827), abs=2e-5)
    assert check(c, "torque")["value"] == pytest.approx(hand, rel=1e-6)
    assert hand == pytest.approx(0.04117, abs=1e-5) and check(c, "torque")["passed"]
    assert c["torque"]["peak_nm"] == pytest.approx(hand, rel=1e-6)
    assert c["torque"]["inertia_nm"] == pytest.approx(t_mass + t_screw + t_rotor, rel=1e-6)
    assert c["torque"]["total_nm"] == pytest.approx(hand, rel=1e-6)  # no load, no drag


def test_the_nut_carries_m_a_with_no_load(client: TestClient) -> None:
    """Tr16x4 bronze, load 0, 20 kg at 2 m/s^2: the nut carries m a = 40 N, not 0 N
    (contact pressure); B4000-L12-TFE's PV at 40 N and n = 0.05 / 0.012 rev/s is
    n F / (3 h) with h = (OD - RD) / 2 (seed PV, three threads, H.T. cancels), in MPa m/s."""
    axis = {"load_n": 0, "speed_mm_s": 50, "length_mm": 500, "moving_mass_kg": 20,
            "accel_mm_s2": 2000}  # fmt: skip
    bronze = check(evaluate(client, "Tr16x4-bronze", **axis), "bearing_pressure")
    assert bronze["value"] == pytest.approx(20 * 2.0)
    b4 = evaluate(client, "B4000-L12-TFE", **axis)
    h = (B4_OD - B4_RD) / 2
    assert check(b4, "pv")["value"] == pytest.approx(0.05 / 0.012 * 40.0 / (3 * h) / 1e6)


def test_braking_deceleration_sets_the_peak_thrust(client: TestClient) -> None:
    """Vertical, 20 kg, load 0, accel 1 m/s^2, decel 2 m/s^2: braking the descent pushes
    m g + m d = 196.13 + 40 = 236.13 N on the nut (not m g + m a = 216.13 N): buckling
    (thrust bearing below the nut), root stress and design load all judge 236.13 N."""
    c = evaluate(client, "B8000-L10", load_n=0, speed_mm_s=50, length_mm=500,
                 orientation="vertical", moving_mass_kg=20, accel_mm_s2=1000,
                 decel_mm_s2=2000, brake_torque_nm=1)  # fmt: skip
    peak = 20 * G + 20 * 2.0
    assert peak == pytest.approx(236.13, abs=0.01)
    assert c["peak_axial_load_n"] == pytest.approx(peak)
    assert check(c, "buckling")["value"] == pytest.approx(peak)
    assert check(c, "design_load")["value"] == pytest.approx(peak)
    # root stress: von Mises of peak / A and the shear of T = peak lead / (2 pi eta) +
    # J_screw alpha (no drag on a free-wheeling nut; eta at mu_d 0.15, below the static
    # 0.08's), tau = 16 T / (pi d_r^3) (Shigley eqs. 8-7, 8-8, 5-15)
    d_r = 0.78 * 12.7e-3
    tan_l = 0.01 / (math.pi * (12.7e-3 + d_r) / 2)
    eta = (COS_ACME - 0.15 * tan_l) / (COS_ACME + 0.15 / tan_l)
    j_alpha = 3.67e-7 / 0.0254 * 0.5 * (2 * math.pi * 1.0 / 0.01)
    torque_nm = peak * 0.01 / (2 * math.pi * eta) + j_alpha
    sigma, tau = peak / (math.pi * d_r**2 / 4), 16 * torque_nm / (math.pi * d_r**3)
    vm = math.sqrt(sigma**2 + 3 * tau**2)
    assert check(c, "root_stress")["value"] == pytest.approx(vm / 1e6, rel=1e-6)


# --- 2. the load's direction -----------------------------------------------------------------

# ZBX8000 (1/2 in, root 0.78 OD), 10 mm lead, uncoated: mu 0.15 running, 0.08 static,
# drag 0.02-0.04 N m (the top for sizing, the bottom where the load drives).
Z8_OD, Z8_RD, Z8_LEAD, Z8_DRAG, Z8_DRAG_MIN = 12.7e-3, 0.78 * 12.7e-3, 0.010, 0.04, 0.02
Z8_TAN = Z8_LEAD / (math.pi * (Z8_OD + Z8_RD) / 2)


def segment(candidate: dict[str, Any], name: str, direction: str) -> dict[str, Any]:
    return next(
        s for s in candidate["segments"] if (s["name"], s["direction"]) == (name, direction)
    )


def test_guide_friction_on_a_vertical_axis_opposes_both_ways(client: TestClient) -> None:
    """2 kg on a vertical ZBX8000-L10 with 50 N of guide friction. Up at constant speed the
    nut pushes m g + 50 = 69.61 N; down it must push the carriage through the friction,
    50 - m g = 30.39 N against the motion: T = 30.39 x 0.01 / (2 pi x 0.6170) + 0.04 =
    0.1184 N m driving. Taken as weight the 50 N would let the load drive the screw
    down (-69.61 N, eta_b 0.431): the motor brakes, at the bottom of the seed's drag
    range, 0.02 N m, where that brakes hardest: -0.0278 N m (-0.0078 at the top, 0.04).
    Only the weight is held at rest (friction holds nothing): T_physics = 19.61 x 0.01 x
    eta_b(mu_s 0.08) / 2 pi."""
    axis = {"load_n": 50, "speed_mm_s": 50, "length_mm": 500, "stroke_mm": 200,
            "orientation": "vertical", "moving_mass_kg": 2, "brake_torque_nm": 1}  # fmt: skip
    c = evaluate(client, "ZBX8000-L10", **axis, load_direction="opposes")
    e = eta(Z8_TAN, 0.15, COS_ACME)
    assert e == pytest.approx(0.6170, abs=1e-4)
    down = segment(c, "constant", "down")
    assert down["thrust_n"] == pytest.approx(50 - 2 * G)
    assert down["torque_nm"] == pytest.approx((50 - 2 * G) * Z8_LEAD / (2 * math.pi * e) + Z8_DRAG)
    assert down["torque_nm"] == pytest.approx(0.1184, abs=1e-4)
    up = segment(c, "constant", "up")
    assert up["torque_nm"] == pytest.approx((50 + 2 * G) * Z8_LEAD / (2 * math.pi * e) + Z8_DRAG)
    as_weight = segment(evaluate(client, "ZBX8000-L10", **axis), "constant", "down")
    eb = eta_back(Z8_TAN, 0.15, COS_ACME)
    assert eb == pytest.approx(0.431, abs=1e-3)
    assert as_weight["torque_nm"] == pytest.approx(-(50 + 2 * G) * Z8_LEAD * eb / (2 * math.pi)
                                                   + Z8_DRAG_MIN)  # fmt: skip
    assert as_weight["torque_nm"] == pytest.approx(-0.0278, abs=1e-4)
    hold = 2 * G * Z8_LEAD * eta_back(Z8_TAN, 0.08, COS_ACME) / (2 * math.pi)
    assert c["holding_torque"]["physics_nm"] == pytest.approx(hold)


def test_a_spring_on_a_horizontal_axis_is_held_and_compresses_one_way(
    client: TestClient,
) -> None:
    """A 100 N spring pushing a horizontal ZBX8000-L10 back (a load of fixed direction):
    the nut pushes 100 N out and back alike, so with the thrust bearing at the far end
    (tension on the out move) the screw is never pushed (no buckling), and at rest the
    spring must be held like a weight: without a brake the self-locking check applies."""
    c = evaluate(client, "ZBX8000-L10", load_n=100, speed_mm_s=50, length_mm=500,
                 load_direction="fixed", compression=False)  # fmt: skip
    assert "buckling" not in names(c) and "back_driving" in names(c)
    opposing = evaluate(client, "ZBX8000-L10", load_n=100, speed_mm_s=50, length_mm=500,
                        compression=False)  # fmt: skip
    # friction reverses on the move back and pushes the screw with the 100 N
    assert check(opposing, "buckling")["value"] == pytest.approx(100.0)
    assert "back_driving" not in names(opposing)


def test_load_direction_is_a_field_with_a_422(client: TestClient) -> None:
    response = client.get(f"{API}/select", params={"load_n": 1, "speed_mm_s": 1,
                          "length_mm": 100, "load_direction": "sideways"})  # fmt: skip
    assert response.status_code == 422
    assert response.json()["detail"][0]["field"] == "load_direction"


# --- 3. holding honestly ---------------------------------------------------------------------


def test_the_brake_is_sized_at_the_distrusted_friction(client: TestClient) -> None:
    """ZBX8000-L10 holding 10 kg (98.07 N): at static friction 0.08 the physical holding
    torque is 98.07 x 0.01 x eta_b(0.08) / 2 pi = 0.1078 N m, and a 0.11 N m brake looked
    enough; the self-locking margin trusts only 0.5 x 0.08 = 0.04, where eta_b = 0.8435 and
    the load needs 0.1317 N m (the seed's 0.0963 N m is lower): 0.11 N m is short. A brake's
    service factor of 1.5 (Machine Design), the default for a brake, or typed as the holding
    safety factor, asks 1.5 x 0.1317 = 0.1975 N m; typed as 1, 0.1317 N m."""
    axis = {"load_n": 0, "speed_mm_s": 20, "length_mm": 300, "orientation": "vertical",
            "moving_mass_kg": 10}  # fmt: skip
    force = 10 * G
    at_full = force * Z8_LEAD * eta_back(Z8_TAN, 0.08, COS_ACME) / (2 * math.pi)
    distrusted_eta = eta_back(Z8_TAN, 0.04, COS_ACME)
    needed = force * Z8_LEAD * distrusted_eta / (2 * math.pi)
    seed = force * Z8_LEAD * eta(Z8_TAN, 0.15, COS_ACME) / (2 * math.pi)
    assert (at_full, distrusted_eta, needed) == pytest.approx((0.1078, 0.8435, 0.1317), abs=1e-4)
    assert seed == pytest.approx(0.0963, abs=1e-4)
    short = check(evaluate(client, "ZBX8000-L10", **axis, brake_torque_nm=0.11), "holding")
    assert short["value"] == pytest.approx(1.5 * needed) and not short["passed"]
    one = evaluate(client, "ZBX8000-L10", **axis, brake_torque_nm=0.11, brake_safety_factor=1)
    assert check(one, "holding")["value"] == pytest.approx(needed)
    assert "with the power off (a brake)" in short["message"]
    factored = evaluate(
        client, "ZBX8000-L10", **axis, brake_torque_nm=0.14, brake_safety_factor=1.5
    )
    assert check(factored, "holding")["value"] == pytest.approx(1.5 * needed)
    assert 1.5 * needed == pytest.approx(0.1975, abs=1e-4)


# Tr8x8(P2), the usual 3D-printer Z screw: d2 = d - 0.5 P = 7.0 mm (ISO 2904), bronze nut
# greased, mu 0.16 static, 0.13 running (run dry it would be 0.24 and 0.19); 30-degree thread.
TR8_LEAD, TR8_D2 = 0.008, 0.007
TR8_TAN = TR8_LEAD / (math.pi * TR8_D2)
PRINTER_Z = {"load_n": 0, "moving_mass_kg": 3, "orientation": "vertical", "speed_mm_s": 10,
             "accel_mm_s2": 100, "length_mm": 350, "stroke_mm": 300,
             "brake_torque_nm": 0.4, "holding_source": "energised",
             "lubrication": "greased"}  # fmt: skip


def test_a_stepper_holds_while_energised_and_its_detent_with_the_power_off(
    client: TestClient,
) -> None:
    """3D-printer Z: a 3 kg gantry on Tr8x8(P2) bronze, a NEMA 17 stepper (0.4 N m
    energised holding torque, 0.022 N m detent). Holding 29.42 N needs
    29.42 x 0.008 x eta_b(0.5 x 0.16 = 0.08) / 2 pi = 0.0281 N m (eta_b = 0.7497; the
    seed's, at eta 0.6942, is 0.0260 N m): energised it holds (0.4 N m); with the power off
    the 0.022 N m detent is short, and without a detent torque given the thread must
    self-lock, which at lead 8 mm it does not (lead max pi d2 0.08 / cos 15 = 1.82 mm)."""
    force = 3 * G
    eb = eta_back(TR8_TAN, 0.08, COS_ISO)
    needed = force * TR8_LEAD * eb / (2 * math.pi)
    seed = force * TR8_LEAD * eta(TR8_TAN, 0.13, COS_ISO) / (2 * math.pi)
    assert (eb, needed, seed) == pytest.approx((0.7497, 0.02809, 0.02600), abs=1e-4)
    c = evaluate(client, "Tr8x8(P2)-bronze", **PRINTER_Z, detent_torque_nm=0.022)
    on, off = check(c, "holding"), check(c, "holding_power_off")
    assert on["value"] == pytest.approx(needed) and on["passed"]
    assert "with the power on" in on["message"]
    assert off["value"] == pytest.approx(needed) and off["limit"] == 0.022
    assert not off["passed"] and "with the power off (detent torque)" in off["message"]
    assert "back_driving" not in names(c)
    unknown = evaluate(client, "Tr8x8(P2)-bronze", **PRINTER_Z)
    lock = check(unknown, "back_driving")
    lead_max_mm = math.pi * TR8_D2 * 0.08 / COS_ISO * 1e3  # the API gives lengths in mm
    assert lock["limit"] == pytest.approx(lead_max_mm)
    assert lead_max_mm == pytest.approx(1.821, abs=1e-3) and not lock["passed"]
    assert "holding_power_off" not in names(unknown)


def test_a_library_stepper_holding_energised_holds_with_its_own_holding_torque(
    client: TestClient,
) -> None:
    """The same Z axis with the library's 17HS19-2004S1 (holding torque 0.59 N m, the
    maker's 59 N cm) and no holding torque typed: energised, the motor holds with its own
    0.59 N m; a torque typed in still wins; a brake (the default) is never assumed."""
    needed = 3 * G * TR8_LEAD * eta_back(TR8_TAN, 0.08, COS_ISO) / (2 * math.pi)
    axis = {k: v for k, v in PRINTER_Z.items() if k != "brake_torque_nm"}
    c = evaluate(client, "Tr8x8(P2)-bronze", **axis, motor="17hs19-2004s1")
    on = check(c, "holding")
    assert on["limit"] == 0.59 and on["value"] == pytest.approx(needed) and on["passed"]
    typed = evaluate(client, "Tr8x8(P2)-bronze", **PRINTER_Z, motor="17hs19-2004s1")
    assert check(typed, "holding")["limit"] == 0.4
    braked = {**axis, "holding_source": "brake"}
    assert "holding" not in names(evaluate(client, "Tr8x8(P2)-bronze", **braked))
    servo = evaluate(client, "Tr8x8(P2)-bronze", **axis, motor="yaskawa-sgm7j-01a")
    assert "holding" not in names(servo) and not check(servo, "back_driving")["passed"]


# --- 6. ranking and fixes --------------------------------------------------------------------


def test_failed_advice_never_ranks_above_a_clean_candidate(client: TestClient) -> None:
    """Lead 10 mm at 150 mm/s: the seed's traverse table recommends at most 100 mm/s for
    leads of 2.5 to 12 mm, so every seed screw carries a warning; the ISO screws have no
    such table. B4000-L10-TFE needs the least torque of all, 0.020 N m, yet it ranks after
    the clean Tr22x10(P5) with a PTFE or acetal nut (0.053 to 0.064 N m)."""
    body = client.get(f"{API}/select", params={"load_n": 10, "speed_mm_s": 150,
                      "length_mm": 300, "lead_mm": 10, "limit": 30}).json()  # fmt: skip
    warned = [bool(c["warned"]) for c in body["candidates"]]
    assert warned == sorted(warned) and warned[0] is False and warned[-1] is True
    ids = [c["id"] for c in body["candidates"]]
    assert ids.index("Tr22x10(P5)-acetal") < ids.index("B4000-L10-TFE")
    torque = {c["id"]: c["torque"]["total_nm"] for c in body["candidates"]}
    assert torque["B4000-L10-TFE"] < torque["Tr22x10(P5)-ptfe"]


def test_fixes_offer_only_leads_the_size_is_made_in(client: TestClient) -> None:
    """ZBX8000-L10 holding 10 kg with a 0.11 N m brake: it self-locks with margin up to a
    lead of pi d_p (0.5 x 0.08) / cos 14.5 = 1.467 mm; the 1/2 in size is made in 1 and
    2 mm, so the fix offers 1 mm (not 1.467 mm, which nobody makes). Tr8x8(P2) bronze
    self-locks only up to 1.82 mm and its size is made in 2, 4 and 8 mm: no lead is
    offered, only the brake (greased). Run dry it starts at static 0.24, which would
    self-lock up to pi 7 (0.5 x 0.24) / cos 15 = 2.73 mm, but holds at no more than the
    oiled 0.16 (it may be oiled later): still no lead is offered."""
    lead_max = math.pi * (Z8_OD + Z8_RD) / 2 * 0.04 / COS_ACME
    assert lead_max == pytest.approx(1.467e-3, abs=1e-6)
    c = evaluate(client, "ZBX8000-L10", load_n=0, speed_mm_s=20, length_mm=300,
                 orientation="vertical", moving_mass_kg=10, brake_torque_nm=0.11)  # fmt: skip
    fix = check(c, "holding")["fix"]
    assert "use a lead of 1 mm" in fix and "1.47" not in fix
    z = evaluate(client, "Tr8x8(P2)-bronze", **PRINTER_Z)
    assert "lead" not in check(z, "back_driving")["fix"]
    assert math.pi * TR8_D2 * 0.12 / COS_ISO == pytest.approx(2.73e-3, abs=1e-5)
    dry = evaluate(client, "Tr8x8(P2)-bronze", **{**PRINTER_Z, "lubrication": "dry"})
    assert "lead" not in check(dry, "back_driving")["fix"]


def test_a_fix_length_says_at_which_mounting_it_holds(client: TestClient) -> None:
    """ZBX8000-L10 (root 9.906 mm, 303 stainless E 193 GPa, rho 8000), 2 m fixed-free at
    300 mm/s = 1800 rpm: n_c = (1.875 / 2)^2 sqrt(E / rho) d_r / 4 x 60 / 2 pi = 102 rpm,
    far over; the length that would pass is the length at the ends as mounted."""
    c = evaluate(client, "ZBX8000-L10", load_n=10, speed_mm_s=300, length_mm=2000,
                 end_fixity="fixed-free")  # fmt: skip
    n_c = (1.875 / 2.0) ** 2 * math.sqrt(193e9 / 8000) * Z8_RD / 4 * 60 / (2 * math.pi)
    assert n_c == pytest.approx(102.1, abs=0.1)
    speed = check(c, "critical_speed")
    assert speed["limit"] == pytest.approx(0.8 * n_c, rel=1e-3) and not speed["passed"]
    assert "unsupported length at most" in speed["fix"]
    assert "with the ends fixed-free" in speed["fix"]


# --- 7. one pitch diameter -------------------------------------------------------------------


def test_an_iso_screw_shows_the_pitch_diameter_it_is_computed_with(
    client: TestClient, series_bodies: dict[str, BeautifulSoup]
) -> None:
    """Tr20x4 (ISO 2904): d2 = d - 0.5 P = 20 - 2 = 18.0 mm, the diameter its lead angle,
    efficiency and flank area use; (OD + RD) / 2 = (20 + 15.5) / 2 = 17.75 mm is the seed's
    P_o, which the catalog page showed for it. Both the API and the series' catalog page
    (/catalog/{series_id}) give 18."""
    c = evaluate(client, "Tr20x4-bronze", load_n=100, speed_mm_s=20, length_mm=500)
    assert c["pitch_diameter_mm"] == pytest.approx(20 - 0.5 * 4)
    tan_l = 4 / (math.pi * 18.0)
    # run dry (the default lubrication): the bronze nut's dry friction 0.19
    assert c["efficiency"] == pytest.approx(eta(tan_l, 0.19, COS_ISO))
    rows = [
        r for body in series_bodies.values() for r in body.select("tr[data-field=pitch_diameter]")
    ]
    shown = [" ".join(r.get_text(" ").split()) for r in rows]
    iso = [r for r in shown if "ISO 2904" in r]
    assert iso and all("standard" in r and "d2 = d - 0.5 P" in r for r in iso)
    assert any(r.startswith("pitch_diameter 18 mm") for r in iso)
    assert not any("17.75" in r for r in shown)


# --- 4. nut ratings --------------------------------------------------------------------------


def test_a_bronze_nut_has_a_sliding_speed_limit(client: TestClient) -> None:
    """Tr8x1.5 bronze at 50 mm/s turns 2000 rpm; its flanks slide at
    2000 / 60 x sqrt(1.5^2 + (pi 7.25)^2) mm = 0.761 m/s, over the 25 m/min = 0.417 m/s
    a bronze nut should not exceed (Bimeccanica's sizing data): rejected, where it used to
    rank first for 100 N over 500 mm. Tr8x4(P2) bronze at 750 rpm slides at 0.277 m/s."""
    c = evaluate(client, "Tr8x1.5-bronze", load_n=100, speed_mm_s=50, length_mm=500)
    v_s = 2000 / 60 * math.hypot(1.5e-3, math.pi * 7.25e-3)
    assert v_s == pytest.approx(0.761, abs=1e-3)
    sliding = check(c, "max_sliding_speed")
    assert sliding["value"] * 1e-3 == pytest.approx(v_s) and not sliding["passed"]
    assert sliding["limit"] * 1e-3 == pytest.approx(25 / 60, rel=1e-3)
    body = client.get(f"{API}/select", params={"load_n": 100, "speed_mm_s": 50,
                      "length_mm": 500}).json()  # fmt: skip
    assert "Tr8x1.5-bronze" not in [x["id"] for x in body["candidates"]]
    ok = evaluate(client, "Tr8x4(P2)-bronze", load_n=100, speed_mm_s=50, length_mm=500)
    assert check(ok, "max_sliding_speed")["value"] * 1e-3 == pytest.approx(
        750 / 60 * math.hypot(4e-3, math.pi * 7e-3)
    )


def test_the_nut_length_is_an_input(client: TestClient) -> None:
    """Tr16x4 bronze at 10 mm/s (150 rpm, flanks sliding at 2.5 x sqrt(4^2 + (pi 14)^2) mm =
    0.110 m/s, where Shigley's table allows 5.5 MPa): the catalog's 2 x d = 32 mm nut
    engages 8 turns of pi d2 H1 = pi x 14 x 2 mm^2, 703.7 mm^2, and carries 3870 N; a 20 mm
    nut engages 5 turns, 439.8 mm^2, 2419 N, and the message names the pressure."""
    axis = {"load_n": 3000, "speed_mm_s": 10, "length_mm": 500}
    turn = math.pi * 14e-3 * 2e-3
    catalog = check(evaluate(client, "Tr16x4-bronze", **axis), "bearing_pressure")
    short = check(evaluate(client, "Tr16x4-bronze", **axis, nut_length_mm=20), "bearing_pressure")
    assert catalog["limit"] == pytest.approx(5.5e6 * 8 * turn) and catalog["passed"]
    assert short["limit"] == pytest.approx(5.5e6 * 5 * turn) and not short["passed"]
    assert (5.5e6 * 8 * turn, 5.5e6 * 5 * turn) == pytest.approx((3870, 2419), abs=1)
    assert "where the nut material allows 5.5 MPa" in short["message"]


# --- 5. vacuum -------------------------------------------------------------------------------


def test_vacuum_changes_the_answer(client: TestClient) -> None:
    """The seed gives its polyacetal nut's weight loss at 1e-4 torr (0.37 % after 330 h);
    no outgassing is published for the ISO family's oiled bronze, acetal or PTFE nuts. In
    a vacuum those are warned and rank after every measured nut; out of it the ISO screws
    rank among the seed's."""
    c = evaluate(client, "Tr16x4-bronze", load_n=100, speed_mm_s=20, length_mm=500,
                 vacuum=True)  # fmt: skip
    assert "vacuum" in [w["name"] for w in c["warnings"]] and not check(c, "vacuum")["passed"]
    seed = evaluate(client, "B8000-L10", load_n=100, speed_mm_s=20, length_mm=500, vacuum=True)
    assert check(seed, "vacuum")["passed"] and "0.37 %" in check(seed, "vacuum")["message"]
    query = {"load_n": 100, "speed_mm_s": 20, "length_mm": 500, "limit": 100}
    plain = client.get(f"{API}/select", params=query).json()["candidates"]
    ids = [x["id"] for x in client.get(f"{API}/select", params={**query, "vacuum": True})
           .json()["candidates"]]  # fmt: skip
    assert any(x["id"].startswith("Tr") for x in plain[:10])
    # over a hundred measured seed screws pass, so none of the unmeasured ones is listed
    assert len(ids) == 100 and not any(x.startswith("Tr") for x in ids)


def test_the_holding_torque_a_brake_is_sized_on_is_reported(client: TestClient) -> None:
    """A 3000 N press on B6000-L2: at the full static friction (0.08) the thread
    self-locks, so the physics value is 0, but a hold counts on half of it
    (self_locking_friction_factor 0.5), where it back-drives; the brake is sized on the
    larger of the catalog's value and that one. The answer names the value it used: it
    showed 0 beside a brake of 0.428 N m, the larger of 0.308 and 0."""
    app = {"load_n": 3000, "load_direction": "fixed", "orientation": "vertical",
           "speed_mm_s": 5, "length_mm": 500}  # fmt: skip
    hold = evaluate(client, "B6000-L2", **app)["holding_torque"]
    assert hold["physics_nm"] == 0.0
    assert hold["brake_nm"] == pytest.approx(
        max(hold["seed_method_nm"], hold["physics_with_margin_nm"]), rel=1e-9
    )
    assert hold["physics_with_margin_nm"] > hold["seed_method_nm"] > 0
    assert hold["physics_with_margin_nm"] == pytest.approx(0.428, abs=1e-3)


def test_a_leadscrew_between_its_makers_and_the_beams_speed_fails(client: TestClient) -> None:
    """Tr16x4 bronze, 1.5 m, fixed-simple: its makers (Thomson, Roton) rate these ends
    C_s = 1.47 times simple-simple, Thomson's simple-simple 4.76e6 x 0.4528 / 59.06^2 =
    618.0 rpm (the C45 beam's 620.4 is above it), 1.47 x 618.0 = 908.4 rpm, allowed 0.8 x
    908.4 = 726.7 rpm; the beam's (3.92660 / pi)^2 = 1.562 would allow 0.8 x 969.2 = 775.4
    rpm. At 49.3 mm/s (60 x 49.3 / 4 = 739.5 rpm, between the two) the check fails, its
    message naming the makers' factor; at 40 mm/s (600 rpm) it passes. Fixed-fixed: C_s
    2.23 allows 0.8 x 2.23 x 618.0 = 1102.5 rpm (the beam's 2.267, 1125.0): 74.3 mm/s
    (1114.5 rpm) fails. Fixed-simple 6.3 % below the beam; simple-simple Thomson's
    constant alone, 0.4 % below the beam, and a ball screw is rated at most at HIWIN's:
    no leadscrew makers' factor there."""
    # Tr16x4: ISO 2904 root d3 = 16 - 4 - 2 x 0.25 = 11.5 mm, carbon steel E 207 GPa,
    # rho 7800 kg/m^3, over 1.5 m simple-simple (Blevins table 8-1, beta = pi)
    n_ss = 60 / (2 * math.pi) * (math.pi / 1.5) ** 2 * math.sqrt(207e9 / 7800) * 0.0115 / 4
    assert n_ss == pytest.approx(620.4, abs=0.05)
    thomson = 4.76e6 * (11.5 / 25.4) / (1500 / 25.4) ** 2
    assert thomson == pytest.approx(618.0, abs=0.05)
    axis = {"load_n": 50, "length_mm": 1500, "end_fixity": "fixed-simple"}
    fast = check(evaluate(client, "Tr16x4-bronze", **axis, speed_mm_s=49.3), "critical_speed")
    allowed = 0.8 * 1.47 * thomson
    assert allowed == pytest.approx(726.7, abs=0.05)
    assert allowed < 60 * 49.3 / 4 < 0.8 * (3.92660 / math.pi) ** 2 * n_ss
    assert not fast["passed"]
    assert fast["limit"] == pytest.approx(allowed, rel=1e-6)
    said = "C_s 1.47 (at most Thomson's 4.76e6 d_r / L^2 [rpm, in]) times simple-simple"
    assert said + ", 6.3 % below the beam's" in fast["message"]
    slow = check(evaluate(client, "Tr16x4-bronze", **axis, speed_mm_s=40), "critical_speed")
    assert slow["passed"] and slow["limit"] == pytest.approx(allowed, rel=1e-6)
    assert "C_s 1.47 (at most Thomson's" in slow["message"]
    fixed = {**axis, "end_fixity": "fixed-fixed"}
    both = check(evaluate(client, "Tr16x4-bronze", **fixed, speed_mm_s=74.3), "critical_speed")
    allowed_ff = 0.8 * 2.23 * thomson
    assert allowed_ff < 60 * 74.3 / 4 < 0.8 * (4.73004 / math.pi) ** 2 * n_ss
    assert not both["passed"] and both["limit"] == pytest.approx(allowed_ff, rel=1e-6)
    assert "times simple-simple, 2.0 % below the beam's" in both["message"]
    simple = {**axis, "end_fixity": "simple-simple"}
    plain = check(evaluate(client, "Tr16x4-bronze", **simple, speed_mm_s=20), "critical_speed")
    assert plain["limit"] == pytest.approx(0.8 * thomson, rel=1e-6)
    assert "C_s 1 (at most Thomson's" in plain["message"]
    ball = check(evaluate(client, "R16-10K3-FSCDIN", **axis, speed_mm_s=100), "critical_speed")
    assert ball["passed"] and "leadscrew makers" not in ball["message"]
