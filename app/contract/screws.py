"""The screw inputs of the API and the /custom page: a catalog screw by id, or a screw of
the user's own with its geometry and material (pydantic v2); the evaluate request.
"""

import math
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import (
    BaseModel,
    ConfigDict,
    Discriminator,
    Field,
    Tag,
    ValidationInfo,
    create_model,
    field_validator,
)
from pydantic_core import PydanticCustomError

from app.contract.input_field import InputField
from app.contract.input_types import api_type
from app.contract.inputs import ApplicationIn
from app.contract.params import close_hint, page_name_hint
from app.contract.screw_fields import MATERIAL_FIELDS, SCREW_FIELDS
from app.contract.sections import ProvenanceOut
from app.core.formulas import trapezoidal
from app.core.units import from_si, to_si

#: the nut material of a screw of one's own: the custom page's name (share links;
#: ``nut_material`` is the selector's catalog filter there), the API's, and its label
NUT_FIELD = "nut"
NUT_API = "nut_material"
NUT_LABEL = "Nut material"


def _definitions(rows: tuple[InputField, ...]) -> dict[str, Any]:
    """``create_model`` field definitions of ``rows``: API name -> (type, default or ``...``)."""
    return {f.api: (api_type(f), ... if f.required else f.default) for f in rows}


class MaterialInputs(BaseModel):
    """The user's own screw material; its numbers are the rows of ``MATERIAL_FIELDS``."""

    model_config = ConfigDict(extra="forbid")


if TYPE_CHECKING:
    MaterialIn = MaterialInputs
else:
    MaterialIn = create_model(
        "MaterialIn",
        __base__=MaterialInputs,
        __module__=__name__,
        __doc__=MaterialInputs.__doc__,
        **_definitions(MATERIAL_FIELDS),
    )


class CatalogScrewIn(BaseModel):
    model_config = ConfigDict(extra="forbid")

    catalog_id: str = Field(max_length=100, description="A screw id from /api/v1/select.")


class CustomScrewInputs(BaseModel):
    """A screw that is not in the catalog. Diameters and lead in mm; its numbers are the
    rows of ``SCREW_FIELDS`` (``CustomScrewIn``), its material and nut material its own.
    The checks between numbers read the fields before them (``SCREW_FIELDS`` order)."""

    model_config = ConfigDict(extra="forbid")

    material: Literal["steel", "stainless-303", "c45-steel", "stainless-304"] | MaterialIn = "steel"
    nut_material: str | None = Field(
        default=None,
        max_length=40,
        description="A catalog nut material (GET /api/v1/nut-materials: 'bronze', "
        "'acetal', 'ptfe'): its limits rate the nut, with the nut length its catalog family "
        "takes (2 x d; the application's nut_length_mm sets another); a nut rated by "
        "contact pressure needs pitch_mm.",
    )

    @field_validator("root_diameter_mm", check_fields=False)
    @classmethod
    def _root_below_outer(cls, value: float, info: ValidationInfo) -> float:
        outer = info.data.get("outer_diameter_mm")
        if outer is not None and value >= outer:
            raise ValueError("must be smaller than outer_diameter_mm")
        return value

    @field_validator("pitch_mm", check_fields=False)
    @classmethod
    def _pitch_fits(cls, value: float | None, info: ValidationInfo) -> float | None:
        """The lead is a whole number of pitches, and the thread's basic profile (d2 =
        d - 0.5 P, ``trapezoidal.pitch_diameter``), whose flanks the torque and the nut's
        pressure read, has its pitch line above the root and can be driven at its
        friction."""
        lead = info.data.get("lead_mm")
        if value is None or lead is None:
            return value
        starts = round(lead / value)
        if starts < 1 or not math.isclose(lead, starts * value):
            raise _lengths_error(
                "pitch_multiple", "the lead {lead} must be a whole number of pitches", lead=lead
            )
        outer, root = info.data.get("outer_diameter_mm"), info.data.get("root_diameter_mm")
        half_angle = info.data.get("thread_half_angle_deg")
        if outer is None or root is None or half_angle is None:
            return value  # an earlier field is invalid and already reported
        flank = from_si(trapezoidal.pitch_diameter(to_si(outer, "mm"), to_si(value, "mm")), "mm")
        if flank <= root:
            raise _lengths_error(
                "pitch_too_coarse",
                "too coarse for this screw: its flanks' pitch diameter d - P/2 = {flank} is "
                "not above the root diameter {root}",
                flank=flank,
                root=root,
            )
        for name in ("friction_dynamic", "friction_static"):
            friction = info.data.get(name)
            problem = None if friction is None else _undrivable(lead, flank, half_angle, friction)
            if problem:
                raise _lengths_error(
                    "pitch_undrivable",
                    "at its pitch diameter d - P/2 = {flank}, " + problem,
                    flank=flank,
                )
        return value

    @field_validator("friction_dynamic", "friction_static", check_fields=False)
    @classmethod
    def _thread_drivable(cls, value: float, info: ValidationInfo) -> float:
        """A sliding thread can be driven only while mu tan(lambda) < cos(a_n) (Shigley)."""
        names = ("outer_diameter_mm", "root_diameter_mm", "lead_mm", "thread_half_angle_deg")
        if any(info.data.get(name) is None for name in names):
            return value  # an earlier field is invalid and already reported
        outer, root, lead, half_angle = (float(info.data[name]) for name in names)
        problem = _undrivable(lead, (outer + root) / 2, half_angle, value)
        if problem:
            raise ValueError(problem)
        return value


