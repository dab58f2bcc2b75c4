"""Physics an engineer can stake a design on, through the API: each rule against hand
arithmetic from the reference formulas (engineering.md; Shigley, Mechanical Engineering
Design, 9th ed., sec. 4-11 to 4-13 and 8-2), never against the app's own output."""

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.catalog import Catalog
from tests.api.calls import check, evaluate
from tests.leadscrews import leadscrew_families

G = 9.80665
COS_ACME = math.cos(math.radians(14.5))
API = "/api/v1"


def post(client: TestClient, path: str, body: dict[str, Any]) -> Any:
    params = {"detail": "full"} if path == "select" else {}
    response = client.post(f"{API}/{path}", json=body, params=params)
    assert response.status_code == 200, response.text
    return response.json()


def eta(lead: float, d_p: float, mu: float, cos_a: float = COS_ACME) -> float:
    """Shigley's Acme-form efficiency (engineering.md section 2)."""
    tan_l = lead / (math.pi * d_p)
    return (cos_a - mu * tan_l) / (cos_a + mu / tan_l)


# --- 1. the force that accelerates the moving mass reaches the nut ------------------------


def test_peak_thrust_judges_the_design_load(client: TestClient) -> None:
    """load 5 N, 50 kg at 5 m/s^2: peak thrust 5 + 50 x 5 = 255 N against the 1/4 in design
    load 3 MPa x 3 pi d_p h = 111.6 N (d_p = 0.89 x 6.35 mm, h = 0.11 x 6.35 mm)."""
    c = evaluate(client, "B4000-L2", load_n=5, speed_mm_s=20, length_mm=200,
                 moving_mass_kg=50, accel_mm_s2=5000)  # fmt: skip
    d_p, h = 0.89 * 6.35e-3, 0.11 * 6.35e-3
    design = 3e6 * 3 * math.pi * d_p * h
    assert c["axial_load_n"] == pytest.approx(5.0)
    assert c["peak_axial_load_n"] == pytest.approx(255.0)
    load = check(c, "design_load")
    assert (load["value"], load["limit"]) == (pytest.approx(255.0), pytest.approx(design))
    assert design == pytest.approx(111.6, rel=1e-3) and not load["passed"]
    assert check(c, "buckling")["value"] == pytest.approx(255.0)
    # PV at the peak thrust, n F_peak / (3 h) with F_peak = 255 N, n = 10 rev/s: the
    # accelerating segment reaches the top speed still carrying m a (it read 5 N before)
    assert c["pv"]["value_mpa_m_s"] == pytest.approx(10 * 255.0 / (3 * h) / 1e6)


# --- 2. the inertia torque of the moving mass passes through the thread --------------------


def test_mass_inertia_torque_goes_through_the_efficiency(client: TestClient) -> None:
    """ZBX8000-L10, 20 kg at 5 m/s^2: m a lead / (2 pi eta) = 100 x 0.01 / (2 pi x 0.617)
    = 0.258 N m, where the reflected inertia alone, m a lead / 2 pi, gives 0.159 N m."""
    c = evaluate(client, "ZBX8000-L10", load_n=10, speed_mm_s=50, length_mm=500,
                 moving_mass_kg=20, accel_mm_s2=5000)  # fmt: skip
    e = eta(0.010, (12.7e-3 + 0.78 * 12.7e-3) / 2, 0.15)
    assert e == pytest.approx(0.617, abs=1e-3)
    assert c["torque"]["inertia_mass_nm"] == pytest.approx(20 * 5 * 0.010 / (2 * math.pi * e))
    assert c["torque"]["inertia_mass_nm"] == pytest.approx(0.258, abs=1e-3)


