"""Ball screws rated no better than their maker, HIWIN GmbH, Ballscrews & Accessories,
BS-08-2-EN-1704-K, rates them (the families under catalog/hiwin/)."""

import math

import pytest
from fastapi.testclient import TestClient

#: the ball nut's load factor f_w by default: the top of HIWIN's 1.1 to 1.2 without impact
F_W = 1.2


def _check(client: TestClient, name: str, **params: object) -> dict:  # type: ignore[type-arg]
    r = client.get("/api/v1/evaluate", params=params)
    assert r.status_code == 200, r.text
    candidate = r.json()["candidate"]
    return next(c for c in candidate["checks"] if c["name"] == name) | {"screw": candidate}


def test_a_fixed_free_ball_screw_whirls_where_hiwin_says(client: TestClient) -> None:
    """R20-05K4-FSC, 1000 mm, fixed-free, at 48 mm/s (576 rpm). HIWIN F 3.27: n_k =
    2.71e8 x 0.147 x d_k / l_s^2, at most 0.8 n_k: 552 rpm for its 17.32 mm root, so
    576 rpm fails. The beam alone allowed 599 rpm, a pass."""
    check = _check(
        client,
        "critical_speed",
        catalog_id="R20-05K4-FSC",
        load_n=1000,
        speed_mm_s=48,
        length_mm=1000,
        end_fixity="fixed-free",
    )
    d_k = check["screw"]["root_diameter_mm"]
    hiwin = 0.8 * 2.71e8 * 0.147 * d_k / 1000.0**2
    assert check["value"] == 576.0
    assert check["limit"] == pytest.approx(hiwin, rel=1e-9)
    assert not check["passed"]
    assert "HIWIN rates it (F 3.27, its mounting factor for these ends)" in check["message"]


def test_a_ball_screws_critical_speed_is_hiwins_where_the_beam_is_higher(
    client: TestClient,
) -> None:
    """R16-10K3-FSCDIN over 600 mm, fixed-simple: HIWIN F 3.27 gives 2.71e8 x 0.692 x
    12.5 / 600^2 = 6511.6 rpm for its 12.5 mm root; the beam with the catalog's steel
    (E 207 GPa, 7800 kg/m^3) 6584 rpm. Scaled by HIWIN's mounting factor over the beam's
    (0.9932) it read 6539 rpm, 0.4 % above the maker's own figure; now HIWIN's, the lower."""
    check = _check(
        client, "critical_speed", catalog_id="R16-10K3-FSCDIN", load_n=100, speed_mm_s=200,
        length_mm=600, end_fixity="fixed-simple",
    )  # fmt: skip
    hiwin = 2.71e8 * 0.692 * 12.5 / 600.0**2
    assert check["limit"] == pytest.approx(0.8 * hiwin, rel=1e-9)
    assert "critical 6512 rpm" in check["message"]


def test_a_fast_lead_ball_screw_drives_at_most_at_hiwins_efficiency(client: TestClient) -> None:
    """R25-25K2-FSCDIN, an 18.8 degree lead angle: the thread's efficiency at the ball
    track's friction (HIWIN Fig. 2.1, mu 0.01) is 0.968, above the 0.85 to 0.95 HIWIN F
    3.15 gives for the drive torque T_a = F P / (2000 pi eta_1). At most 0.95: 500 N on
    the 25 mm lead needs 500 x 0.025 / (2 pi 0.95) = 2.094 N m (1.8 % more than at 0.968)."""
    r = client.get(
        "/api/v1/evaluate",
        params={"catalog_id": "R25-25K2-FSCDIN", "load_n": 500, "speed_mm_s": 50, "length_mm": 800},
    )
    assert r.status_code == 200, r.text
    screw = r.json()["candidate"]
    assert screw["efficiency"] == 0.95
    assert screw["torque"]["load_nm"] == pytest.approx(500 * 0.025 / (2 * math.pi * 0.95), rel=1e-6)


def test_a_ball_nut_run_past_its_dynamic_rating_is_flagged_without_a_duty(
    client: TestClient,
) -> None:
    """55 kN on R40-10K4-FSCDIN (HIWIN Table 4.4: Ca 45 kN, C0a 123 kN), with no life
    asked: the static check passes (2 x 55 kN < 123 kN), but the nut runs at 1.22 Ca,
    where its L10 at the default load factor 1.2 is (45 / (1.2 x 55))^3 x 10^6 revolutions
    x 10 mm = 3.170 km of travel (it was given at load factor 1, beside the life section's
    at the user's). HIWIN Table 3.1 recommends a mean load of at most Ca / 5 = 9 kN: the
    advice fails and says so; nothing compared the load with Ca before."""
    check = _check(
        client,
        "ball_load",
        catalog_id="R40-10K4-FSCDIN",
        load_n=55000,
        speed_mm_s=20,
        length_mm=600,
        end_fixity="fixed-fixed",
    )
    assert (check["value"], check["limit"]) == (55000.0, 45000.0 / 5)
    assert not check["passed"] and check["kind"] == "advice"
    km = (45.0 / (F_W * 55.0)) ** 3 * 1e6 * 0.010 / 1e3
    assert f"{km:.4g} km of travel (L10 at the load factor 1.2" in check["message"]
    assert "Mean load (ball screw)" in check["screw"]["verdict"]["text"]


