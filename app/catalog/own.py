"""A screw of the user's own as a candidate: the ScrewSpec a catalog series would give
(``app.catalog.series``), built from the user's geometry and friction in SI and a screw
material, the catalog's by name or the user's constants (``user_material``). Every value
the user gives carries the provenance "user"; the inertia, when not given, is derived
as a catalog screw's (``screw_inertia``).

A nut material (``NutMaterial``) is one of the catalog's nut variants rated by its
material (a bronze nut's pressure-speed table, a polymer nut's maximum pressure and PV,
the sliding speed, the wear rate, a maker's dynamic thrust table), read from the catalog's
own candidates with their provenance (``nut_materials``): the user's screw with that nut
is rated exactly as a catalog screw of the same size with that nut."""

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace

from app.catalog.models import Ends, Material, Series, Sourced
from app.catalog.nut_ratings import thrust_pressure
from app.catalog.series import NOT_GIVEN
from app.core.dry_run import DRY
from app.core.formulas import geometry as thread_geometry
from app.core.formulas import torque, trapezoidal
from app.core.model import Provenance, ScrewSpec
from app.core.record import GEOMETRY_SOURCES

#: What the user gives in a request.
USER = Provenance("user", "given in the request")
THREAD_RULE = Provenance("derived", "basic profile from the pitch: d2 = d - 0.5 P, H1 = 0.5 P")


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
    #: thread pitch and nut length [m] (None: not given; a nut rated by its contact
    #: pressure needs both; the nut length then is the nut material's family's)
    pitch_m: float | None = None
    nut_length_m: float | None = None


class UnknownNutMaterial(ValueError):
    """A nut material the loaded catalog does not hold (a 422 on ``field``)."""

    field = "screw.nut_material"


#: The ScrewSpec values a nut material sets, by its provenance key.
NUT_VALUES = {
    "bearing_pressure": "bearing_pressure_table",
    "max_pressure": "max_pressure_pa",
    "bearing_pv_limit": "nut_pv_limit_pa_m_s",
    "max_sliding_speed": "max_sliding_speed_m_s",
    "wear_rate": "wear_rate_m2_n",
    "allowed_wear": "allowed_wear_fraction",
}


#: The ScrewSpec values of a nut rated lubricated run dry (``NutMaterial``), ranged.
DRY_FRICTION = tuple(DRY.values())


#: The catalog's name of the ranged nut length over the screw's diameter.
NUT_LENGTH_RANGE = "nut_length_to_d"


@dataclass(frozen=True, slots=True)
class NutMaterial:
    """One catalog nut material: its key (the variant, "bronze"), its name, the family it
    is read from, its limits as ScrewSpec values (SI, ``NUT_VALUES``), its temperature
    range [C], whether oil suits it, its maker's dynamic thrust table (rows d [m], P [m],
    thrust [N]; None: not rated so), the running and static friction the catalog gives
    it (a suggestion: the user gives the screw's own), the nut's length over the screw's
    diameter the family takes (None: none) and that ratio's range, the ends of its
    limits given with a range (the wear rate's scatter: ``ScrewSpec.assumption_ends``),
    the axial play [m] of its thread fit (low, high; None: not given), and each value's
    provenance."""

    key: str
    name: str
    family: str
    limits: Mapping[str, object]
    temperature_c: tuple[float, float] | None
    oil_compatible: bool
    thrust_table: Sourced | None
    friction_dynamic: float
    friction_static: float
    nut_length_to_d: float | None = None
    provenance: Mapping[str, Provenance] = field(default_factory=dict)
    ends: Ends = field(default_factory=dict)
    nut_length_to_d_ends: tuple[float, float] | None = None
    backlash_m: tuple[float, float] | None = None
    #: its ratings are a lubricated nut's (``ScrewSpec.lubricated_rating``), and its
    #: running and static friction run dry, which replace the user's friction on an axis
    #: that runs it dry as on a catalog screw (None: none given)
    lubricated_rating: bool = False
    dry_friction_dynamic: float | None = None
    dry_friction_static: float | None = None

    def rates_by_pressure(self) -> bool:
        """Whether a limit reads the engaged flank area (pitch and nut length needed)."""
        pressure = ("bearing_pressure_table", "max_pressure_pa", "nut_pv_limit_pa_m_s")
        return self.thrust_table is not None or any(
            self.limits.get(name) not in (None, ()) for name in pressure
        )


#: The values that rate a nut by its material (a maker's nut rated per size by its maker,
#: by a three-thread PV limit and a rated life, is not a material preset).
MATERIAL_RATINGS = (
    "bearing_pressure_table",
    "max_pressure_pa",
    "nut_pv_limit_pa_m_s",
    "max_sliding_speed_m_s",
)


