"""Every feasible change the select summary offers admits the screw it names: evaluated
with the change made, that screw passes (at its limits, the change having no margin)."""

from fastapi.testclient import TestClient

#: A short vertical axis on a stepper: Tr18x4 bronze fails only its stroke on the 300 mm
#: screw; the longer screw the stroke asks for (321 mm) is a heavier one, which the
#: 14HS20's curve then cannot accelerate (1.044 of it), so that change alone admits none.
#: Run dry: greased, the polymer nuts would hold at their static friction eased by the
#: grease, and none of lead 4 mm self-locks with margin then (no change admits one).
AXIS = {
    "orientation": "vertical",
    "load_n": 5,
    "moving_mass_kg": 0.5,
    "speed_mm_s": 10,
    "length_mm": 300,
    "end_fixity": "fixed-fixed",
    "stroke_mm": 285,
    "accel_mm_s2": 5000,
    "lead_mm": 4,
    "motor": "14hs20-1504s",
    "max_step_rate_hz": 50000,
    "microsteps": 8,
    "hold_power_off": True,
    "lubrication": "dry",
    "support_id": "thk-fk15",
}


def test_every_change_admits_its_screw(client: TestClient) -> None:
    r = client.post("/api/v1/select", json=AXIS)
    assert r.status_code == 200, r.text
    summary = r.json()["summary"]
    assert r.json()["counts"]["passed"] == 0
    offered = [(c["inputs"], c["admits"]) for c in summary["changes"]]
    if summary["input_change"]:
        offered.append((summary["input_change"], summary["best_rejected_id"]))
    assert offered
    for inputs, screw in offered:
        body = {"application": {**AXIS, **inputs}, "screw": {"catalog_id": screw}}
        e = client.post("/api/v1/evaluate", json=body)
        assert e.status_code == 200, e.text
        candidate = e.json()["candidate"]
        failed = [(c["name"], c["utilization"]) for c in candidate["checks"] if not c["passed"]]
        assert candidate["passed"], (inputs, screw, failed)
