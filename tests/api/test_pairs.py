"""Screw + motor pairs over the whole library (GET/POST /api/v1/pairs, and the page with
the motor "any"): the screws screened once without a motor, then each motor over the
screws that pass; the same answer as selecting with each motor in turn, ranked by the
number shown."""

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.catalog.axis_motor import CURVE_ORIGINS, pair_applications
from app.catalog.motors import MAX_STEPPER_RPM
from app.contract.inputs import ApplicationIn
from app.core.formulas import stepper
from tests.motor_library import MOTORS

#: A light axis at constant speed (no move given: the top speed is held), every screw.
AXIS = {"load_n": 20.0, "speed_mm_s": 50.0, "length_mm": 350.0, "limit": 100}


def _pairs(client: TestClient, **extra: object) -> dict:  # type: ignore[type-arg]
    r = client.get("/api/v1/pairs", params={**AXIS, **extra})
    assert r.status_code == 200, r.text
    return r.json()  # type: ignore[no-any-return]


def test_the_pairs_are_the_selections_with_each_motor(client: TestClient) -> None:
    """Screening once and pairing the survivors gives exactly what selecting with each
    library motor in turn gives: as many passing pairs as the selections pass in all."""
    body = _pairs(client)
    motors = [m["id"] for m in client.get("/api/v1/motors").json()["motors"]]
    assert body["motors"] == len(motors) == len(MOTORS)
    passed = 0
    for motor in motors:
        r = client.get("/api/v1/select", params={**AXIS, "motor": motor, "limit": 1})
        passed += r.json()["counts"]["passed"]
    assert body["pairs_passed"] == passed


def test_a_motor_that_holds_the_load_pairs_with_screws_that_cannot_alone(
    client: TestClient,
) -> None:
    """A 1 kg vertical axis held by the energised motor, and with the power off: without
    a motor only the self-locking screws hold, but a stepper's detent torque holds a
    back-driving screw too (B4000-L8-TFE needs 0.0111 N m, SY42STH47-1684B's detent gives
    more). The pairs are still every selection with each motor."""
    held = {
        "load_n": 0, "moving_mass_kg": 1.0, "orientation": "vertical", "speed_mm_s": 12,
        "accel_mm_s2": 200, "length_mm": 350, "stroke_mm": 200, "lead_mm": 8,
        "hold_power_off": "true", "holding_source": "energised", "limit": 100,
    }  # fmt: skip
    body = client.get("/api/v1/pairs", params=held).json()
    passed = 0
    for motor in (m["id"] for m in client.get("/api/v1/motors").json()["motors"]):
        r = client.get("/api/v1/select", params={**held, "motor": motor, "limit": 1})
        passed += r.json()["counts"]["passed"]
    assert body["pairs_passed"] == passed > 0
    assert ("B4000-L8-TFE", "sy42sth47-1684b") in {
        (p["screw_id"], p["motor"]) for p in body["pairs"]
    }
    assert body["screws_passing_alone"] < len({p["screw_id"] for p in body["pairs"]})


def test_a_pair_shows_the_selection_s_motor_use(client: TestClient) -> None:
    """The first pair's motor use is the select endpoint's for that screw and motor."""
    first = _pairs(client)["pairs"][0]
    r = client.get("/api/v1/select", params={**AXIS, "motor": first["motor"]})
    candidate = next(c for c in r.json()["candidates"] if c["id"] == first["screw_id"])
    assert first["motor_use"] == pytest.approx(candidate["motor_use"])


def test_a_pair_s_torque_is_the_evaluated_peak_torque(client: TestClient) -> None:
    """Each pair's torque is the peak torque the results table and /evaluate give that
    screw with that motor named: on a 2 kg vertical axis with a 200 mm stroke the
    self-locking Tr8x1.5-bronze, oiled, starts from rest at 0.02332 N m with the Pololu #1205,
    above its 0.02041 N m while accelerating, which the pairs showed and ranked by."""
    axis = {
        "load_n": 5, "moving_mass_kg": 2, "orientation": "vertical", "speed_mm_s": 20,
        "accel_mm_s2": 300, "length_mm": 300, "stroke_mm": 200, "cycles_per_day": 500,
        "lubrication": "oiled",
    }  # fmt: skip
    r = client.get("/api/v1/pairs", params={**axis, "limit": 20})
    assert r.status_code == 200, r.text
    pairs = r.json()["pairs"]
    assert ("Tr8x1.5-bronze", "pololu-1205") in {(p["screw_id"], p["motor"]) for p in pairs}
    for pair in pairs:
        query = {**axis, "catalog_id": pair["screw_id"], "motor": pair["motor"]}
        candidate = client.get("/api/v1/evaluate", params=query).json()["candidate"]
        assert candidate["passed"]
        assert pair["torque_nm"] == pytest.approx(candidate["torque"]["peak_motor_nm"])


