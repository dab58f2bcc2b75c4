"""The nut's permissible PV derated with the ambient temperature and raised by its
lubrication (``app.core.formulas.pv_derating``), through the API, with the arithmetic by
hand.

B8000-L10 (seed polyacetal nut): PV rating 0.105 MPa m/s, highest temperature 93 C
(catalog). At 100 N and 50 mm/s its PV is 0.1193 MPa m/s. A PV rating is the PV whose
own friction heat takes the nut to its highest temperature from the rating's 23 C room,
so only the ambient above that room derates it (RBC Fiberglide: the PV limit is lowered
at elevated temperatures so that the environment plus the friction heat stays below the
limit); the nut's own rise is the nut heat check's."""

import math

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
    assert "at the ambient" in pv["message"]


def test_oil_turns_a_failing_nut_into_a_passing_one(client: TestClient) -> None:
    """0.1193 against 0.0795 dry fails (150 %); oiled, 0.159, passes (75 %)."""
    assert not _pv(client, ambient_c=40.0)["passed"]
    oiled = _pv(client, ambient_c=40.0, lubrication="oiled")
    assert oiled["passed"] and oiled["utilization"] == pytest.approx(0.1193 / 0.159, rel=1e-3)


def test_the_derating_reads_the_ambient_not_the_nut_rise(catalog: Catalog) -> None:
    """33 C around the nut: (93 - 33) / (93 - 23) = 0.857 of the rating, whatever the
    nut's own rise (the rating holds it)."""
    table = catalog.index.table.take(np.array([catalog.index.positions["B8000-L10"]]))
    app = Application(load_n=100.0, speed_m_s=0.05, length_m=0.35, ambient_c=33.0)
    out = _pv_limit(app, table)
    assert out["pv_temperature_factor"][0] == pytest.approx(60.0 / 70.0)
    assert out["pv_limit_pa_m_s"][0] == pytest.approx(60.0 / 70.0 * RATING * 1e6)


#: Tr12x3 acetal (ISO 2904: d2 = 10.5 mm, H1 = 1.5 mm; nut 2 d = 24 mm, 8 turns):
#: PV 0.07 MPa m/s (Neale A5), highest 100 C (catalog). At 50 mm/s the screw turns
#: 1000 rpm and the flanks slide sqrt(3^2 + (pi 10.5)^2) mm a turn: 0.552 m/s.
TR12_AREA_M2 = 8 * math.pi * 10.5e-3 * 1.5e-3
TR12_SLIDING_M_S = 1000 / 60 * math.hypot(3e-3, math.pi * 10.5e-3)


@pytest.mark.parametrize(
    ("ambient_c", "lubrication", "share"),
    [(20.0, "dry", 1.0), (61.5, "dry", 0.5), (61.5, "oiled", 1.0), (100.0, "greased", 0.0)],
)
def test_an_iso_polymer_nut_is_derated_as_well(
    client: TestClient, ambient_c: float, lubrication: str, share: float
) -> None:
    """The contact-pressure check of a trapezoidal polymer nut takes the same factors: at
    61.5 C, (100 - 61.5) / (100 - 23) = 0.5; oiled, x 2 again. The load its flanks
    carry is PV_lim f_T f_lub / v over the engaged flank area (0.07 MPa m/s: 50.2 N at
    20 C; half at 61.5 C)."""
    body = {
        "application": {**AXIS, "ambient_c": ambient_c, "lubrication": lubrication},
        "screw": {"catalog_id": "Tr12x3-acetal"},
    }
    r = client.post("/api/v1/evaluate", json=body)
    assert r.status_code == 200, r.text
    checks = r.json()["candidate"]["checks"]
    pressure = next(c for c in checks if c["name"] == "bearing_pressure")
    carried_n = 0.07e6 * share / TR12_SLIDING_M_S * TR12_AREA_M2
    assert carried_n == pytest.approx(50.2 * share, abs=0.05)
    assert pressure["limit"] == pytest.approx(carried_n, rel=1e-6, abs=1e-9)
    if share:
        assert "at the ambient" in pressure["message"]
    else:
        assert "no PV left" in pressure["fix"]


def test_a_bad_lubrication_is_a_field_level_422(client: TestClient) -> None:
    r = client.get("/api/v1/select", params={**AXIS, "lubrication": "wet"})
    assert r.status_code == 422
    assert r.json()["detail"][0]["field"] == "lubrication"


def test_each_lubrication_factor_carries_provenance() -> None:
    for factor, kind, source in pv_derating.LUBRICATION_FACTORS.values():
        assert factor >= 1.0 and kind in PROVENANCE_KINDS and source
    assert pv_derating.temperature_factor(T_MAX, T_MAX) == 0.0