def test_the_rotor_inertia_torque_is_its_own_part_of_the_breakdown(client: TestClient) -> None:
    """ZBX8000-L10 at 5 m/s^2 with a rotor of 82e-7 kg m^2 (a NEMA 23 stepper):
    alpha = 2 pi a / lead = 2 pi x 5 / 0.01 = 3141.6 rad/s^2, J_motor alpha = 0.02576 N m,
    inside the inertia torque and the total."""
    axis = {"load_n": 10, "speed_mm_s": 50, "length_mm": 500, "moving_mass_kg": 20,
            "accel_mm_s2": 5000}  # fmt: skip
    bare = evaluate(client, "ZBX8000-L10", **axis)["torque"]
    c = evaluate(client, "ZBX8000-L10", **axis, motor_inertia_kg_m2=82e-7)["torque"]
    rotor_nm = 82e-7 * 2 * math.pi * 5 / 0.010
    assert rotor_nm == pytest.approx(0.02576, abs=1e-5)
    assert (bare["inertia_motor_nm"], c["inertia_motor_nm"]) == (0.0, pytest.approx(rotor_nm))
    parts = c["inertia_screw_nm"] + c["inertia_mass_nm"] + c["inertia_motor_nm"]
    assert c["inertia_nm"] == pytest.approx(parts, rel=1e-12)
    assert c["total_nm"] - bare["total_nm"] == pytest.approx(rotor_nm, rel=1e-9)


# --- 3. vertical axes: a brake, and self-locking only with a margin -------------------------


def test_a_vertical_lead_8_axis_passes_with_a_brake(client: TestClient) -> None:
    """A Z axis on the seed's screws: 2 kg, lead 8 mm, 20 mm/s. Without a brake none of them
    holds it; with 0.5 N m holding torque they pass, each needing 1.5 x max(seed, physics)
    (a brake's service factor, Machine Design), the physics at the static friction the
    self-locking margin trusts, 0.5 x 0.08."""
    axis = {"load_n": 5, "moving_mass_kg": 2, "orientation": "vertical", "lead_mm": 8,
            "speed_mm_s": 20, "length_mm": 300, "accel_mm_s2": 500,
            "family": ["B", "ZBX", "KHD", "VHD"]}  # fmt: skip
    free = post(client, "select", axis)
    assert free["counts"]["passed"] == 0
    assert free["counts"]["failed_by_check"]["back_driving"] == free["counts"]["evaluated"]
    held = post(client, "select", {**axis, "brake_torque_nm": 0.5})
    assert held["counts"]["passed"] > 0
    c = held["candidates"][0]
    hold = check(c, "holding")
    force = 5 + 2 * G
    lead, d_p = 0.008, c["pitch_diameter_mm"] / 1e3
    tan_l = lead / (math.pi * d_p)
    eta_b = (COS_ACME * tan_l - 0.04) / (tan_l * (COS_ACME + 0.04 * tan_l))
    seed = force * lead * c["efficiency"] / (2 * math.pi)
    physics = force * lead * eta_b / (2 * math.pi)
    assert hold["value"] == pytest.approx(1.5 * max(seed, physics))
    assert hold["limit"] == 0.5 and hold["passed"]


def test_self_locking_needs_a_margin_on_static_friction(client: TestClient) -> None:
    """ZBX8000: the physical limit is pi d_p mu_s / cos a_n = 2.934 mm; a 2.5 mm lead sits at
    0.85 of it, self-locking on paper but not with half the static friction (1.467 mm)."""
    c = evaluate(client, "ZBX8000-L2.5", load_n=50, speed_mm_s=10, length_mm=300,
                 orientation="vertical")  # fmt: skip
    d_p = (12.7 + 0.78 * 12.7) / 2
    assert c["max_self_locking_lead_mm"] == pytest.approx(math.pi * d_p * 0.08 / COS_ACME)
    assert c["max_self_locking_lead_with_margin_mm"] == pytest.approx(
        math.pi * d_p * 0.04 / COS_ACME
    )
    assert c["self_locking"] and not c["self_locking_with_margin"]
    assert not check(c, "back_driving")["passed"]
    # the seed's rule (lead under 12.7 / 8 = 1.59 mm) agrees with the margin here
    assert not c["seed_rule_no_backdrive"]


