"""Catalog candidates as columns, with every number that does not depend on the axis.

Built once per catalog (at start-up for the built-in one). The formula functions of the
core are plain arithmetic, so the same function serves one screw (a column of one) or
the whole catalog.
"""

import math
from collections.abc import Hashable, Sequence
from dataclasses import dataclass, fields
from functools import partial
from operator import attrgetter, eq
from typing import Any

import numpy as np
from numpy.typing import NDArray

from app.core.axis_free import axis_free, friction_columns, screw_terms
from app.core.formulas import (
    column_rules,
    critical_speed,
    efficiency,
    geometry,
    limits,
)
from app.core.model import ScrewSpec
from app.core.reach import Reach, reach_of

Array = NDArray[np.float64]
Mask = NDArray[np.bool_]


#: None (no such limit) to NaN; any other value to itself (``dict.get(v, v)``)
_NAN_FOR_NONE: dict[float | None, float] = {None: math.nan}


def column(values: Sequence[float | None]) -> Array:
    """Float column; None (no such limit) becomes NaN.

    ``np.fromiter`` reads a list of floats about twice as fast as ``np.array`` and stops
    with a TypeError at the first None; a column with some is then read again with each
    None looked up as NaN (``dict.get`` mapped in C), still faster than ``np.array``'s
    conversion of None (a column of 100,000 catalog values in 1-2 ms).

    >>> column([0.5, None, 2]).tolist()
    [0.5, nan, 2.0]
    """
    try:
        return np.fromiter(values, dtype=np.float64, count=len(values))
    except TypeError:
        nan = _NAN_FOR_NONE.get
        return np.fromiter(map(nan, values, values), dtype=np.float64, count=len(values))


def filled(n: int, value: float) -> Array:
    """A float column of ``n`` copies of ``value``: ``np.full(n, value)`` as float64, without
    its dtype inference (built a score of times per query).

    >>> filled(2, 0.5).tolist(), filled(1, 3).dtype
    ([0.5, 0.5], dtype('float64'))
    """
    out = np.empty(n)
    out.fill(value)
    return out


def finite(values: Array) -> Array:
    """NaN where a limit is unbounded (e.g. the PV speed limit with no thrust at all)."""
    return np.where(np.isfinite(values), values, np.nan)


def _bands(screws: Sequence[ScrewSpec], lead_m: Array) -> tuple[Array, Mask]:
    """Each screw's family traverse limit [m/s] (NaN without a table) and off-table flag;
    screws sharing a table are looked up together."""
    speeds, off = np.full(len(screws), np.nan), np.zeros(len(screws), dtype=bool)
    bands, which = _distinct(screws, "traverse_bands")
    for j, table in enumerate(bands):
        index = np.flatnonzero(which == j)
        speeds[index], off[index] = limits.band_limit(lead_m[index], table)
    return speeds, off


def _column_of(screws: Sequence[ScrewSpec], name: str) -> Array:
    """The float column of ScrewSpec field ``name`` (``column``: None becomes NaN)."""
    return column(list(map(attrgetter(name), screws)))


def _flag_of(screws: Sequence[ScrewSpec], name: str) -> Mask:
    """The boolean column of ScrewSpec field ``name``."""
    return np.fromiter(map(attrgetter(name), screws), dtype=bool, count=len(screws))


def _equals(screws: Sequence[ScrewSpec], name: str, value: str) -> Mask:
    """Whether each screw's ScrewSpec field ``name`` is ``value``."""
    same = map(partial(eq, value), map(attrgetter(name), screws))
    return np.fromiter(same, dtype=bool, count=len(screws))


def _makers_column(youngs_modulus_pa: Array, ball: Mask, hiwin: Mask) -> dict[str, Array]:
    """The makers' column rules of each screw of modulus ``youngs_modulus_pa``, ball
    screws ``ball`` of which ``hiwin`` are rated by HIWIN's buckling rule:
    ``makers_modulus_pa`` and ``makers_stress_pa``."""
    return {
        "makers_modulus_pa": column_rules.makers_column_modulus(youngs_modulus_pa, ball, hiwin),
        "makers_stress_pa": column_rules.makers_allowed_stress(ball, hiwin),
    }