def _rated(screw: ScrewSpec) -> bool:
    """Whether a catalog candidate's nut is rated by its material."""
    return any(getattr(screw, name) not in (None, ()) for name in MATERIAL_RATINGS)


def _nut_material(series: Series, screw: ScrewSpec) -> NutMaterial:
    """The nut material of one catalog candidate, with its provenance."""
    keys = (*NUT_VALUES, "temperature_range", "oil_compatible", "friction_dynamic")
    keys += ("lubricated_rating", *DRY_FRICTION)
    prov = {k: screw.provenance[k] for k in (*keys, "friction_static") if k in screw.provenance}
    low, high = screw.temperature_min_c, screw.temperature_max_c
    thrust = series.fields.get(f"dynamic_thrust_{screw.variant}")
    if thrust is not None:
        prov["dynamic_thrust"] = thrust.provenance
    length = series.fields.get("nut_length")
    if length is not None:
        prov["nut_length"] = length.provenance
    limits = {*NUT_VALUES.values(), *DRY_FRICTION}
    ranged = screw.assumption_ends.get(NUT_LENGTH_RANGE)
    play = series.fields.get("backlash")
    if play is not None:
        prov["backlash"] = play.provenance
    least, most = screw.backlash_min_m, screw.backlash_max_m
    return NutMaterial(
        key=screw.variant,
        name=screw.nut_material,
        family=series.family_name,
        limits={name: getattr(screw, name) for name in NUT_VALUES.values()},
        temperature_c=None if low is None or high is None else (low, high),
        oil_compatible=screw.oil_compatible,
        lubricated_rating=screw.lubricated_rating,
        dry_friction_dynamic=screw.dry_friction_dynamic,
        dry_friction_static=screw.dry_friction_static,
        thrust_table=thrust,
        friction_dynamic=screw.friction_dynamic,
        friction_static=screw.friction_static,
        nut_length_to_d=None if length is None else length.value / screw.outer_diameter_m,
        provenance=prov,
        ends={
            name: ends
            for name, ends in screw.assumption_ends.items()
            if all(set(end) <= limits for end in ends)
        },
        nut_length_to_d_ends=None
        if ranged is None
        else (
            ranged[0]["nut_length_m"] / screw.outer_diameter_m,
            ranged[1]["nut_length_m"] / screw.outer_diameter_m,
        ),
        backlash_m=None if least is None or most is None else (least, most),
    )


def nut_materials(series: Iterable[Series]) -> dict[str, NutMaterial]:
    """The catalog's nut materials by variant key, each read from the first candidate
    that has it (the variants a family declares are the same for all its sizes)."""
    found: dict[str, NutMaterial] = {}
    for s in series:
        for screw in s.screws:
            if screw.variant and screw.variant not in found and _rated(screw):
                found[screw.variant] = _nut_material(s, screw)
    return found


def user_material(
    youngs_modulus_pa: float,
    density_kg_m3: float,
    yield_strength_pa: float | None,
    like: Material,
    expansion_per_k: float | None = None,
) -> Material:
    """The user's constants as a material, each of provenance "user"; the thermal
    expansion [1/K] the user's where given, else ``like``'s value, "assumed" (an
    aluminium screw expands about twice as much as steel); no thermal conductivity (the
    nut heat check says it could not run)."""
    yield_strength = None if yield_strength_pa is None else Sourced(yield_strength_pa, "Pa", USER)
    return Material(
        youngs_modulus_pa=Sourced(youngs_modulus_pa, "Pa", USER),
        density_kg_m3=Sourced(density_kg_m3, "kg/m3", USER),
        expansion_per_k=_expansion(expansion_per_k, like),
        yield_strength_pa=yield_strength,
    )


def _expansion(expansion_per_k: float | None, like: Material) -> Sourced:
    """The user's thermal expansion [1/K], else ``like``'s, "assumed"."""
    if expansion_per_k is not None:
        return Sourced(expansion_per_k, "1/K", USER)
    expansion = like.expansion_per_k
    assumed = Provenance(
        "assumed",
        f"not given with the screw's own material: steel's {expansion.value:.3g} 1/K taken "
        f"({expansion.provenance.kind}: {expansion.provenance.source}); a screw of another "
        "metal expands by its own (aluminium about 23e-6 1/K, twice steel's)",
    )
    return Sourced(expansion.value, expansion.unit, assumed)