def test_backdrive_efficiency_is_labelled_by_its_friction(client: TestClient) -> None:
    """Uncoated: static 0.08 below running 0.15, so the back-drive efficiency from rest can
    exceed the forward one; the running back-drive efficiency uses 0.15 and cannot."""
    c = evaluate(client, "ZBX8000-L25", load_n=50, speed_mm_s=10, length_mm=300)
    d_p = (12.7 + 0.78 * 12.7) / 2e3
    tan_l = 0.025 / (math.pi * d_p)

    def eta_b(mu: float) -> float:
        return (COS_ACME * tan_l - mu) / (tan_l * (COS_ACME + mu * tan_l))

    assert c["backdrive_efficiency"] == pytest.approx(eta_b(0.08))
    assert c["backdrive_efficiency_running"] == pytest.approx(eta_b(0.15))
    assert c["backdrive_efficiency"] > c["efficiency"] > c["backdrive_efficiency_running"]


# --- 4. short, heavily loaded columns -----------------------------------------------------


def test_a_short_heavy_column_fails_on_yield(client: TestClient) -> None:
    """Custom 30 mm steel screw, 25 mm root, 200 kN over 100 mm, fixed-simple: 407 MPa at the
    root against 0.5 x 310 MPa; slenderness (0.1 / sqrt 2) / (0.025 / 4) = 11.3, far below
    sqrt(2 pi^2 E / S_y) = 114.5, so Johnson: A (S_y - (S_y s / 2 pi)^2 / E)."""
    screw = {"outer_diameter_mm": 30, "root_diameter_mm": 25, "lead_mm": 6,
             "friction_dynamic": 0.15, "friction_static": 0.2, "material": "steel"}  # fmt: skip
    c = evaluate(client, screw, load_n=200e3, speed_mm_s=10, length_mm=100)
    area = math.pi * 0.025**2 / 4
    s = (0.1 / math.sqrt(2)) / (0.025 / 4)
    johnson = area * (310e6 - (310e6 * s / (2 * math.pi)) ** 2 / 206e9)
    assert c["buckling"]["mode"] == "johnson"
    assert c["buckling"]["slenderness"] == pytest.approx(s)
    assert c["buckling"]["critical_load_n"] == pytest.approx(johnson)
    stress = check(c, "root_stress")
    # von Mises of the axial 200e3 / A = 407.4 MPa and the shear of the torque the screw
    # carries, T = F lead / (2 pi eta) at the lower efficiency (static, mu 0.2) plus the
    # rod's inertia torque rho pi d_p^4 / 32 x L x 2 pi a / lead (a = 1 m/s^2; a rod at the
    # pitch diameter d_p = 27.5 mm): tau = 16 T / (pi d_r^3) (Shigley eqs. 8-7, 8-8, 5-15)
    tan_l = 0.006 / (math.pi * (0.030 + 0.025) / 2)
    eta = (COS_ACME - 0.2 * tan_l) / (COS_ACME + 0.2 / tan_l)
    j_alpha = 7850 * math.pi * 0.0275**4 / 32 * 0.1 * (2 * math.pi * 1.0 / 0.006)
    torque_nm = 200e3 * 0.006 / (2 * math.pi * eta) + j_alpha
    sigma, tau = 200e3 / area, 16 * torque_nm / (math.pi * 0.025**3)
    assert sigma / 1e6 == pytest.approx(407.4, abs=0.1)
    assert stress["value"] == pytest.approx(math.sqrt(sigma**2 + 3 * tau**2) / 1e6, rel=1e-6)
    assert stress["limit"] == pytest.approx(155.0) and not stress["passed"]
    assert not check(c, "buckling")["passed"] and not c["passed"]


# --- 5. inputs an engineer sends ----------------------------------------------------------