def test_a_preloaded_nut_carries_its_preload_in_the_mean_load(client: TestClient) -> None:
    """R20-20K2-FSC (Ca 7.6 kN, preload 5 % of Ca, 380 N) over 500 mm strokes: the mean
    load is the cubic mean of each segment's thrust raised by the preload (HIWIN F 3.7),
    the L10 check's 497.9 N, against 7.6 kN / 5 = 1.52 kN: within."""
    params = {
        "catalog_id": "R20-20K2-FSC",
        "load_n": 200,
        "moving_mass_kg": 30,
        "speed_mm_s": 1000,
        "accel_mm_s2": 5000,
        "length_mm": 700,
        "stroke_mm": 500,
        "cycles_per_day": 2000,
        "required_life_years": 5,
    }
    check = _check(client, "ball_load", **params)
    assert check["value"] == pytest.approx(497.92, abs=0.01)
    assert check["limit"] == pytest.approx(1520.0) and check["passed"]


def test_the_mean_load_advice_names_a_preloaded_nuts_two_sided_life(client: TestClient) -> None:
    """R20-20K2-FSC (Ca 7,600 N, preload 380 N: F_lim = 2^1.5 x 380 = 1,074.8 N) under a
    running 200 N, no stroke: the pressed side carries (1 + 200 / 1074.8)^1.5 x 380 =
    490.86 N (HIWIN F 3.7), the other 490.86 - 200 = 290.86 N. Both sides roll under load
    (HIWIN sec. 3.7.2 d): L = ((490.86 / 7600)^(10/3) + (290.86 / 7600)^(10/3))^(-0.9) x
    10^6 revolutions, at the default load factor 1.2 (1.2^3 shorter than at 1), times the
    20 mm lead; the pressed side alone rated (7600 / 490.86)^3 x 10^6, 1.16 times
    longer, which the advice named before."""
    check = _check(
        client, "ball_load", catalog_id="R20-20K2-FSC", load_n=200, speed_mm_s=50, length_mm=700
    )
    limit = 2**1.5 * 380.0
    pressed = (1 + 200.0 / limit) ** 1.5 * 380.0
    other = pressed - 200.0
    both = ((pressed / 7600) ** (10 / 3) + (other / 7600) ** (10 / 3)) ** -0.9 * 1e6
    one_sided = (7600 / pressed) ** 3 * 1e6
    assert check["value"] == pytest.approx(pressed, rel=1e-4)
    km = float(f"{both / F_W**3 * 0.020 / 1e3:.4g}")  # the message's four figures
    assert f"{km:,.0f} km of travel" in check["message"] and km == 37_160
    assert one_sided / both == pytest.approx(1.156, abs=0.001)


def test_the_ball_nuts_static_safety_factor_is_an_input(client: TestClient) -> None:
    """55 kN on R40-10K4-FSCDIN (C0a 123 kN): at THK's f_s = 2 without vibration or impact
    the nut holds 2 x 55 = 110 kN; an axis with shocks asks more, and at 2.5 it needs
    137.5 kN, above C0a: a failure that the fixed factor could not show."""
    axis = {"catalog_id": "R40-10K4-FSCDIN", "load_n": 55000, "speed_mm_s": 20}
    axis |= {"length_mm": 600, "end_fixity": "fixed-fixed"}
    default = _check(client, "ball_static", **axis)
    assert default["value"] == 110_000.0 and default["passed"]
    shocks = _check(client, "ball_static", **axis, ball_static_safety_factor=2.5)
    assert (shocks["value"], shocks["limit"]) == (137_500.0, 123_000.0)
    assert not shocks["passed"]
    assert "at most 46,740 N" in shocks["fix"]  # 123 kN / 2.5, less the 5 % margin


def test_a_vanishing_load_gives_the_mean_load_advice_without_a_life(client: TestClient) -> None:
    """6.5e-211 N (a schema-fuzz request): the life (Ca / F)^3 overflows a float; the
    advice passes and names no life, and nothing fails with a 500."""
    axis = {"catalog_id": "R16-05T3-FSIDIN", "load_n": 6.462e-211, "speed_mm_s": 50}
    check = _check(client, "ball_load", **axis, length_mm=400)
    assert check["passed"] and "rated life" not in check["message"]