def _thread(geometry: OwnGeometry) -> dict[str, object]:
    """The pitch, pitch diameter d2 and flank height H1 of a thread with a pitch, by the
    basic profile (d2 = d - 0.5 P, H1 = 0.5 P: ISO 2904 and ASME B1.5 Acme alike), and
    the nut length; nothing but the nut length without a pitch."""
    out: dict[str, object] = {"nut_length_m": geometry.nut_length_m}
    if geometry.pitch_m is not None:
        out["pitch_m"] = geometry.pitch_m
        out["flank_pitch_diameter_m"] = trapezoidal.pitch_diameter(
            geometry.outer_diameter_m, geometry.pitch_m
        )
        out["flank_height_m"] = trapezoidal.flank_height(geometry.pitch_m)
    return out


def _thread_provenance(geometry: OwnGeometry, nut: NutMaterial | None) -> dict[str, Provenance]:
    """The thread values' provenance: the user's pitch, the basic profile's d2 and H1, the
    nut length the user gives or the nut material's family takes."""
    prov = {}
    if geometry.pitch_m is not None:
        prov["pitch"] = USER
        prov["flank_pitch_diameter"] = THREAD_RULE
        prov["flank_height"] = THREAD_RULE
    if geometry.nut_length_m is not None:
        prov["nut_length"] = USER
    elif nut is not None and nut.nut_length_to_d is not None:
        prov["nut_length"] = nut.provenance["nut_length"]
    return prov


def _with_nut_length(geometry: OwnGeometry, nut: NutMaterial | None) -> OwnGeometry:
    """The geometry with the nut length the nut material's family takes (its length over
    d times the screw's outer diameter) when the user gives none."""
    if geometry.nut_length_m is not None or nut is None or nut.nut_length_to_d is None:
        return geometry
    return replace(geometry, nut_length_m=nut.nut_length_to_d * geometry.outer_diameter_m)


def _nut(geometry: OwnGeometry, nut: NutMaterial | None) -> dict[str, object]:
    """The ScrewSpec values of the nut: its material's limits, and its flank pressure in
    motion from the maker's thrust table for this size (``nut_ratings.thrust_pressure``)."""
    if nut is None:
        return {}
    values: dict[str, object] = {**nut.limits, "nut_material": nut.name}
    values["oil_compatible"] = nut.oil_compatible
    values["lubricated_rating"] = nut.lubricated_rating
    values["dry_friction_dynamic"] = _dry(nut.dry_friction_dynamic, geometry.friction_dynamic)
    values["dry_friction_static"] = _dry(nut.dry_friction_static, geometry.friction_static)
    if nut.backlash_m is not None:
        values["backlash_min_m"], values["backlash_max_m"] = nut.backlash_m
    if nut.temperature_c is not None:
        values["temperature_min_c"], values["temperature_max_c"] = nut.temperature_c
    rated = _dynamic_pressure(geometry, nut)
    if rated is not None:
        values["dynamic_pressure_pa"] = rated[0]
    return values


def _dynamic_pressure(geometry: OwnGeometry, nut: NutMaterial) -> tuple[float, Provenance] | None:
    """The nut's flank pressure in motion [Pa] from its maker's thrust table for this size
    and nut length (``nut_ratings.thrust_pressure``), with its provenance; None without a
    table, a pitch or a nut length."""
    length, pitch = geometry.nut_length_m, geometry.pitch_m
    if nut.thrust_table is None or length is None or pitch is None:
        return None
    return thrust_pressure(nut.thrust_table, geometry.outer_diameter_m, pitch, length)


def own_screw(
    geometry: OwnGeometry, material: Material, material_name: str, nut: NutMaterial | None = None
) -> ScrewSpec:
    """The candidate "custom" from the user's ``geometry``, a ``material`` and a catalog
    ``nut`` material (None: no nut rating beyond a given PV limit). A value the screw
    lacks has the catalog's provenance of a value not given (``series.NOT_GIVEN``)."""
    rho = material.density_kg_m3.value
    inertia, inertia_source = screw_inertia(geometry, rho)
    strength = material.yield_strength_pa
    thread_provenance = _thread_provenance(geometry, nut)
    ends = _nut_ends(geometry, nut)
    geometry = _with_nut_length(geometry, nut)
    rated = None if nut is None else _dynamic_pressure(geometry, nut)
    provenance: dict[str, Provenance] = {
        **({} if strength is None else {"yield_strength": strength.provenance}),
        **dict.fromkeys(GEOMETRY_SOURCES, USER),
        "pv_limit": USER,
        "inertia_per_length": inertia_source,
        "youngs_modulus": material.youngs_modulus_pa.provenance,
        "density": material.density_kg_m3.provenance,
        "screw_expansion": material.expansion_per_k.provenance,
        **_conductivity_provenance(material),
        **({} if nut is None else _nut_provenance(nut, geometry)),
        **thread_provenance,
        **({} if rated is None else {"dynamic_pressure": rated[1]}),
    }
    if geometry.pv_limit_pa_m_s is None:
        provenance["pv_limit"] = NOT_GIVEN["pv_limit"]
    for name, not_given in NOT_GIVEN.items():
        provenance.setdefault(name, not_given)
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
        thermal_conductivity_w_m_k=_conductivity(material),
        provenance=provenance,
        assumption_ends={**ends, **material.ends},
        **_thread(geometry),  # type: ignore[arg-type]
        **_nut(geometry, nut),  # type: ignore[arg-type]
    )


