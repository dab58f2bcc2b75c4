"""The select and evaluate routes skip response validation (``app.server.responses.ModelJSON``);
what they serve must still be, byte for byte, what the validated output model gives."""

from typing import Any

import pytest
from fastapi.testclient import TestClient
from pydantic import BaseModel

from app.contract.outputs import EvaluateOut, SelectOut, SelectSummaryOut

BASE: dict[str, Any] = {"load_n": 100, "speed_mm_s": 50, "length_mm": 500}
APPLICATIONS: dict[str, dict[str, Any]] = {
    "typical": {**BASE, "lead_mm": 10},
    "any-lead": BASE,
    "no-lead-matches": {**BASE, "lead_mm": 7.77},
    "nothing-passes": {"load_n": 900_000, "speed_mm_s": 90_000, "length_mm": 90_000},
    "every-option": {
        **BASE,
        "lead_mm": 5,
        "vacuum": True,
        "orientation": "vertical",
        "end_fixity": "fixed-free",
        "coating": "tfe",
        "require_anti_backlash": True,
        "moving_mass_kg": 3,
        "ambient_c": 60,
        "stroke_mm": 300,
        "cycles_per_day": 500,
        "required_life_years": 2,
        "positioning_tolerance_mm": 0.05,
        "max_torque_nm": 0.5,
        "rank_by": "life",
        "limit": 100,
    },
    "rank-by-margin": {**BASE, "rank_by": "margin", "limit": 3},
    "rank-by-size": {**BASE, "rank_by": "size"},
}


def _as_validated(model: type[BaseModel], served: bytes) -> bytes:
    return model.model_validate_json(served).model_dump_json(by_alias=True).encode()


@pytest.mark.parametrize("body", APPLICATIONS.values(), ids=APPLICATIONS.keys())
def test_select_serves_what_the_model_would(client: TestClient, body: dict[str, Any]) -> None:
    full = {"detail": "full"}
    for response in (
        client.post("/api/v1/select", json=body, params=full),
        client.get("/api/v1/select", params={**body, **full}),
    ):
        assert response.status_code == 200, response.text
        assert response.headers["content-type"] == "application/json"
        assert response.content == _as_validated(SelectOut, response.content)


@pytest.mark.parametrize("body", APPLICATIONS.values(), ids=APPLICATIONS.keys())
def test_compact_select_serves_what_its_model_would(
    client: TestClient, body: dict[str, Any]
) -> None:
    """The compact form's candidates leave out what is not worked out (their models'
    optional fields, never null): the served JSON is the validated model's fields as
    served, and outside the candidates no field is left to its default."""
    for response in (
        client.post("/api/v1/select", json=body),
        client.get("/api/v1/select", params=body),
    ):
        assert response.status_code == 200, response.text
        validated = SelectSummaryOut.model_validate_json(response.content)
        served = validated.model_dump_json(by_alias=True, exclude_unset=True).encode()
        assert response.content == served
        around = {"candidates", "rejected"}
        assert validated.model_dump(exclude=around) == validated.model_dump(
            exclude=around, exclude_unset=True
        )


@pytest.mark.parametrize(
    "screw",
    [
        {"catalog_id": "ZBX8000-L10"},
        {"catalog_id": "B4000-L1-TFE"},
        {
            "outer_diameter_mm": 12.7,
            "root_diameter_mm": 10.0,
            "lead_mm": 10.0,
            "friction_dynamic": 0.15,
            "friction_static": 0.08,
            "material": {"youngs_modulus_pa": 2e11, "density_kg_m3": 7800},
        },
    ],
    ids=["catalog", "catalog-tfe", "custom"],
)
@pytest.mark.parametrize("application", APPLICATIONS.values(), ids=APPLICATIONS.keys())
def test_evaluate_serves_what_the_model_would(
    client: TestClient, application: dict[str, Any], screw: dict[str, Any]
) -> None:
    response = client.post("/api/v1/evaluate", json={"application": application, "screw": screw})
    assert response.status_code == 200, response.text
    assert response.content == _as_validated(EvaluateOut, response.content)


def test_non_finite_numbers_are_null_as_in_the_model() -> None:
    from app.api.routes import ModelJSON

    assert ModelJSON({"a": float("inf"), "b": float("nan"), "c": 1.5}).body == (
        b'{"a":null,"b":null,"c":1.5}'
    )
