"""The same axis typed in inches, lbf, lb in and in/s² (an export link of the page) and in
the API's mm and N gives the same numbers, to 1e-9, and both the core's in SI.

A vertical Z axis with a library stepper, a stroke, a duty and a required life: 5 lbf
down plus 2 lb moving, 2 in/s, a 24 in screw and a 16 in stroke, 40 in/s² with 0.5 s
dwells, 500 cycles a day for 3 years at 95 °F, greased, fixed-fixed, with a 1 lb in brake
(greased, no polymer nut self-locks with margin: the brake holds the load).
"""

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.catalog import Catalog
from app.catalog.axis_motor import with_motor
from app.core.model import Application
from app.core.selection import select

IN, LBF, LB = 0.0254, 4.4482216152605, 0.45359237  # exact factors to m, N, kg
PAGE = {
    "load": "5", "moving_mass_kg": "2", "speed": "2", "length": "24", "stroke": "16",
    "accel": "40", "dwell": "0.5", "cycles_per_day": "500", "required_life_years": "3",
    "ambient_c": "95", "orientation": "vertical", "lubrication": "greased",
    "end_fixity": "fixed-fixed", "motor": "17hs19-2004s1", "limit": "100", "brake_torque": "1",
    "force_unit": "lbf", "length_unit": "in", "accel_unit": "in_s2", "torque_unit": "lb_in",
}  # fmt: skip
AXIS = Application(
    load_n=5 * LBF, moving_mass_kg=2 * LB, speed_m_s=2 * IN, length_m=24 * IN,
    stroke_m=16 * IN, accel_m_s2=40 * IN, dwell_s=0.5, cycles_per_day=500.0,
    required_life_years=3.0, ambient_c=35.0, orientation="vertical", lubrication="greased",
    end_fixity="fixed-fixed", motor="17hs19-2004s1", limit=100, brake_torque_nm=LBF * IN,
)  # fmt: skip
API = {
    "load_n": repr(AXIS.load_n), "moving_mass_kg": repr(AXIS.moving_mass_kg),
    "speed_mm_s": repr(2 * 25.4), "length_mm": repr(24 * 25.4), "stroke_mm": repr(16 * 25.4),
    "accel_mm_s2": repr(40 * 25.4), "dwell_s": "0.5", "cycles_per_day": "500",
    "required_life_years": "3", "ambient_c": "35", "orientation": "vertical",
    "lubrication": "greased", "end_fixity": "fixed-fixed", "motor": "17hs19-2004s1",
    "limit": "100", "detail": "full", "brake_torque_nm": repr(AXIS.brake_torque_nm),
}  # fmt: skip


def _numbers(value: Any, path: str = "") -> dict[str, float]:
    """Every number of a JSON value by its path."""
    if isinstance(value, dict):
        return {
            k: v for key, item in value.items() for k, v in _numbers(item, f"{path}.{key}").items()
        }
    if isinstance(value, list):
        return {
            k: v for i, item in enumerate(value) for k, v in _numbers(item, f"{path}[{i}]").items()
        }
    if isinstance(value, int | float) and not isinstance(value, bool):
        return {path: float(value)}
    return {}


@pytest.fixture(scope="module")
def answers(client: TestClient) -> tuple[dict[str, Any], dict[str, Any]]:
    api = client.get("/api/v1/select", params=API)
    page = client.get("/export.json", params=PAGE)
    assert api.status_code == page.status_code == 200
    for r in (api, page):
        assert "NaN" not in r.text and "Infinity" not in r.text
    return api.json(), page.json()


def test_inches_and_millimetres_give_the_same_numbers(answers: tuple[dict, dict]) -> None:
    api, page = answers
    by_id = [{c["id"]: c for c in a["candidates"] + a["rejected"]} for a in (api, page)]
    assert by_id[0].keys() == by_id[1].keys()
    for screw, record in by_id[0].items():
        a, b = _numbers(record), _numbers(by_id[1][screw])
        assert a.keys() == b.keys()
        wrong = {k: (a[k], b[k]) for k in a if not math.isclose(a[k], b[k], rel_tol=1e-9)}
        assert wrong == {}, screw


def test_the_api_gives_the_cores_numbers(answers: tuple[dict, dict], catalog: Catalog) -> None:
    api, _ = answers
    core = {
        c.screw.id: c for c in select(with_motor(AXIS, catalog.motors), catalog.index).candidates
    }
    assert api["candidates"] and [c["id"] for c in api["candidates"]] == list(core)
    for record in api["candidates"]:
        q = core[record["id"]].quantities
        assert record["rpm"] == pytest.approx(q.axis.rpm, rel=1e-9)
        assert record["peak_axial_load_n"] == pytest.approx(q.axis.peak_force_n, rel=1e-9)
        assert record["torque"]["total_nm"] == pytest.approx(q.torque.total_nm, rel=1e-9)
        assert record["torque"]["rms_nm"] == pytest.approx(q.motor.motor_rms_nm, rel=1e-9)