def screw_inertia(geometry: OwnGeometry, density_kg_m3: float) -> tuple[float, Provenance]:
    """The screw's inertia per length [kg m^2/m] and its provenance: the user's, else a
    solid rod rho pi d_p^4 / 32 at the pitch diameter the torque takes, d2 = d - 0.5 P
    with a pitch (as the catalog derives an ISO screw's, catalog/README.md rule 9), else
    (d + d_r) / 2 (the seed's P_o). The root diameter would understate it: the seed's
    screws weigh in at 0.65-0.84 of a solid rod at the outer diameter (catalog-notes.md),
    a rod at a 0.78 d root at 0.37, and the screw's share of the accelerating torque with
    it. Valid for a thread whose flanks fill about half the depth (trapezoidal, Acme)."""
    if geometry.inertia_kg_m2_per_m is not None:
        return geometry.inertia_kg_m2_per_m, USER
    if geometry.pitch_m is None:
        d_p = thread_geometry.pitch_diameter(geometry.outer_diameter_m, geometry.root_diameter_m)
        rule = "(d + d_r) / 2"
    else:
        d_p = trapezoidal.pitch_diameter(geometry.outer_diameter_m, geometry.pitch_m)
        rule = "d2 = d - 0.5 P"
    inertia = torque.solid_rod_inertia_per_length(density_kg_m3, d_p)
    source = f"solid rod rho pi d_p^4 / 32 at the pitch diameter {rule}"
    return inertia, Provenance("derived", source)


def _nut_ends(geometry: OwnGeometry, nut: NutMaterial | None) -> Ends:
    """The ends of the nut material's ranged values, as a catalog screw of this size with
    that nut has them: its limits' (the wear rate's scatter), and the nut length's range
    over d where the user gives no nut length (the flank pressure in motion recomputed
    at each end). The user's own values (friction, a nut length given) have none."""
    if nut is None:
        return {}
    ratios = nut.nut_length_to_d_ends
    if geometry.nut_length_m is None and ratios is not None:
        low, high = (_nut_length_end(geometry, nut, r) for r in ratios)
        return {**nut.ends, NUT_LENGTH_RANGE: (low, high)}
    return dict(nut.ends)


def _nut_length_end(geometry: OwnGeometry, nut: NutMaterial, ratio: float) -> dict[str, float]:
    """The nut length at ``ratio`` x d, and the flank pressure in motion it gives."""
    length = ratio * geometry.outer_diameter_m
    rated = _dynamic_pressure(replace(geometry, nut_length_m=length), nut)
    end = {"nut_length_m": length}
    if rated is not None:
        end["dynamic_pressure_pa"] = rated[0]
    return end


def _conductivity_provenance(material: Material) -> dict[str, Provenance]:
    """The screw material's thermal conductivity's provenance, where it gives one (else
    the catalog's provenance of a value not given)."""
    k = material.thermal_conductivity_w_m_k
    return {} if k is None else {"thermal_conductivity": k.provenance}


def _conductivity(material: Material) -> float | None:
    k = material.thermal_conductivity_w_m_k
    return None if k is None else k.value


def _dry(run_dry: float | None, given: float) -> float | None:
    """The friction a nut the user describes rubs at run dry: its material's friction run
    dry, but never below the friction given for it (a nut whose friction the user measured
    higher keeps it); None where the material gives none."""
    return None if run_dry is None else max(run_dry, given)


#: The provenance of a friction run dry that is the one the user gave (``_dry``).
GIVEN_RUN_DRY = Provenance(
    "user", "given in the request; above the nut material's friction run dry, so kept run dry"
)


def _nut_provenance(nut: NutMaterial, geometry: OwnGeometry) -> dict[str, Provenance]:
    """The provenance of the values a nut material sets, under the catalog's keys; a
    friction run dry that is the one given, the user's (``_dry``)."""
    prov = {k: p for k, p in nut.provenance.items() if not k.startswith("friction")}
    prov["nut_material"] = Provenance("user", f"the catalog's {nut.key} nut ({nut.family})")
    for key, given in (
        ("dry_friction_dynamic", geometry.friction_dynamic),
        ("dry_friction_static", geometry.friction_static),
    ):
        run_dry = getattr(nut, key)
        if run_dry is not None and given > run_dry:
            prov[key] = GIVEN_RUN_DRY
    return prov
