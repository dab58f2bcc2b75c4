"""What the loader hands to the rest of the app: sourced values, series, the catalog."""

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from app.core.index import CatalogIndex
from app.core.model import Provenance, ScrewSpec

if TYPE_CHECKING:
    from app.catalog.motors import Motor
    from app.catalog.supports import SupportUnit


@dataclass(frozen=True, slots=True)
class Sourced:
    """A catalog value with its unit and provenance, as shown to users."""

    value: Any
    unit: str
    provenance: Provenance


@dataclass(frozen=True, slots=True)
class Material:
    """A screw material's constants in SI, each with its provenance."""

    youngs_modulus_pa: Sourced
    density_kg_m3: Sourced
    expansion_per_k: Sourced
    yield_strength_pa: Sourced | None = None
    thermal_conductivity_w_m_k: Sourced | None = None


@dataclass(frozen=True, slots=True)
class Series:
    """One catalog series (one size): display fields with provenance, and its screws."""

    id: str
    name: str
    family: str
    family_name: str
    type: str
    file: str
    fields: Mapping[str, Sourced]
    screws: tuple[ScrewSpec, ...]


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
    motors: Mapping[str, "Motor"] = field(default_factory=dict)
    supports: Mapping[str, "SupportUnit"] = field(default_factory=dict)