def test_a_servo_pair_s_motor_use_by_hand(client: TestClient) -> None:
    """Pittman 14201S003 at n rpm: its peak envelope gives 0.44 x (1 - n / 4230) N m and
    it is drawn to 3547 rpm, so a pair's motor use is max(T / (0.44 (1 - n / 4230)),
    n / 3547) (no stroke: no RMS check; no torque limit given)."""
    found = _pairs(client, lead_mm=2.0)["pairs"]
    pairs = [p for p in found if p["motor"] == "pittman-14201s003"]
    assert pairs
    for p in pairs:
        n, torque = p["peak_rpm"], p["torque_nm"]
        by_hand = max(torque / (0.44 * (1 - n / 4230.0)), n / 3547.0)
        assert p["motor_use"] == pytest.approx(by_hand, rel=2e-4)


def test_an_ac_servo_pair_s_motor_use_by_hand(client: TestClient) -> None:
    """Yaskawa SGM7J-01A: at 50 mm/s every lead of 1 mm or more turns at most 3000 rpm,
    the rated speed, where the peak envelope is still the whole 1.11 N m; the top speed is
    6000 rpm. So a pair's motor use is max(T / 1.11, n / 6000) (no stroke: no RMS check);
    on a 2 mm lead n = 50 / 2 x 60 = 1500 rpm, a share of at least 0.25."""
    found = _pairs(client, lead_mm=2.0)["pairs"]
    pairs = [p for p in found if p["motor"] == "yaskawa-sgm7j-01a"]
    assert pairs
    for p in pairs:
        assert p["peak_rpm"] == pytest.approx(1500.0)
        by_hand = max(p["torque_nm"] / 1.11, p["peak_rpm"] / 6000.0)
        assert p["motor_use"] == pytest.approx(by_hand, rel=1e-6)
        assert p["motor_use"] >= 0.25


@pytest.mark.parametrize(
    ("rank", "field"),
    [("motor_margin", "motor_use"), ("motor_size", "motor_size_nm"), ("torque", "torque_nm")],
)
def test_the_pairs_rank_by_the_number_they_show(client: TestClient, rank: str, field: str) -> None:
    body = _pairs(client, pair_rank=rank)
    values = [p[field] for p in body["pairs"]]
    assert values == sorted(values)
    assert [p["ranked_value"] for p in body["pairs"]] == values
    assert body["rank"] == rank and body["ranked_by"]


def test_the_smallest_motor_ranks_first_by_size(client: TestClient) -> None:
    """The SS2421-5041 holds 0.083 N m, the least of the library (the NEMA 11 0.0932):
    ranked by motor size (its curve at standstill, the microstepping pull-out
    0.083 / sqrt 2 = 0.0587 N m), its pairs come first."""
    first = _pairs(client, pair_rank="motor_size")["pairs"][0]
    assert first["motor"] == "ss2421-5041"
    assert first["motor_size_nm"] == pytest.approx(0.083 / 2**0.5)


def test_post_and_get_agree_and_a_typed_motor_is_set_aside(client: TestClient) -> None:
    got = _pairs(client, motor="pololu-1205")
    r = client.post("/api/v1/pairs", json={**AXIS, "motor": "pololu-1205"})
    assert r.status_code == 200
    assert r.json()["pairs"] == got["pairs"]
    assert got["motors"] == len(MOTORS)


