"""A screw of the user's own as a candidate: the ScrewSpec a catalog series would give
(``app.catalog.series``), built from the user's geometry and friction in SI and a screw
material, the catalog's by name or the user's constants (``user_material``). Every value
the user gives carries the provenance "user"; the inertia, when not given, is derived
(a solid rod at the root diameter, ``formulas.torque.solid_rod_inertia_per_length``)."""

from dataclasses import dataclass

from app.catalog.models import Material, Sourced
from app.core.formulas import torque
from app.core.model import Provenance, ScrewSpec
from app.core.record import GEOMETRY_SOURCES

#: What the user gives in a request.
USER = Provenance("user", "given in the request")
DERIVED_INERTIA = Provenance("derived", "solid rod at the root diameter: rho pi d_r^4 / 32")


@dataclass(frozen=True, slots=True)
class OwnGeometry:
    """The user's screw in SI: diameters, lead [m], the flank half-angle [rad], static
    and dynamic friction, the drag torque [N m], the nut's PV limit [Pa m/s] (None: no PV
    limit) and the inertia per length [kg m^2/m] (None: derived from the material)."""

    outer_diameter_m: float
    root_diameter_m: float
    lead_m: float
    thread_half_angle_rad: float
    friction_static: float
    friction_dynamic: float
    drag_torque_nm: float = 0.0
    pv_limit_pa_m_s: float | None = None
    inertia_kg_m2_per_m: float | None = None


def user_material(
    youngs_modulus_pa: float, density_kg_m3: float, yield_strength_pa: float | None, like: Material
) -> Material:
    """The user's constants as a material, each of provenance "user"; the thermal
    expansion, which the user is not asked for, is ``like``'s (with its provenance)."""
    yield_strength = None if yield_strength_pa is None else Sourced(yield_strength_pa, "Pa", USER)
    return Material(
        youngs_modulus_pa=Sourced(youngs_modulus_pa, "Pa", USER),
        density_kg_m3=Sourced(density_kg_m3, "kg/m3", USER),
        expansion_per_k=like.expansion_per_k,
        yield_strength_pa=yield_strength,
    )


def own_screw(geometry: OwnGeometry, material: Material, material_name: str) -> ScrewSpec:
    """The candidate "custom" from the user's ``geometry`` and a ``material``."""
    rho = material.density_kg_m3.value
    inertia, inertia_source = geometry.inertia_kg_m2_per_m, USER
    if inertia is None:
        inertia = torque.solid_rod_inertia_per_length(rho, geometry.root_diameter_m)
        inertia_source = DERIVED_INERTIA
    strength = material.yield_strength_pa
    return ScrewSpec(
        id="custom",
        series_id="custom",
        series_name="Custom screw",
        anti_backlash=False,
        coated=False,
        outer_diameter_m=geometry.outer_diameter_m,
        root_diameter_m=geometry.root_diameter_m,
        lead_m=geometry.lead_m,
        thread_half_angle_rad=geometry.thread_half_angle_rad,
        friction_static=geometry.friction_static,
        friction_dynamic=geometry.friction_dynamic,
        youngs_modulus_pa=material.youngs_modulus_pa.value,
        density_kg_m3=rho,
        screw_expansion_per_k=material.expansion_per_k.value,
        inertia_kg_m2_per_m=inertia,
        drag_torque_min_nm=geometry.drag_torque_nm,
        drag_torque_max_nm=geometry.drag_torque_nm,
        pv_limit_pa_m_s=geometry.pv_limit_pa_m_s,
        material_name=material_name,
        yield_strength_pa=None if strength is None else strength.value,
        provenance={
            **({} if strength is None else {"yield_strength": strength.provenance}),
            **dict.fromkeys(GEOMETRY_SOURCES, USER),
            "pv_limit": USER,
            "inertia_per_length": inertia_source,
            "youngs_modulus": material.youngs_modulus_pa.provenance,
            "density": material.density_kg_m3.provenance,
        },
    )