def test_constant_speed_and_a_pure_inertia_axis_are_accepted(client: TestClient) -> None:
    body = post(client, "select", {"load_n": 0, "moving_mass_kg": 5, "accel_mm_s2": 0,
                                   "speed_mm_s": 50, "length_mm": 500})  # fmt: skip
    assert body["counts"]["passed"] > 0
    c = body["candidates"][0]
    assert c["torque"]["inertia_nm"] == 0.0 and c["peak_axial_load_n"] == 0.0
    axis = {"load_n": 0, "moving_mass_kg": 5, "accel_mm_s2": 0, "speed_mm_s": 50,
            "length_mm": 500}  # fmt: skip
    seed_nuts = post(client, "select", {**axis, "family": ["B"]})
    # no thrust: no PV speed limit on the seed's nuts
    assert all(c["pv"]["max_speed_mm_s"] is None for c in seed_nuts["candidates"])


def test_a_lead_with_no_screw_names_the_nearest_leads(client: TestClient) -> None:
    body = post(client, "select", {"load_n": 50, "speed_mm_s": 50, "length_mm": 500,
                                   "lead_mm": 7.5})  # fmt: skip
    assert body["counts"]["evaluated"] == 0
    assert "Nearest leads: 7 mm and 8 mm" in body["summary"]["message"]


@pytest.mark.parametrize(
    ("asked", "said"),
    [
        ({"family": ["NOPE"]}, "The catalog has no family 'NOPE': its families are B, "),
        ({"nut_material": "unobtainium"}, "No catalog screw has a nut of 'unobtainium': its "),
    ],
)
def test_a_family_or_nut_the_catalog_lacks_is_named_not_blamed_on_the_lead(
    client: TestClient, catalog: Catalog, asked: dict[str, Any], said: str
) -> None:
    """Nothing eligible because a family or nut material is not in the catalog: the
    summary names it and what the catalog holds (it said to try another lead, with no
    lead given)."""
    body = post(client, "select", {"load_n": 50, "speed_mm_s": 50, "length_mm": 500, **asked})
    message = body["summary"]["message"]
    assert body["counts"]["evaluated"] == 0 and message.startswith(said)
    held = {s.family_id for s in catalog.screws} | {s.nut_material for s in catalog.screws}
    assert all(name in held for name in message.split(" are ")[1].rstrip(".").split(", "))


# --- 6. advice versus limits ----------------------------------------------------------------


def test_traverse_speed_is_advice(client: TestClient) -> None:
    """200 mm/s on a 10 mm lead exceeds the seed's 100 mm/s band: a warning, not a reject,
    unless the user asks to reject on advice."""
    axis = {"load_n": 20, "speed_mm_s": 200, "length_mm": 300, "lead_mm": 10,
            "coating": "none", "family": ["B", "ZBX", "KHD", "VHD"]}  # fmt: skip
    warned = post(client, "select", axis)
    assert warned["counts"]["passed"] > 0
    c = warned["candidates"][0]
    assert [w["name"] for w in c["warnings"]] == ["traverse_speed"]
    assert c["warnings"][0]["kind"] == "advice" and c["passed"]
    assert all(
        [w["name"] for w in c["warnings"]] == ["traverse_speed"] for c in warned["candidates"]
    )
    strict = post(client, "select", {**axis, "advice": "reject"})
    assert strict["counts"]["passed"] == 0  # every 10 mm lead runs above its 100 mm/s band


# --- 7. honest nearest and feasible fixes -------------------------------------------------


def test_fixes_stay_within_the_catalog(client: TestClient, catalog: Catalog) -> None:
    """A long, fast axis: the lead that would clear critical speed is beyond the catalog's
    largest (60 mm), so no fix offers it; an anti-backlash screw is never told to become one."""
    axis = {"load_n": 3000, "speed_mm_s": 500, "length_mm": 3000,
            "positioning_tolerance_mm": 0.01, "stroke_mm": 1000}  # fmt: skip
    body = post(client, "select", axis)
    largest_lead_mm = max(s.lead_m for s in catalog.screws) * 1e3
    for c in body["rejected"]:
        for k in c["checks"]:
            fix = k["fix"] or ""
            if "lead of at least" in fix:
                wanted = float(fix.split("lead of at least ")[1].split(" mm")[0])
                assert wanted <= largest_lead_mm, fix
            if c["anti_backlash"]:
                assert "anti-backlash" not in fix, fix
    rejected = [(len([k for k in c["checks"] if not k["passed"] and k["kind"] == "limit"]))
                for c in body["rejected"]]  # fmt: skip
    assert rejected == sorted(rejected)


