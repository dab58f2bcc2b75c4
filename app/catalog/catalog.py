"""What the loader hands to the rest of the app: every series, every candidate, the index,
the materials and the motor and support-unit libraries."""

from collections.abc import Mapping
from dataclasses import dataclass, field

from app.catalog.models import Material, Series
from app.catalog.motors import Motor
from app.catalog.own import NutMaterial
from app.catalog.supports import SupportUnit
from app.core.index import CatalogIndex
from app.core.model import ScrewSpec


@dataclass(frozen=True, slots=True)
class Catalog:
    """Every series, every expanded candidate, the index the core's queries read, and the
    motor library (``motors.toml`` of every catalog directory) and the support-unit
    library (``supports.toml``)."""

    version: str
    series: Mapping[str, Series]
    screws: tuple[ScrewSpec, ...]
    index: CatalogIndex
    materials: Mapping[str, Material]
    by_id: Mapping[str, ScrewSpec] = field(default_factory=dict)
    motors: Mapping[str, Motor] = field(default_factory=dict)
    supports: Mapping[str, SupportUnit] = field(default_factory=dict)
    #: the nut materials a screw of the user's own may take (``own.nut_materials``)
    nut_materials: Mapping[str, NutMaterial] = field(default_factory=dict)