def _pitch_diameter(od: Array, rd: Array, d2: Array, d0: Array) -> Array:
    """The diameter the thread's lead angle and friction are taken at [m]: a standard
    thread's pitch diameter (ISO 2904 d2 = d - 0.5 P), a ball screw's pitch circle
    diameter d0 (its nominal diameter, ISO 3408-1; the balls' centres run above the
    shaft's outer diameter); otherwise the seed's (OD + RD) / 2 (NaN: not given)."""
    given: Array = np.where(np.isnan(d2), d0, d2)
    return np.where(np.isnan(given), geometry.pitch_diameter(od, rd), given)


def _nut_columns(screws: Sequence[ScrewSpec], lead_m: Array, d2: Array) -> dict[str, Array]:
    """Thread and nut-rating columns (NaN where a family gives none): pitch, d2 (the
    column ``d2`` read), H1, nut length, the polymer limits, the wear rating and the helix
    of one turn at d2."""
    names = ("pitch_m", "flank_height_m", "nut_length_m")
    names += ("max_pressure_pa", "dynamic_pressure_pa", "nut_pv_limit_pa_m_s")
    names += ("max_sliding_speed_m_s",)
    names += ("wear_rate_m2_n", "allowed_wear_fraction")
    out = {name: _column_of(screws, name) for name in names}
    out["flank_pitch_diameter_m"] = d2
    out["flank_helix_travel_m"] = np.asarray(geometry.helix_travel(lead_m, d2), dtype=np.float64)
    return out


#: A table of rows of two numbers: a nut material's allowable pressure by sliding speed
#: (speed [m/s], pressure [Pa]), a ball screw's limit deviation by useful travel (l_u up
#: to [m], e_p [m]).
Rows = tuple[tuple[float, float], ...]


def _first_use(values: Sequence[Hashable]) -> tuple[list[Any], NDArray[np.intp]]:
    """The distinct ``values`` in order of first use, and each value's position among them.
    Equal values are mostly one object (a family's table, a series' id), so the values
    are told apart by identity first, in NumPy, and the distinct objects alone compared.

    >>> _first_use(["b", "a", "b", None])
    (['b', 'a', None], array([0, 1, 0, 2]))
    """
    ids = np.fromiter(map(id, values), dtype=np.uintp, count=len(values))
    _, first, objects = np.unique(ids, return_index=True, return_inverse=True)
    in_use = np.argsort(first)
    seen: dict[Hashable, int] = {}
    position = np.empty(len(first), dtype=np.intp)
    position[in_use] = [seen.setdefault(values[i], len(seen)) for i in first[in_use].tolist()]
    return list(seen), position[objects.reshape(-1)]


def _distinct(screws: Sequence[ScrewSpec], name: str) -> tuple[tuple[Rows, ...], NDArray[np.intp]]:
    """The distinct tables of ScrewSpec field ``name`` (nut pressure-speed tables, ball
    screws' travel deviation tables, traverse bands), in first use, and each screw's
    position in them (-1: none)."""
    values, which = _first_use(list(map(attrgetter(name), screws)))
    tables = tuple(t for t in values if t)
    renumber = np.array([tables.index(t) if t else -1 for t in values], dtype=np.intp)
    return tables, renumber[which]


def _renumbered(
    tables: tuple[Rows, ...], others: tuple[Rows, ...], which: NDArray[np.intp]
) -> tuple[tuple[Rows, ...], NDArray[np.intp]]:
    """``tables`` with those of ``others`` it lacks appended, and positions ``which`` in
    ``others`` as positions in the merged tables (-1, no table, stays -1)."""
    merged = tables + tuple(t for t in others if t not in tables)
    renumber = np.array([*map(merged.index, others), -1], dtype=np.intp)
    return merged, renumber[which]


#: Columns copied from each screw's catalog value as they are: column -> ScrewSpec field.
COPIED = {
    "youngs_modulus_pa": "youngs_modulus_pa",
    "density_kg_m3": "density_kg_m3",
    "screw_expansion_per_k": "screw_expansion_per_k",
    "inertia_kg_m2_per_m": "inertia_kg_m2_per_m",
    "drag_max_nm": "drag_torque_max_nm",
    "drag_min_nm": "drag_torque_min_nm",
    "pv_limit_pa_m_s": "pv_limit_pa_m_s",
    "design_load_n": "design_load_n",
    "max_length_m": "max_length_m",
    "life_min_m": "life_min_m",
    "life_max_m": "life_max_m",
    "lead_accuracy": "lead_accuracy_m_per_m",
    "backlash_max_m": "backlash_max_m",
    "temperature_min_c": "temperature_min_c",
    "temperature_max_c": "temperature_max_c",
    "yield_strength_pa": "yield_strength_pa",
    "thermal_conductivity_w_m_k": "thermal_conductivity_w_m_k",
    "dynamic_load_n": "dynamic_load_n",
    "static_load_n": "static_load_n",
    "dn_limit_mm_rpm": "dn_limit_mm_rpm",
    "preload_n": "preload_n",
    "travel_variation_300mm_m": "travel_variation_300mm_m",
    "dry_friction_dynamic": "dry_friction_dynamic",
    "dry_friction_static": "dry_friction_static",
}


