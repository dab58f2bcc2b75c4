"""A lift whose start from rest governs its stepper: a bronze ISO nut lifting 150 N and
10 kg at 20 mm/s on the STEPPERONLINE 23HS32-4004S, oiled. The top screw, Tr14x3-bronze,
needs 0.4550 N m starting from rest (the thread at its static friction), nearer the
motor's usable torque (37.1 %) than any moving segment (35.5 %). Read by the motor chart's
and the cycle chart's tests."""

from app.contract.schemas import ApplicationIn

INPUTS = ApplicationIn.model_validate(
    {"load_n": 150, "moving_mass_kg": 10, "orientation": "vertical", "speed_mm_s": 20,
     "length_mm": 600, "accel_mm_s2": 500, "stroke_mm": 400, "cycles_per_day": 200,
     "motor": "23hs32-4004s", "family": ["TR-304", "TR-C45"], "nut_material": "bronze",
     "lubrication": "oiled"}
)  # fmt: skip
