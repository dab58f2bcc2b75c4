"""The nut's permissible PV derated with its temperature and raised by its lubrication
(``app.core.formulas.pv_derating``), through the API, with the arithmetic by hand.

B8000-L10 (seed polyacetal nut): PV rating 0.105 MPa m/s, highest temperature 93 C
(catalog). At 100 N and 50 mm/s its PV is 0.1193 MPa m/s. The seed gives no nut length,
so the heat balance has none to work with: the nut is judged at the ambient, and the
message says so."""

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.catalog import PROVENANCE_KINDS, Catalog
from app.core.formulas import pv_derating
from app.core.model import Application
from app.core.quantities import _pv_limit

AXIS = {"load_n": 100.0, "speed_mm_s": 50.0, "length_mm": 350.0}
RATING = 0.105  # MPa m/s
T_MAX = 93.0  # C


def _pv(client: TestClient, **extra: object) -> dict:  # type: ignore[type-arg]
    """The PV check; the candidate's PV block shows the same permissible PV."""
    body = {"application": {**AXIS, **extra}, "screw": {"catalog_id": "B8000-L10"}}
    r = client.post("/api/v1/evaluate", json=body)
    assert r.status_code == 200, r.text
    candidate = r.json()["candidate"]
    check = next(c for c in candidate["checks"] if c["name"] == "pv")
    assert candidate["pv"]["limit_mpa_m_s"] == pytest.approx(check["limit"])
    return check  # type: ignore[no-any-return]


@pytest.mark.parametrize(
    ("ambient_c", "lubrication", "limit"),
    [
        (20.0, "dry", RATING),  # below the 23 C reference: the rating itself
        (40.0, "dry", RATING * (93 - 40) / (93 - 23)),  # 0.0795
        (40.0, "greased", RATING * (93 - 40) / (93 - 23) * 1.5),  # 0.1193
        (40.0, "oiled", RATING * (93 - 40) / (93 - 23) * 2.0),  # 0.159
        (58.0, "dry", RATING * 0.5),  # half-way from 23 to 93 C
        (95.0, "oiled", 0.0),  # past the material's highest: nothing left
    ],
)
def test_the_permissible_pv_by_hand(
    client: TestClient, ambient_c: float, lubrication: str, limit: float
) -> None:
    pv = _pv(client, ambient_c=ambient_c, lubrication=lubrication)
    assert pv["limit"] == pytest.approx(limit, abs=1e-9)
    assert pv["value"] == pytest.approx(0.1193, rel=1e-3)
    assert pv["passed"] is (pv["value"] <= limit)
    assert "no heat balance for this nut" in pv["message"]


def test_oil_turns_a_failing_nut_into_a_passing_one(client: TestClient) -> None:
    """0.1193 against 0.0795 dry fails (150 %); oiled, 0.159, passes (75 %)."""
    assert not _pv(client, ambient_c=40.0)["passed"]
    oiled = _pv(client, ambient_c=40.0, lubrication="oiled")
    assert oiled["passed"] and oiled["utilization"] == pytest.approx(0.1193 / 0.159, rel=1e-3)


def test_the_nut_temperature_from_the_heat_balance_derates(catalog: Catalog) -> None:
    """Where the heat balance gives a rise, the nut is judged at ambient + rise: 33 C and
    25 K make 58 C, half-way from 23 to 93 C, so half the rating."""
    table = catalog.index.table.take(np.array([catalog.index.positions["B8000-L10"]]))
    app = Application(load_n=100.0, speed_m_s=0.05, length_m=0.35, ambient_c=33.0)
    out = _pv_limit(app, table, np.array([25.0]))
    assert out["nut_temperature_c"][0] == pytest.approx(58.0)
    assert out["pv_temperature_factor"][0] == pytest.approx(0.5)
    assert out["pv_limit_pa_m_s"][0] == pytest.approx(0.5 * RATING * 1e6)


def test_a_bad_lubrication_is_a_field_level_422(client: TestClient) -> None:
    r = client.get("/api/v1/select", params={**AXIS, "lubrication": "wet"})
    assert r.status_code == 422
    assert r.json()["detail"][0]["field"] == "lubrication"


def test_each_lubrication_factor_carries_provenance() -> None:
    for factor, kind, source in pv_derating.LUBRICATION_FACTORS.values():
        assert factor >= 1.0 and kind in PROVENANCE_KINDS and source
    assert pv_derating.temperature_factor(T_MAX, T_MAX) == 0.0
