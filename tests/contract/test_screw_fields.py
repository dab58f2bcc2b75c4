"""The custom screw's numbers are declared once, as rows (``app.contract.screw_fields``):
the API's models, the /custom page's fields and the core's values are read from them."""

import dataclasses
import math

import pytest
from pydantic import ValidationError

from app.catalog.own import OwnGeometry
from app.contract.input_types import describe
from app.contract.screw_fields import BY_NAME, HALF_ANGLE, MATERIAL_FIELDS, SCREW_FIELDS
from app.contract.screws import CustomScrewIn, MaterialIn
from app.report.present import own_geometry
from app.web import screw_form

TR12X3 = {
    "outer_diameter_mm": 12.0,
    "root_diameter_mm": 8.5,
    "lead_mm": 3.0,
    "thread_half_angle_deg": 15.0,
    "friction_dynamic": 0.13,
    "friction_static": 0.16,
    "pitch_mm": 3.0,
}


@pytest.mark.parametrize(
    ("model", "rows"), [(CustomScrewIn, SCREW_FIELDS), (MaterialIn, MATERIAL_FIELDS)]
)
def test_each_row_is_one_field_of_the_api_model_with_its_bounds_and_words(
    model: type, rows: tuple
) -> None:
    schema = model.model_json_schema()["properties"]
    numbers = [name for name in model.model_fields if name not in ("material", "nut_material")]
    assert numbers == [row.api for row in rows]
    for row in rows:
        field = schema[row.api]
        number = next(t for t in field.get("anyOf", [field]) if t.get("type") == "number")
        assert (number["minimum"], number["maximum"]) == row.bounds, row.api
        assert field["description"] == describe(row)
        assert model.model_fields[row.api].is_required() == row.required


def test_a_field_without_help_is_described_by_its_label_and_unit_alone() -> None:
    assert describe(BY_NAME["outer_diameter_mm"]) == "Outer diameter [mm]."
    assert describe(BY_NAME["friction_dynamic"]) == "Running friction coefficient."
    assert describe(HALF_ANGLE) == "Flank half-angle [deg]. 14.5 Acme, 15 trapezoidal."


def test_the_page_shows_each_rows_label_unit_hint_and_default() -> None:
    shown = {f.name: f for f in (*screw_form.SCREW_FIELDS, *screw_form.MATERIAL_FIELDS)}
    assert list(shown) == [row.api for row in (*SCREW_FIELDS, *MATERIAL_FIELDS)]
    for row in (*SCREW_FIELDS, *MATERIAL_FIELDS):
        field = shown[row.page]
        assert (field.label, field.unit, field.help) == (row.label, row.unit, row.help)
        assert field.quantity == row.quantity
    assert (shown["thread_half_angle_deg"].default, shown["drag_torque_nm"].default) == (
        "14.5",
        "0",
    )
    assert shown["pv_limit_mpa_m_s"].quantity == "pv"  # typed in psi ft/min on an inch page


def test_the_core_reads_every_row_in_si() -> None:
    """Tr12x3: 12 mm, 8.5 mm, 3 mm lead and pitch, 15 degrees (pi / 12 rad)."""
    assert {row.core for row in SCREW_FIELDS} <= {f.name for f in dataclasses.fields(OwnGeometry)}
    values = CustomScrewIn.model_validate({**TR12X3, "pv_limit_mpa_m_s": 3.0}).model_dump()
    geometry = own_geometry(values)
    assert geometry.outer_diameter_m == pytest.approx(0.012, rel=1e-15)
    assert geometry.root_diameter_m == pytest.approx(0.0085, rel=1e-15)
    assert geometry.lead_m == geometry.pitch_m == pytest.approx(0.003, rel=1e-15)
    assert geometry.thread_half_angle_rad == pytest.approx(math.pi / 12, rel=1e-15)
    assert geometry.pv_limit_pa_m_s == pytest.approx(3e6, rel=1e-15)
    assert (geometry.friction_dynamic, geometry.friction_static) == (0.13, 0.16)
    assert (geometry.drag_torque_nm, geometry.inertia_kg_m2_per_m) == (0.0, None)


@pytest.mark.parametrize("text", ["１２", "1_2", "nan", "12,5"])
def test_a_screw_number_as_text_is_an_ascii_decimal_as_every_input_is(text: str) -> None:
    """The application's rule for number text holds for the screw's numbers too."""
    with pytest.raises(ValidationError) as caught:
        CustomScrewIn.model_validate({**TR12X3, "outer_diameter_mm": text})
    (error,) = caught.value.errors()
    assert error["loc"] == ("outer_diameter_mm",)
    assert "ASCII decimal" in error["msg"]
    assert CustomScrewIn.model_validate({**TR12X3, "outer_diameter_mm": " 12.0 "})
