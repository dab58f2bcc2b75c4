"""``app.report.construct.construct`` (and ``from_fields``, for every field given in order)
builds the same output model as ``model_construct``."""

import pytest
from fastapi.testclient import TestClient
from pydantic import BaseModel

from app.contract.outputs import SelectOut
from app.contract.schemas import CandidateOut, CheckOut, TorqueOut
from app.main import create_app
from app.report.construct import construct, from_fields

CHECK = {
    "name": "pv",
    "label": "PV",
    "kind": "limit",
    "passed": True,
    "value": 1.5,
    "limit": 2.0,
    "unit": "MPa m/s",
    "utilization": 0.75,
    "message": "within",
    "formula": "p v",
    "sources": ["pv_limit"],
    "fix": None,
}


def test_a_model_built_both_ways_is_the_same() -> None:
    a, b = construct(CheckOut, **CHECK), CheckOut.model_construct(**CHECK)
    assert a == b
    assert a.model_dump_json() == b.model_dump_json()
    assert a.model_fields_set == b.model_fields_set == set(CHECK)


def test_every_field_in_order_builds_the_same_model() -> None:
    a, b = from_fields(CheckOut, dict(CHECK)), CheckOut.model_construct(**CHECK)
    assert a == b and a.model_dump_json() == b.model_dump_json()
    assert a.model_fields_set == b.model_fields_set == set(CHECK)


def test_defaults_fill_the_fields_not_given_and_are_not_counted_as_set() -> None:
    values = {k: 1.0 for k in ("inertia_nm", "inertia_screw_nm", "inertia_mass_nm", "drag_nm")}
    values |= {"drag_range_nm": [0.0, 1.0], "load_nm": 1.0, "total_nm": 3.0}
    values |= {"breakaway_nm": 3.5, "safety_factor": 2.0, "required_nm": 7.0, "note": "n"}
    a, b = construct(TorqueOut, **values), TorqueOut.model_construct(**values)
    assert a.peak_nm is None and a == b and a.model_dump_json() == b.model_dump_json()
    assert a.model_fields_set == b.model_fields_set == set(values)
    assert a.model_dump(exclude_unset=True) == b.model_dump(exclude_unset=True)


def test_a_full_selection_through_the_api_validates_against_its_own_model() -> None:
    """The select response (built with ``construct`` at every level) is valid JSON for
    ``SelectOut``: every required field of every nested model is there."""
    client = TestClient(create_app())
    query = "load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10&stroke_mm=300&detail=full"
    body = client.get(f"/api/v1/select?{query}&accel_mm_s2=1000&vacuum=true").json()
    out = SelectOut.model_validate(body)
    assert out.candidates and out.candidates[0].segments
    assert isinstance(out.candidates[0], CandidateOut)


def test_models_it_cannot_build_faithfully_are_refused() -> None:
    class Extra(BaseModel):
        model_config = {"extra": "allow"}

    with pytest.raises(TypeError):
        construct(Extra)


def test_a_misspelled_field_is_an_error_not_a_silent_gap() -> None:
    wrong = {**CHECK, "utilisation": 0.75}
    del wrong["utilization"]
    with pytest.raises(KeyError):
        construct(CheckOut, **wrong)