@dataclass(frozen=True, slots=True)
class CandidateTable:
    """One element per candidate: catalog values (SI) and axis-independent derived ones."""

    screws: tuple[ScrewSpec, ...]
    lead_m: Array
    outer_diameter_m: Array
    root_diameter_m: Array
    pitch_diameter_m: Array
    thread_depth_m: Array
    helix_travel_m: Array
    lead_angle_rad: Array
    youngs_modulus_pa: Array
    density_kg_m3: Array
    screw_expansion_per_k: Array
    inertia_kg_m2_per_m: Array
    drag_max_nm: Array
    #: the bottom of the nut's drag range [N m]: a segment the load drives is worked at it
    #: too (``segments.moving_torques``), where the drag helps the motor brake
    drag_min_nm: Array
    pv_limit_pa_m_s: Array
    design_load_n: Array
    max_length_m: Array
    life_min_m: Array
    life_max_m: Array
    lead_accuracy: Array
    backlash_max_m: Array
    repeatability_m: Array
    temperature_min_c: Array
    temperature_max_c: Array
    coated: Mask
    anti_backlash: Mask
    oil_compatible: Mask
    lubricated_rating: Mask
    efficiency: Array
    efficiency_static: Array
    efficiency_square_thread: Array
    backdrive_efficiency: Array
    self_locking: Mask
    seed_rule_no_backdrive: Mask
    max_self_locking_lead_m: Array
    traverse_limit_m_s: Array
    traverse_extrapolated: Mask
    #: the thread's static and running friction, as the catalog gives them or as an axis
    #: runs the nut (``dry_run.as_run``), each column that follows from them formed by
    #: ``axis_free.friction_columns``; a nut rated lubricated's friction run dry (NaN:
    #: none), and whether the row is at it (``dry_run.as_run``; False as catalogued);
    #: whether a nut rated dry holds at its static friction eased by the axis's
    #: lubricant (``dry_run.as_run``; False as catalogued)
    friction_static: Array
    friction_dynamic: Array
    dry_friction_static: Array
    dry_friction_dynamic: Array
    runs_dry: Mask
    lubricant_eased: Mask
    cos_half_angle: Array
    backdrive_efficiency_running: Array
    #: running back-drive efficiency without the clip at 0 (negative: self-locking), for
    #: the torque of a segment where the load drives
    backdrive_efficiency_signed: Array
    #: the same at static friction, for the start from rest of a move the load drives (a
    #: thread that self-locks at static friction needs the motor to start lowering)
    start_backdrive_efficiency_signed: Array
    #: the same where the load drives a segment, at its unsafe end (the most the load
    #: drives the motor): a ball screw's at the low end of its maker's equivalent
    #: friction (HIWIN's 0.003 of 0.003 to 0.01, the friction it holds at), a sliding
    #: nut's at its running friction (its range's ends are screened by robustness)
    braking_backdrive_efficiency_signed: Array
    yield_strength_pa: Array
    thermal_conductivity_w_m_k: Array
    pitch_m: Array
    flank_pitch_diameter_m: Array
    flank_height_m: Array
    nut_length_m: Array
    max_pressure_pa: Array
    dynamic_pressure_pa: Array
    nut_pv_limit_pa_m_s: Array
    max_sliding_speed_m_s: Array
    wear_rate_m2_n: Array
    allowed_wear_fraction: Array
    flank_helix_travel_m: Array
    #: ball screws: the flag, Ca and C0a [N], the DN limit [mm rpm] and the nut's preload
    #: [N] (0: a nut with play; NaN: none)
    ball: Mask
    #: a ball screw whose maker rates its critical speed by HIWIN's rule, as its family
    #: declares (``critical_speed.rated_critical_speed_rpm``)
    hiwin_speed: Mask
    #: a ball screw's makers' column rules (its family's, else the lowest published):
    #: the Young's modulus their Euler load is taken with (``makers_column_modulus``) and
    #: the root stress they allow (``makers_allowed_stress``) [Pa]; inf: none (a leadscrew)
    makers_modulus_pa: Array
    makers_stress_pa: Array
    dynamic_load_n: Array
    static_load_n: Array
    dn_limit_mm_rpm: Array
    preload_n: Array
    #: a ball screw's ISO 3408-3 travel variation within 300 mm, v300p [m] (NaN: none)
    travel_variation_300mm_m: Array
    #: Axis-free numbers of the operating point (``_axis_free``): tan of ``lead_angle_rad``,
    #: the static friction at which the thread self-locks, the seed's contact area of
    #: three threads [m^2], the transition slenderness, the engaged flank area at the
    #: catalog's nut length [m^2] (NaN: no thread pitch or nut length), the screw's fin
    #: conductance [W/K] and fin parameter [1/m], the nut's outside diameter [m] and
    #: min(efficiency, efficiency_static).
    tan_lead_angle: Array
    self_locking_friction: Array
    contact_area_m2: Array
    transition_slenderness: Array
    catalog_flank_area_m2: Array
    fin_conductance_w_k: Array
    fin_m_per_m: Array
    nut_outer_diameter_m: Array
    root_efficiency: Array
    #: The root section's area [m^2], second moment [m^4] and pi d_r^3 [m^3]
    #: (``buckling``), sqrt(E / rho) [m/s] and the radius of gyration d_r / 4 [m]
    #: (``critical_speed.shaft_terms``).
    root_area_m2: Array
    root_second_moment_m4: Array
    root_pi_d_cubed_m3: Array
    wave_speed_m_s: Array
    root_gyration_m: Array
    #: 2 pi eta at the running and the static efficiency [rad] (``torque.efficient_turn``:
    #: what divides F lead in the torque that drives a load)
    efficient_turn_rad: Array
    start_efficient_turn_rad: Array
    #: The screw's own terms of the query's formulas (``axis_free.screw_terms``): the
    #: reflected inertia per kg of moving mass [m^2], the drag's work per turn [J], the
    #: thread's friction loss 1 / eta - 1 [-] and a ball screw's DN speed limit [rpm];
    #: whether the catalog gives each value of ``axis_free.GIVEN``; and the wear geometry
    #: at the catalog's nut length (``axis_free.wear_geometry``: area [m^2], allowed depth
    #: [m], sliding per travel [-]).
    reflected_inertia_per_kg_m2: Array
    drag_work_per_turn_j: Array
    friction_loss: Array
    dn_speed_limit_rpm: Array
    pv_limit_given: Mask
    max_length_given: Mask
    traverse_limit_given: Mask
    temperature_given: Mask
    max_sliding_speed_given: Mask
    design_load_given: Mask
    life_min_given: Mask
    life_max_given: Mask
    pitch_given: Mask
    travel_variation_given: Mask
    wear_area_m2: Array
    wear_depth_m: Array
    wear_sliding_per_travel: Array
    #: the nut's rated load in motion [N] and engaged length [m] at the catalog's nut
    #: length (``axis_free.nut_rating``)
    catalog_rated_load_n: Array
    catalog_engaged_length_m: Array

    #: each candidate's nut pressure-speed table, as a position in ``pressure_tables``
    #: (-1: none), so that candidates sharing a table are interpolated together
    pressure_table: NDArray[np.intp]
    #: each ball screw's table of limit deviation by useful travel, as a position in
    #: ``deviation_tables`` (-1: none, a transport class or a leadscrew)
    deviation_table: NDArray[np.intp]

    #: what the whole catalog offers; a subset (``take``) keeps its catalog's
    reach: Reach
    #: the distinct nut pressure-speed tables, (sliding speed [m/s], pressure [Pa]) rows
    pressure_tables: tuple[Rows, ...]
    #: the distinct tables of limit deviation by useful travel, (l_u up to [m], e_p [m])
    deviation_tables: tuple[Rows, ...]

    @classmethod
    def build(cls, screws: Sequence[ScrewSpec]) -> "CandidateTable":
        """Columns from screws, and the efficiencies and limits that follow from them."""
        screws = tuple(screws)
        col, flag = partial(_column_of, screws), partial(_flag_of, screws)
        od, rd, lead = col("outer_diameter_m"), col("root_diameter_m"), col("lead_m")
        d2 = col("flank_pitch_diameter_m")
        d_p = _pitch_diameter(od, rd, d2, col("pitch_circle_diameter_m"))
        tan_l = geometry.tan_lead_angle(lead, d_p)
        cos_a = np.cos(col("thread_half_angle_rad"))
        traverse, extrapolated = _bands(screws, lead)
        ball = _equals(screws, "screw_type", "ball")
        tables, which = _distinct(screws, "bearing_pressure_table")
        deviation_tables, deviation_table = _distinct(screws, "travel_deviation_bands")
        copied = {name: col(attr) for name, attr in COPIED.items()}
        anti_backlash = flag("anti_backlash")
        limits = (copied["design_load_n"], copied["max_length_m"], anti_backlash)
        reach = reach_of(screws, lead, rd, *limits)
        columns = dict(
            lead_m=lead,
            traverse_limit_m_s=traverse,
            pitch_diameter_m=d_p,
            thread_depth_m=geometry.thread_depth(od, rd),
            helix_travel_m=geometry.helix_travel(lead, d_p),
            lead_angle_rad=np.arctan(tan_l),
            cos_half_angle=cos_a,
            **copied,
            **_nut_columns(screws, lead, d2),
        )
        mu = (col("friction_static"), col("friction_dynamic"))
        columns |= friction_columns(tan_l, cos_a, d_p, *mu, ball)
        columns["root_diameter_m"], columns["outer_diameter_m"] = rd, od
        columns |= axis_free(columns)
        return cls(
            reach=reach,
            pressure_tables=tables,
            pressure_table=which,
            deviation_tables=deviation_tables,
            deviation_table=deviation_table,
            screws=screws,
            repeatability_m=np.nan_to_num(col("repeatability_m")),
            coated=flag("coated"),
            anti_backlash=anti_backlash,
            oil_compatible=flag("oil_compatible"),
            lubricated_rating=flag("lubricated_rating"),
            runs_dry=np.zeros(len(screws), dtype=bool),
            lubricant_eased=np.zeros(len(screws), dtype=bool),
            # the seed's rule of thumb is a sliding thread's: a ball screw always back-drives
            seed_rule_no_backdrive=efficiency.seed_backdrive_rule(lead, od) & ~ball,
            traverse_extrapolated=extrapolated,
            ball=ball,
            hiwin_speed=_equals(screws, "critical_speed_rule", critical_speed.HIWIN_RULE),
            **_makers_column(
                copied["youngs_modulus_pa"],
                ball,
                _equals(screws, "buckling_rule", column_rules.HIWIN_BUCKLING_RULE),
            ),
            **columns,
            **screw_terms(columns),
        )

    def take(self, index: NDArray[np.intp]) -> "CandidateTable":
        """The candidates at ``index``, in that order (the table itself for all of them)."""
        if len(index) == len(self) and bool(np.all(index == np.arange(len(self)))):
            return self
        picked = {name: getattr(self, name)[index] for name in COLUMNS}
        screws = self.screws
        return CandidateTable(
            screws=tuple([screws[i] for i in index.tolist()]),
            reach=self.reach,
            pressure_tables=self.pressure_tables,
            deviation_tables=self.deviation_tables,
            **picked,
        )

    def join(self, other: "CandidateTable") -> "CandidateTable":
        """This table's candidates followed by ``other``'s (this table's reach)."""
        joined = {
            name: np.concatenate((getattr(self, name), getattr(other, name))) for name in COLUMNS
        }
        n = len(self)
        tables, joined["pressure_table"][n:] = _renumbered(
            self.pressure_tables, other.pressure_tables, other.pressure_table
        )
        deviations, joined["deviation_table"][n:] = _renumbered(
            self.deviation_tables, other.deviation_tables, other.deviation_table
        )
        return CandidateTable(
            screws=self.screws + other.screws,
            reach=self.reach,
            pressure_tables=tables,
            deviation_tables=deviations,
            **joined,
        )

    def __len__(self) -> int:
        return len(self.screws)


#: The array fields of a table, in declaration order.
COLUMNS = tuple(
    f.name
    for f in fields(CandidateTable)
    if f.name not in ("screws", "reach", "pressure_tables", "deviation_tables")
)
