"""A bronze nut's ratings are a lubricated nut's: run dry, it is flagged (advice), and its
numbers are worked at its dry friction."""

import math

import pytest
from fastapi.testclient import TestClient

AXIS = {"load_n": 500, "speed_mm_s": 20, "length_mm": 500}


def _evaluate(client: TestClient, **params: object) -> dict:  # type: ignore[type-arg]
    r = client.get("/api/v1/evaluate", params={**AXIS, **params})
    assert r.status_code == 200, r.text
    return r.json()["candidate"]  # type: ignore[no-any-return]


def test_a_bronze_nut_run_dry_is_flagged_and_greased_it_is_not(client: TestClient) -> None:
    """Tr20x4 bronze: its friction 0.13 is Shigley Table 8-5's steel on bronze with
    machine oil (0.10-0.16); dry the table gives 0.15-0.23, and its pressures (Table 8-4)
    are lubricated screws'. With the nut left dry (the default) its numbers are at the dry
    friction and the advice fails with a warning; greased or oiled, it does not run."""
    dry = _evaluate(client, catalog_id="Tr20x4-bronze")
    (check,) = [c for c in dry["checks"] if c["name"] == "lubrication"]
    assert not check["passed"] and check["kind"] == "advice"
    assert "0.15 to 0.23" in check["message"] and "Grease or oil" in check["fix"]
    assert dry["passed"] and dry["warned"] == ["lubrication"]
    for lubrication in ("greased", "oiled"):
        lubricated = _evaluate(client, catalog_id="Tr20x4-bronze", lubrication=lubrication)
        assert "lubrication" not in [c["name"] for c in lubricated["checks"]]
        assert lubricated["warned"] == []


def test_a_polymer_nut_and_a_ball_nut_need_no_lubrication_to_be_rated(client: TestClient) -> None:
    for screw in ("Tr20x4-acetal", "Tr20x4-ptfe", "B8000-L10-TFE", "R16-10K3-FSCDIN"):
        checks = _evaluate(client, catalog_id=screw)["checks"]
        assert "lubrication" not in [c["name"] for c in checks], screw


def test_a_screw_of_ones_own_with_a_bronze_nut_is_flagged_dry_too(client: TestClient) -> None:
    """The catalog's bronze nut material on a screw of one's own carries its rule."""
    screw = {
        "outer_diameter_mm": 20, "root_diameter_mm": 15.5, "lead_mm": 4, "pitch_mm": 4,
        "thread_half_angle_deg": 15, "friction_dynamic": 0.13, "friction_static": 0.16,
        "nut_material": "bronze",
    }  # fmt: skip
    body = {"application": AXIS, "screw": screw}
    r = client.post("/api/v1/evaluate", json=body)
    assert r.status_code == 200, r.text
    assert r.json()["candidate"]["warned"] == ["lubrication"]


def _raise_torque(force_n: float, mu: float) -> float:
    """Shigley eq. 8-1 with the flank angle (eq. 8-5 style) on Tr20x4: lead 4 mm, pitch
    diameter d2 18 mm, 15 deg half-angle: T = F d2 / 2 (l + pi mu d2 sec a) /
    (pi d2 - mu l sec a) [N m]."""
    lead, d2, sec = 0.004, 0.018, 1.0 / math.cos(math.radians(15.0))
    return force_n * d2 / 2 * (lead + math.pi * mu * d2 * sec) / (math.pi * d2 - mu * lead * sec)


def test_the_torque_of_a_dry_bronze_nut_is_at_its_dry_friction(client: TestClient) -> None:
    """Tr20x4 bronze at 1000 N: 2.4409 N m dry (mu 0.19), 1.8657 N m oiled (mu 0.13), as
    the page and the API show it; the friction's provenance says which."""
    params = {**AXIS, "load_n": 1000, "catalog_id": "Tr20x4-bronze"}
    dry = _evaluate(client, **params)
    oiled = _evaluate(client, **params, lubrication="oiled")
    assert dry["torque"]["load_nm"] == _approx(_raise_torque(1000.0, 0.19))
    assert oiled["torque"]["load_nm"] == _approx(_raise_torque(1000.0, 0.13))
    assert round(dry["torque"]["load_nm"], 4) == 2.4409
    assert round(oiled["torque"]["load_nm"], 4) == 1.8657
    assert "run dry" in dry["provenance"]["friction_dynamic"]["source"]
    assert "machine oil" in oiled["provenance"]["friction_dynamic"]["source"]
    (check,) = [c for c in dry["checks"] if c["name"] == "lubrication"]
    assert "dry friction, running 0.19 and static 0.24" in check["message"]
    assert "pressure and wear ratings are still a lubricated nut's" in check["message"]


