"""A stepper gives more torque slower: where nothing passes on the motor's curve, the
no-pass summary tries the speeds at which the screws a slower move may clear fit the
curve, and each screw's fix names the top speed that fits, with or without a stroke.

A vertical 20 kg on STEPPERONLINE 17HS19-2004S1 (the library's curve) at 50 mm/s: every
screw fails (the fine leads nearest to passing need more torque than the curve gives at
any speed), and the summary said no screw could do it with this motor, a larger one or
a gearbox; at 2.4 mm/s six 1 mm leads pass."""

from typing import Any

import pytest
from fastapi.testclient import TestClient

from tests.api.calls import check, evaluate

AXIS = {"load_n": 0, "length_mm": 500, "orientation": "vertical", "moving_mass_kg": 20,
        "motor": "17hs19-2004s1"}  # fmt: skip
#: a remedy passes at its governing utilisation at most 1 / 1.05 (app.core.remedy)
MARGIN = 1.05


def _select(client: TestClient, **axis: Any) -> Any:
    response = client.get("/api/v1/select", params={**AXIS, **axis})
    assert response.status_code == 200, response.text
    return response.json()


def test_a_slower_move_is_offered_and_lets_the_screws_pass(client: TestClient) -> None:
    summary = _select(client, speed_mm_s=50)["summary"]
    assert summary["impossible"] is None
    slower = [r for r in summary["remedies"] if set(r["inputs"]) == {"speed_mm_s"}]
    assert slower, summary["remedies"]
    speed = slower[0]["inputs"]["speed_mm_s"]
    assert 1.0 < speed < 50.0
    assert slower[0]["utilization"] <= 1.0 / MARGIN
    applied = _select(client, speed_mm_s=speed)
    assert applied["counts"]["passed"] == slower[0]["passing"] > 0
    surest = min(c["utilization"][c["governing_check"]] for c in applied["candidates"])
    assert surest == pytest.approx(slower[0]["utilization"], rel=1e-5)


def test_without_a_stroke_the_motor_fix_names_the_speed_that_fits(client: TestClient) -> None:
    """B6000-L1-TFE at 50 mm/s turns at 3000 rpm, past where the curve holds its torque;
    its fix now names the top speed at which it fits (with the fix's 5 % margin), and at
    that speed the motor's curve check passes."""
    candidate = evaluate(client, "B6000-L1-TFE", **AXIS, speed_mm_s=50)
    fix = check(candidate, "motor_curve")["fix"]
    assert "a top speed of at most " in fix, fix
    speed = float(fix.split("a top speed of at most ")[1].split(" mm/s")[0])
    assert 1.0 < speed < 50.0
    slower = evaluate(client, "B6000-L1-TFE", **AXIS, speed_mm_s=speed)
    assert check(slower, "motor_curve")["passed"]
    assert check(slower, "motor_curve")["utilization"] <= 1.0 / MARGIN + 1e-6