def test_the_pairs_run_the_steppers_on_the_drive_voltage_typed_in(client: TestClient) -> None:
    """On a 5 V drive the steppers are paired at 5 V: the 17HS19-2004S1's curve is the
    model's at 5 V (its library 24 V curve would overstate it), and the two steppers whose
    rated current 5 V cannot push through their winding are left out: the SS2422-5041
    (1.0 A x 5.4 ohm = 5.4 V) and the QSH4218-51-10-049 (1.0 A x 5.0 ohm = 5.0 V)."""
    inputs = ApplicationIn.model_validate({**AXIS, "motor_supply_v": 5.0})
    alone, driven = pair_applications(inputs.axis(), MOTORS)
    assert alone.motor_supply_v is None and not alone.motor_curve
    assert set(MOTORS) - set(driven) == {"ss2422-5041", "qsh4218-51-10-049"}
    at_5 = driven["17hs19-2004s1"].motor_curve
    model = stepper.microstep_pull_out_curve((5.0, 2.0, 1.4, 3e-3, 1.8, 0.59), MAX_STEPPER_RPM)
    assert at_5 == model != MOTORS["17hs19-2004s1"].curve()
    servos = [mid for mid, m in MOTORS.items() if m.kind == "servo"]
    assert servos and all(driven[mid].motor_curve == MOTORS[mid].curve() for mid in servos)
    body = _pairs(client, motor_supply_v=5.0)
    assert body["motors"] == len(MOTORS) - 2
    assert {p["motor"] for p in body["pairs"]} <= set(driven)


def test_each_pair_says_where_its_motor_curve_comes_from(client: TestClient) -> None:
    """A pair of a library stepper with its maker's curve (the 23HS32-4004S's at 48 V,
    the Songyang and Trinamic ones at 24 V) reads that curve on its chart's drive; on a
    36 V drive, the chart of none, the model draws every stepper's. A servo's is the
    servo model's."""

    def origins(**extra: object) -> dict[str, str]:
        return {p["motor"]: p["motor_curve_origin"] for p in _pairs(client, **extra)["pairs"]}

    published = {mid for mid, m in MOTORS.items() if m.published_curve()}
    by_motor = origins()
    assert published & set(by_motor) and set(by_motor) - published
    assert by_motor == {mid: "published" if mid in published else "model" for mid in by_motor}
    assert set(origins(motor_supply_v=36.0).values()) == {"model"}


def test_a_bad_rank_is_a_field_level_422(client: TestClient) -> None:
    r = client.get("/api/v1/pairs", params={**AXIS, "pair_rank": "cheapest"})
    assert r.status_code == 422
    assert r.json()["detail"][0]["field"] == "pair_rank"


def test_the_library_lists_every_value_with_provenance(client: TestClient) -> None:
    motors = client.get("/api/v1/motors").json()["motors"]
    servo = next(m for m in motors if m["id"] == "pittman-14204s004")
    assert servo["kind"] == "servo" and servo["continuous_torque_nm"] == pytest.approx(0.18)
    # Ametek Pittman 14204S004 data sheet: 2.6E-05 kg m2 = 260 g cm2 (1 g cm2 = 1e-7 kg m2)
    assert servo["values"]["rotor_inertia_g_cm2"]["value"] == pytest.approx(260.0)
    assert servo["values"]["rotor_inertia_g_cm2"]["unit"] == "g cm²"
    assert servo["curve"] == [[0.0, 1.4], [3226.0, 0.18]]
    for motor in motors:
        for value in motor["values"].values():
            assert value["provenance"]["kind"] in ("vendor", "derived", "assumed")


def test_the_page_ranks_pairs_with_the_motor_any(client: TestClient) -> None:
    """The form with "any" as the motor shows the pairs table under the results, ranked
    by the share of the motor used when the page ranks by the motor's margin."""
    params = {"load": "20", "speed": "50", "length": "350", "motor": "any"}
    r = client.get("/", params={**params, "rank_by": "motor_margin"})
    assert r.status_code == 200
    page = BeautifulSoup(r.text, "html.parser")
    rows = page.select("table.pairs tr.pair")
    assert len(rows) == 10
    used = [float(cell.text.strip(" %")) for cell in page.select("table.pairs .motor-use")]
    assert used == sorted(used)
    (caption,) = page.select("table.pairs caption")
    assert "share of the motor used" in caption.text
    # each pair names the curve it was judged on, as the API's motor_curve_origin
    api = _pairs(client, rank_by="motor_margin")["pairs"][:10]
    words = [tag.text for tag in page.select("table.pairs tr.pair .curve-origin")]
    assert words == [f"curve: {CURVE_ORIGINS[p['motor_curve_origin']]}" for p in api]
    without = BeautifulSoup(client.get("/", params=params | {"motor": ""}).text, "html.parser")
    assert without.select("table.pairs") == []


