"""The values the loader hands to the rest of the app: sourced values, materials, series
(the whole catalog that holds them: ``app.catalog.catalog``)."""

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from app.core.model import Provenance, ScrewSpec


@dataclass(frozen=True, slots=True)
class Sourced:
    """A catalog value with its unit and provenance, as shown to users."""

    value: Any
    unit: str
    provenance: Provenance


#: For each catalog value given with a range, the ScrewSpec fields at its low and at its
#: high end (``ScrewSpec.assumption_ends``).
Ends = Mapping[str, tuple[Mapping[str, Any], Mapping[str, Any]]]


@dataclass(frozen=True, slots=True)
class Material:
    """A screw material's constants in SI, each with its provenance, and the ends of
    those given with a range, which every screw of the material carries."""

    youngs_modulus_pa: Sourced
    density_kg_m3: Sourced
    expansion_per_k: Sourced
    yield_strength_pa: Sourced | None = None
    thermal_conductivity_w_m_k: Sourced | None = None
    ends: Ends = field(default_factory=dict)


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
