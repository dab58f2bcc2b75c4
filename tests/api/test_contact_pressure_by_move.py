"""The nut's contact pressure in a cycle of moves: each move's peak thrust at its own
sliding speed, the move the nut carries worst (a heavy slow move and a light fast one
were judged as one heavy fast move, and good bronze nuts were rejected).

Tr20x4-bronze (ISO 2904: d2 = 18 mm, H1 = 2 mm; the catalog's 40 mm nut, 10 turns of
pi d2 H1: 1131 mm^2), oiled; one turn of the helix at d2 is sqrt((18 pi)^2 + 4^2) =
56.69 mm. The bronze nut's allowable pressure by sliding speed is the catalog's table
(Shigley Table 8-4, after Rothbart): 11 MPa at 28 mm/s, 1 MPa at 354 mm/s."""

import math

import pytest
from fastapi.testclient import TestClient

from tests.api.calls import check, evaluate

AREA_MM2 = 10 * math.pi * 18.0 * 2.0
HELIX_MM = math.hypot(math.pi * 18.0, 4.0)
AXIS = {"load_n": 10, "speed_mm_s": 10, "length_mm": 800, "lubrication": "oiled"}


def _pressure(client: TestClient, out: str, back: str) -> dict:  # type: ignore[type-arg]
    """The contact-pressure check of the cycle out and back, each move as (speed mm/s,
    load N) over 300 mm with 1000 mm/s^2 ramps."""
    (v1, f1), (v2, f2) = out.split("@"), back.split("@")
    moves = f"300:{v1}:1000:1000:0:0:{f1};-300:{v2}:1000:1000:0:0:{f2}"
    return check(evaluate(client, "Tr20x4-bronze", **AXIS, moves=moves), "bearing_pressure")


def test_each_move_at_its_own_thrust_and_speed(client: TestClient) -> None:
    """The heavy move (5 kN at 2 mm/s) slides at 2 / 4 x 56.69 = 28.3 mm/s, where 11 MPa
    carries 12.44 kN: 5000 / 12441 = 0.402; the fast one (500 N at 25 mm/s) at 354.3 mm/s,
    where 1 MPa carries 1131 N: 500 / 1131 = 0.442, the worse, and the check's. It was
    judged 5000 N against 1131 N, 4.42, and failed."""
    slow_mm_s, fast_mm_s = 2.0 / 4.0 * HELIX_MM, 25.0 / 4.0 * HELIX_MM
    assert (round(slow_mm_s, 1), round(fast_mm_s, 1)) == (28.3, 354.3)
    cycle = _pressure(client, "2@5000", "25@500")
    assert cycle["utilization"] == pytest.approx(500.0 / AREA_MM2, rel=1e-3)
    assert cycle["passed"] and "354.3 mm/s" in cycle["message"]
    heavy = _pressure(client, "2@5000", "2@5000")
    assert heavy["utilization"] == pytest.approx(5000.0 / (11.0 * AREA_MM2), rel=1e-3)
    fast = _pressure(client, "25@500", "25@500")
    assert cycle["utilization"] == max(heavy["utilization"], fast["utilization"])