def test_a_controller_step_rate_limits_the_stepper_pairs_alone(client: TestClient) -> None:
    """A 5 kHz controller at 16 microsteps allows 5000 x 60 / 3200 = 93.75 rpm: at
    50 mm/s only leads of 50 / 93.75 x 60 = 32 mm and up keep a stepper in step, so
    stepper pairs are lost; a servo has no step rate, so its selection is the same. Without
    a motor the limit has no step angle to work with: a 422 that names "any"."""
    limit = {"max_step_rate_hz": 5000.0, "microsteps": 16}
    bare = client.get("/api/v1/pairs", params={**AXIS, **limit})
    assert bare.status_code == 422
    assert '"any"' in bare.json()["detail"][0]["message"]
    free, limited = _pairs(client), _pairs(client, motor="any", **limit)
    assert 0 < limited["pairs_passed"] < free["pairs_passed"]
    servo = {**AXIS, "motor": "yaskawa-sgm7j-01a"}
    counts = [
        client.get("/api/v1/select", params=params).json()["counts"]["passed"]
        for params in (servo, {**servo, **limit})
    ]
    assert counts[0] == counts[1] > 0
    stepper = {**AXIS, "motor": "17hs19-2004s1", **limit}
    kept = client.get("/api/v1/select", params=stepper).json()["candidates"]
    assert kept and all(c["lead_mm"] >= 32.0 for c in kept)


def test_an_unknown_motor_is_refused_as_a_selection_refuses_it(client: TestClient) -> None:
    """Pairs set a motor given aside, but an id the library lacks is a typing slip that
    select and the page refuse: so do the pairs, on the same field."""
    for route in ("pairs", "select"):
        r = client.get(f"/api/v1/{route}", params={**AXIS, "motor": "foo"})
        assert r.status_code == 422, r.text
        assert r.json()["detail"][0]["field"] == "motor"
        assert "unknown motor 'foo'" in r.json()["detail"][0]["message"]


def test_each_pair_names_the_motor_limit_its_share_is(client: TestClient) -> None:
    """A 2.5 kg vertical axis at 25 mm/s on R08-02.5T2-RSIT (lead 2.5 mm): the screw turns
    25 / 2.5 x 60 = 600 rpm. With SY35ST36-1004A, whose library curve ends at 750 rpm,
    the speed uses 600 / 750 = 80 % of the motor, more than its torque uses: the pair's
    share is its speed limit, and it says so; every pair names the check its share is."""
    body = _pairs(
        client, load_n=0.0, speed_mm_s=25.0, length_mm=300.0, moving_mass_kg=2.5,
        orientation="vertical", accel_mm_s2=500.0, stroke_mm=200.0, dwell_s=0.5,
        holding_source="energised", limit=100,
    )  # fmt: skip
    pairs = {(p["screw_id"], p["motor"]): p for p in body["pairs"]}
    pair = pairs[("R08-02.5T2-RSIT", "sy35st36-1004a")]
    assert pair["motor_use"] == pytest.approx(600.0 / 750.0, rel=1e-9)
    assert pair["motor_limit"] == "motor_speed"
    checks = {c["name"] for c in client.get("/api/v1/checks").json()["checks"]}
    assert all(p["motor_limit"] in checks for p in body["pairs"])


def test_a_library_support_unit_limits_the_pairs_as_it_limits_evaluate(
    client: TestClient,
) -> None:
    """A library support unit's axial ratings judge every pair, as they judge the same
    screw and motor on /evaluate and /select: a 1000 N push on a THK FK6 (static rating
    1760 N over the factor 2: 880 N allowed) passes no screw; the pairs listed 14."""
    axis = {
        "load_n": 1000, "moving_mass_kg": 2, "speed_mm_s": 20, "length_mm": 300,
        "accel_mm_s2": 500, "stroke_mm": 200, "support_id": "thk-fk6", "limit": 100,
    }  # fmt: skip
    assert _pairs(client, **axis)["pairs_passed"] == 0
    without = {k: v for k, v in axis.items() if k != "support_id"}
    pairs = _pairs(client, **without)["pairs"]
    assert pairs
    for pair in pairs[:3]:
        r = client.post(
            "/api/v1/evaluate",
            json={"application": {**axis, "motor": pair["motor"]},
                  "screw": {"catalog_id": pair["screw_id"]}},
        )  # fmt: skip
        assert r.json()["candidate"]["passed"] is False