def test_a_preloaded_nut_wears_out_under_no_thrust_and_a_nut_with_play_does_not(
    client: TestClient,
) -> None:
    """No load, no mass: only the preload loads the balls. R16-16K2-FSC (Ca 6800 N,
    preload 5 % of Ca, 340 N on each side): L1 = L2 = (6800 / (1.2 x 340))^3 x 10^6 rev,
    combined L = 2^(-9/10) L1 (HIWIN sec. 3.7.2 d)), over 800 mm of travel a cycle at a
    16 mm lead and 5,000 cycles a day: 27.19 years, short of 40. The check did not run
    without thrust, and the screw passed. R16-16K3-FSCDIN, a nut with play, has no load
    on its balls: it passes with no life worked out."""
    axis = {"load_n": 0, "speed_mm_s": 200, "length_mm": 600, "stroke_mm": 400,
            "cycles_per_day": 5000, "required_life_years": 40}  # fmt: skip
    one_side = (6800 / (1.2 * 340)) ** 3 * 1e6
    revolutions = 2 ** (-0.9) * one_side
    years = revolutions / (0.8 / 0.016 * 5000 * 365)
    assert years == pytest.approx(27.19, abs=0.01)
    preloaded = _check(client, "ball_life", catalog_id="R16-16K2-FSC", **axis)
    assert preloaded["limit"] == pytest.approx(years, rel=1e-6)
    assert not preloaded["passed"] and not preloaded["screw"]["passed"]
    play = _check(client, "ball_life", catalog_id="R16-16K3-FSCDIN", **axis)
    assert play["passed"] and play["utilization"] == 0.0 and play["limit"] is None
    assert "no fatigue" in play["message"] and "inf" not in play["message"]


def test_a_short_stroke_carries_the_whole_first_band_of_its_class(client: TestClient) -> None:
    """R12-05K4-FSCDIN, rolled T7, over a 100 mm stroke against 0.05 mm: HIWIN Table 3.3
    v300p = 52 um is the variation allowed within any 300 mm, not a rate, so the 100 mm
    carry all of it (ISO 3408-3 transport rule, at least v300p; Steinmeyer's rolled T7,
    52 um up to 315 mm), with the nut's 0.02 mm play (Table 4.4): 0.072 mm, a fail. Taken
    as 52 x 100 / 300 = 17.3 um it passed at 0.0373 mm."""
    check = _check(
        client,
        "accuracy",
        catalog_id="R12-05K4-FSCDIN",
        load_n=200,
        speed_mm_s=100,
        length_mm=300,
        stroke_mm=100,
        positioning_tolerance_mm=0.05,
    )
    assert check["screw"]["accuracy"]["lead_error_mm"] == pytest.approx(0.052)
    assert check["value"] == pytest.approx(0.052 + 0.02)
    assert not check["passed"]


@pytest.mark.parametrize(
    ("catalog_id", "stroke_mm", "lead_error_mm"),
    [
        # ISO 3408-3 transport rule, 2 x (600 / 300) x 52 um (HIWIN Table 3.3 v300p)
        pytest.param("R16-05T3-FSIDIN", 600, 2 * 600 / 300 * 0.052, id="rolled-T7-600mm"),
        # HIWIN Table 3.4, T3: 12 um up to 315 mm, 21 um for 800-1000 mm
        pytest.param("R16-16K2-FSC", 100, 0.012, id="ground-T3-100mm"),
        pytest.param("R16-16K2-FSC", 900, 0.021, id="ground-T3-900mm"),
    ],
)
def test_the_lead_error_is_the_limit_deviation_of_the_class(
    client: TestClient, catalog_id: str, stroke_mm: float, lead_error_mm: float
) -> None:
    """The limit deviation e_p of the screw's ISO 3408-3 class over the stroke (HIWIN
    BS-08-2-EN-1704-K sec. 3.5.3): 0.208, 0.012 and 0.021 mm, where the stroke share of
    v300p gave 0.104, 0.004 and 0.036 mm."""
    check = _check(
        client,
        "accuracy",
        catalog_id=catalog_id,
        load_n=100,
        speed_mm_s=100,
        length_mm=stroke_mm + 200,
        stroke_mm=stroke_mm,
        positioning_tolerance_mm=1.0,
    )
    assert check["screw"]["accuracy"]["lead_error_mm"] == pytest.approx(lead_error_mm)


def test_with_a_stroke_the_mean_load_advice_leaves_the_life_to_the_life_section(
    client: TestClient,
) -> None:
    """With a stroke and a duty the life section gives the L10 life over the cycle at the
    load factor typed (2 here); the mean-load advice no longer gives a second one (it gave
    1,762 km at load factor 1 beside the life section's 220 km)."""
    axis = {"catalog_id": "R10-02.5T2-RSIT", "load_n": 200, "speed_mm_s": 20,
            "length_mm": 400, "stroke_mm": 300, "cycles_per_day": 1000,
            "ball_load_factor": 2}  # fmt: skip
    check = _check(client, "ball_load", **axis)
    assert "km of travel" not in check["message"]
    assert check["screw"]["life"]["travel_km"][0] > 0