def test_a_screw_of_ones_own_with_a_bronze_nut_runs_dry_as_the_catalog_s(
    client: TestClient,
) -> None:
    screw = {
        "outer_diameter_mm": 20, "root_diameter_mm": 15.5, "lead_mm": 4, "pitch_mm": 4,
        "thread_half_angle_deg": 15, "friction_dynamic": 0.13, "friction_static": 0.16,
        "nut_material": "bronze",
    }  # fmt: skip
    torques = {}
    for lubrication in ("dry", "oiled"):
        body = {"application": {**AXIS, "load_n": 1000, "lubrication": lubrication}}
        r = client.post("/api/v1/evaluate", json={**body, "screw": screw})
        assert r.status_code == 200, r.text
        torques[lubrication] = r.json()["candidate"]["torque"]["load_nm"]
    assert torques["dry"] == _approx(_raise_torque(1000.0, 0.19))
    assert torques["oiled"] == _approx(_raise_torque(1000.0, 0.13))


def _approx(value: float) -> object:
    return pytest.approx(value, rel=1e-9)


def test_a_screw_of_ones_own_run_dry_keeps_a_higher_friction_given(client: TestClient) -> None:
    """A bronze nut given a measured 0.30 running and 0.40 static friction, run dry: the
    bronze nut's friction run dry (0.19, 0.24) is lower, and replaced the one given, so a
    0.40 N m drive passed a vertical 100 N lift whose start, at the friction given, needs
    0.487 N m. Run dry it rubs at no less than the friction given, whose provenance stays
    the user's; given the oiled 0.13 it still runs at the dry 0.19."""
    screw = {
        "outer_diameter_mm": 20, "root_diameter_mm": 15.5, "lead_mm": 4, "pitch_mm": 4,
        "thread_half_angle_deg": 15, "friction_dynamic": 0.30, "friction_static": 0.40,
        "nut_material": "bronze",
    }  # fmt: skip
    axis = {**AXIS, "load_n": 100, "orientation": "vertical", "max_torque_nm": 0.40}
    r = client.post("/api/v1/evaluate", json={"application": axis, "screw": screw})
    candidate = r.json()["candidate"]
    assert candidate["torque"]["load_nm"] == _approx(_raise_torque(100.0, 0.30))
    (torque,) = [c for c in candidate["checks"] if c["name"] == "torque"]
    assert not torque["passed"]
    assert candidate["provenance"]["friction_dynamic"]["kind"] == "user"


def test_a_bronze_nut_oiled_in_a_vacuum_runs_dry(client: TestClient) -> None:
    """Oil and grease evaporate in a vacuum (``lubrication_counted``): the PV check
    already counted none, but the friction stayed the oiled one. Tr16x4 bronze (d2 14 mm,
    tan(lambda) = 4 / (pi 14) = 0.09095) oiled in a vacuum ran at 0.3983 efficiency (mu
    0.13); it runs dry now, 0.3105 at mu 0.19, (cos 15 - mu tan) / (cos 15 + mu / tan),
    and the advice says why."""
    query = {"catalog_id": "Tr16x4-bronze", "stroke_mm": 300, "vacuum": "true"}
    tan_l, cos_a = 0.004 / (math.pi * 0.014), math.cos(math.radians(15.0))
    for lubrication in ("oiled", "greased", "dry"):
        candidate = _evaluate(client, **query, lubrication=lubrication)
        assert candidate["efficiency"] == pytest.approx(
            (cos_a - 0.19 * tan_l) / (cos_a + 0.19 / tan_l), rel=1e-9
        )
        (check,) = [c for c in candidate["checks"] if c["name"] == "lubrication"]
        assert not check["passed"]
        assert ("In a vacuum oil and grease evaporate" in check["message"]) == (
            lubrication != "dry"
        )