def test_nothing_passes_lists_feasible_changes_as_data(
    client: TestClient, catalog: Catalog
) -> None:
    """3000 N at 500 mm/s over 3 m: no leadscrew takes it (a ball screw does: the
    leadscrews by name); each offered change admits its screw."""
    lead = leadscrew_families(catalog)
    axis = {"load_n": 3000, "speed_mm_s": 500, "length_mm": 3000, "family": list(lead)}
    body = post(client, "select", axis)
    assert body["counts"]["passed"] == 0
    changes = body["summary"]["changes"]
    assert changes
    for change in changes:
        again = post(client, "evaluate", {
            "application": {**axis, **change["inputs"]},
            "screw": {"catalog_id": change["admits"]},
        })["candidate"]  # fmt: skip
        assert again["passed"], change


# --- 8. what a pass rests on ----------------------------------------------------------------


def test_governing_limit_provenance(client: TestClient) -> None:
    """PV governs a light slow axis on a plastic nut; its limit is an assumed value, while a
    torque limit is the user's own."""
    c = evaluate(client, "B8000-L10", load_n=100, speed_mm_s=50, length_mm=500)
    assert c["governing_check"] == "pv" and c["governing_limit_provenance"] == "assumed"
    t = evaluate(client, "B8000-L10", load_n=100, speed_mm_s=5, length_mm=500,
                 max_torque_nm=0.05)  # fmt: skip
    assert t["governing_check"] == "torque" and t["governing_limit_provenance"] == "user"


def test_a_family_the_catalog_lacks_beside_one_it_has_is_named_too(client: TestClient) -> None:
    """family B and NOPE: B's screws are selected, and the summary says NOPE is none of
    the catalog's (it was left out without a word)."""
    body = post(client, "select", {"load_n": 50, "speed_mm_s": 50, "length_mm": 500,
                                   "family": ["B", "NOPE"]})  # fmt: skip
    alone = post(client, "select", {"load_n": 50, "speed_mm_s": 50, "length_mm": 500,
                                    "family": ["B"]})  # fmt: skip
    assert body["counts"] == alone["counts"] and body["counts"]["evaluated"] > 0
    assert body["summary"]["message"].startswith("The catalog has no family 'NOPE'")
    assert "no family" not in alone["summary"]["message"]


def test_a_check_that_could_not_run_names_only_what_stops_it(client: TestClient) -> None:
    """The accuracy check runs on the terms a screw has: a missing repeatability counts
    as none. An ISO Tr screw has its play but no lead accuracy: the check runs without
    the lead error and names the lead accuracy alone as left out (it named the
    repeatability too, and once skipped the check, though the nut's play of up to
    0.3 mm alone exceeds the 0.03 mm tolerance); the nut's friction heat grows the screw
    on top."""
    c = evaluate(client, "Tr12x3-bronze", load_n=50, speed_mm_s=20, length_mm=300,
                 stroke_mm=200, positioning_tolerance_mm=0.03)  # fmt: skip
    assert "accuracy" not in {s["check"] for s in c["verdict"]["skipped"]}
    partial = {p["check"]: p["missing"] for p in c["verdict"]["partial"]}
    assert partial["accuracy"] == ["lead accuracy"]
    accuracy = next(k for k in c["checks"] if k["name"] == "accuracy")
    heated_mm = c["accuracy"]["heat_growth_mm"]
    assert accuracy["value"] == pytest.approx(0.3 + heated_mm) and not accuracy["passed"]
