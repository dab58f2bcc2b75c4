"""The drive-torque and motor-RMS checks name the inputs that clear them: the largest
acceleration and load at which the required torque meets the drive's, the acceleration
and the dwell at which the cycle's RMS torque meets the motor's rating. Each value lands
on the limit (the check passes there, and only just), each figure of the fix keeps the
5 % margin it promises, and where no change was tried the no-pass sentence says so."""

from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.core.batch import CheckResult
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.phrase import Amount
from app.core.remedy import NOTHING_TRIED, impossible, tried_words
from app.report.service import INPUT_WORDS

TORQUE = Application(
    load_n=200.0, moving_mass_kg=30.0, speed_m_s=0.15, length_m=0.7, stroke_m=0.5,
    accel_m_s2=3.0, max_torque_nm=0.25, motor_inertia_kg_m2=3e-5,
)  # fmt: skip
RMS = Application(
    load_n=40.0, moving_mass_kg=20.0, speed_m_s=0.4, length_m=0.8, stroke_m=0.5,
    accel_m_s2=8.0, dwell_s=0.05, motor_rms_torque_nm=0.12, motor_inertia_kg_m2=2e-5,
    families=("HIWIN-ROLLED",),
)  # fmt: skip
CASES = [
    (TORQUE, "R10-04T2-RSIT", "torque", {"accel_m_s2", "load_n"}),
    (RMS, "R16-10K3-FSCDIN", "motor_rms", {"accel_m_s2", "dwell_s"}),
]


def _check(app: Application, catalog: Catalog, screw_id: str, name: str) -> CheckResult:
    return next(c for c in evaluate(app, catalog.by_id[screw_id]).checks if c.name == name)


@pytest.mark.parametrize(("app", "screw_id", "name", "keys"), CASES, ids=["torque", "rms"])
def test_each_input_limit_lands_on_the_check_s_limit(
    catalog: Catalog, app: Application, screw_id: str, name: str, keys: set[str]
) -> None:
    failed = _check(app, catalog, screw_id, name)
    assert not failed.passed and failed.input_limits is not None
    assert set(failed.input_limits) == keys
    for key, value in failed.input_limits.items():
        again = _check(replace(app, **{key: value}), catalog, screw_id, name)  # type: ignore[arg-type]
        assert again.utilization == pytest.approx(1.0, abs=1e-6), key
        assert again.passed, key


@pytest.mark.parametrize(("app", "screw_id", "name", "keys"), CASES, ids=["torque", "rms"])
def test_the_fix_names_each_value_with_its_margin(
    catalog: Catalog, app: Application, screw_id: str, name: str, keys: set[str]
) -> None:
    fix = _check(app, catalog, screw_id, name).fix
    assert fix is not None and "Alone, " in fix.template
    for key in keys:
        figure = fix.values[key]
        assert isinstance(figure, Amount) and "{" + key + "}" in fix.template
        again = _check(replace(app, **{key: figure.value}), catalog, screw_id, name)  # type: ignore[arg-type]
        assert again.utilization == pytest.approx(1.0 / 1.05, abs=1e-6), key
    assert "of at most {accel_m_s2}" in fix.template


def test_the_no_pass_sentence_names_only_the_inputs_tried() -> None:
    """Each input by the field table's label, in its order (the words the edge passes)."""
    assert tried_words({"accel_m_s2"}, INPUT_WORDS) == (
        "no change of acceleration tried lets one pass with a 5 % margin"
    )
    said = tried_words({"dwell_s", "accel_m_s2", "load_n", "end_fixity"}, INPUT_WORDS)
    assert "axial load, acceleration, dwell or mounting" in said and "speed" not in said
    text = impossible(TORQUE, "temperature", "Temperature", True, (), "screw").template
    assert NOTHING_TRIED in text and "speed" not in text
