"""A bronze nut's ratings are a lubricated nut's: run dry, it is flagged (advice)."""

from fastapi.testclient import TestClient

AXIS = {"load_n": 500, "speed_mm_s": 20, "length_mm": 500}


def _evaluate(client: TestClient, **params: object) -> dict:  # type: ignore[type-arg]
    r = client.get("/api/v1/evaluate", params={**AXIS, **params})
    assert r.status_code == 200, r.text
    return r.json()["candidate"]  # type: ignore[no-any-return]


def test_a_bronze_nut_run_dry_is_flagged_and_greased_it_is_not(client: TestClient) -> None:
    """Tr20x4 bronze: its friction 0.13 is Shigley Table 8-5's steel on bronze with
    machine oil (0.10-0.16); dry the table gives 0.15-0.23, a torque a quarter to a third
    higher than the one shown, and its pressures (Table 8-4) are lubricated screws'. With
    the nut left dry (the default) the advice fails with a warning; greased or oiled, it
    does not run."""
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