if TYPE_CHECKING:
    CustomScrewIn = CustomScrewInputs
else:
    CustomScrewIn = create_model(
        "CustomScrewIn",
        __base__=CustomScrewInputs,
        __module__=__name__,
        __doc__=CustomScrewInputs.__doc__,
        **_definitions(SCREW_FIELDS),
    )


def _lengths_error(kind: str, template: str, **lengths_mm: float) -> PydanticCustomError:
    """A screw's error naming lengths [mm]: its words in the API with each length in mm
    (``{name}`` in ``template``), and the lengths in its context, for a page to say them
    in its own unit (``app.web.screw_form``: the ``lengths`` key lists them)."""
    shown = {name: f"{value:.4g} mm" for name, value in lengths_mm.items()}
    words = template.format(**shown)
    return PydanticCustomError(kind, words, {"lengths": dict(lengths_mm), "template": template})


def _undrivable(lead: float, pitch_diameter: float, half_angle_deg: float, friction: float) -> str:
    """Why a sliding thread of ``lead`` on ``pitch_diameter`` (one unit) cannot be driven
    at ``friction`` (mu tan(lambda) >= 0.99 cos(a_n), Shigley); empty when it can."""
    tan_lead = lead / (math.pi * pitch_diameter)
    limit = 0.99 * math.cos(math.radians(half_angle_deg)) / tan_lead
    if friction < limit:
        return ""
    return (
        f"with this lead ({math.degrees(math.atan(tan_lead)):.1f} deg lead angle) the "
        f"thread cannot be driven at friction {friction:g}: it must be below {limit:.3g}"
    )


def _screw_kind(data: Any) -> str:
    has_id = isinstance(data, dict) and "catalog_id" in data
    return "catalog" if has_id or isinstance(data, CatalogScrewIn) else "custom"


ScrewIn = Annotated[
    Annotated[CatalogScrewIn, Tag("catalog")] | Annotated[CustomScrewIn, Tag("custom")],
    Discriminator(_screw_kind),
]


class EvaluateIn(BaseModel):
    """One application and one screw: ``{"catalog_id": ...}`` or a custom geometry."""

    model_config = ConfigDict(extra="forbid")

    application: ApplicationIn
    screw: ScrewIn


class NutValueOut(BaseModel):
    label: str
    value: str = Field(description="The value as text with its unit (MPa, m/s, mm³/(N m)).")
    provenance: ProvenanceOut | None


class NutMaterialOut(BaseModel):
    key: str = Field(description="The name a custom screw's nut_material takes.")
    name: str
    family: str = Field(description="The catalog family its values are read from.")
    values: list[NutValueOut]


class NutMaterialsOut(BaseModel):
    """The catalog's nut materials a custom screw may take, with their limits."""

    catalog_version: str
    nut_materials: list[NutMaterialOut]


def screw_hint(name: str) -> str | None:
    """What the API says of a name it does not read in a screw: the custom page's name
    of the nut material and the API's, or the screw's (or its material's) name ``name``
    is close to; None for any other.

    >>> screw_hint("nut")
    "'nut' is the page's name (share links): the API's is 'nut_material' (Nut material)"
    >>> screw_hint("root_diameter")
    "'root_diameter' is not an API name: did you mean 'root_diameter_mm'?"
    """
    if name == NUT_FIELD:
        return page_name_hint(NUT_FIELD, NUT_API, NUT_LABEL)
    models = (CustomScrewIn, CatalogScrewIn, MaterialIn)
    return close_hint(name, [n for model in models for n in model.model_fields])
