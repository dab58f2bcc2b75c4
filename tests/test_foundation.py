"""The walking skeleton: health, OpenAPI, the form and a results fragment."""

from fastapi.testclient import TestClient


def test_health(client: TestClient) -> None:
    body = client.get("/api/v1/health").json()
    assert body["status"] == "ok"
    assert body["candidates"] > 0


def test_openapi_and_docs(client: TestClient) -> None:
    schema = client.get("/openapi.json").json()
    assert "/api/v1/select" in schema["paths"]
    assert client.get("/docs").status_code == 200


def test_form_renders(client: TestClient) -> None:
    html = client.get("/").text
    for name in ("load", "lead", "speed", "length"):
        assert f'name="{name}"' in html


def test_results_show_load_torque(client: TestClient) -> None:
    """ZBX8000, 10 mm lead, 100 N: T = F L / (2 pi eta) with Shigley's Acme efficiency."""
    api = client.get("/api/v1/evaluate", params={})  # a GET evaluate needs its query
    assert api.status_code == 422
    body = client.post(
        "/api/v1/evaluate",
        json={
            "application": {"load_n": 100, "speed_mm_s": 50, "length_mm": 500},
            "screw": {"catalog_id": "ZBX8000-L10"},
        },
    ).json()["candidate"]
    # hand calculation: d_p = 0.89 x 12.7 mm, lambda = atan(10 / (pi d_p)), mu 0.15, 14.5 deg
    import math

    lam = math.atan(10 / (math.pi * 0.89 * 12.7))
    c, t = math.cos(math.radians(14.5)), math.tan(lam)
    eta = (c - 0.15 * t) / (c + 0.15 / t)
    assert math.isclose(body["torque"]["load_nm"], 100 * 0.010 / (2 * math.pi * eta), rel_tol=1e-9)
    page = client.get(
        "/",
        params={"load": 100, "speed": 50, "length": 500, "lead": 10},
        headers={"HX-Request": "true"},
    )
    assert page.status_code == 200
    assert "<html" not in page.text
    # ZBX8000-L10 fails PV at 50 mm/s: it is in the rejected list, which loads on demand
    rejected = client.get(
        "/rejected",
        params={"load": 100, "speed": 50, "length": 500, "lead": 10},
        headers={"HX-Request": "true"},
    )
    assert rejected.status_code == 200 and "ZBX8000-L10" in rejected.text
