"""The candidate table's axis-free columns: numbers the operating point and the checks
read that follow from the catalog alone, each worked out once per catalog by the same
formula call the query would otherwise make (``table.CandidateTable``; ``c``: the table's
columns by name).
"""

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from app.core.formulas import (
    ballscrew,
    bearing,
    buckling,
    critical_speed,
    efficiency,
    heat,
    profile,
    pv,
    torque,
    wear,
)

Array = NDArray[np.float64]
Mask = NDArray[np.bool_]


def friction_columns(
    tan_l: Array,
    cos_a: Array,
    d_p: Array,
    mu_s: Array,
    mu_d: Array,
    ball: Mask,
    mu_hold: Array | None = None,
) -> dict[str, Any]:
    """Every column that follows from the thread's friction, static ``mu_s`` and running
    ``mu_d``, with the screw's geometry (tan of the lead angle ``tan_l``, cos of the
    flank half-angle ``cos_a``, the pitch diameter ``d_p`` [m]; ``ball``: a ball screw):
    the frictions themselves, the efficiencies driving
    and back-driven, running and from rest (the signed back-driven ones, negative where
    the thread self-locks, at ``mu_d``, at ``mu_s`` and where a load driving the screw is
    at its worst: a ball screw's at the low end of its maker's equivalent friction, the
    lower of ``mu_d`` and its holding friction), and whether the thread self-locks
    (``formulas.efficiency``, ``formulas.profile``; a ball screw drives at most at its
    maker's efficiency, ``ballscrew.forward_efficiency``), the longest self-locking
    lead, the lower of the two driving efficiencies (the root section's torque), 2 pi
    eta at each (``torque.efficient_turn``, the divisor of the torque that drives a
    load) and the friction loss per watt moved (``heat.friction_loss``). What holds the
    load at rest (the static friction the holding reads, the back-driven efficiency at
    rest, self-locking and the longest self-locking lead) is at ``mu_hold`` where it is
    given (a nut run dry holds at no more than its oiled static friction: it may be
    oiled later), else at ``mu_s``. Formed once per catalog, and again for the
    candidates an axis runs at another friction (``dry_run.as_run``)."""
    hold = mu_s if mu_hold is None else mu_hold

    def driving(mu: Array) -> Array:
        eta = efficiency.forward_efficiency(tan_l, mu, cos_a)
        return np.where(ball, ballscrew.forward_efficiency(eta), eta)

    eta, eta_s = driving(mu_d), driving(mu_s)
    with np.errstate(invalid="ignore", divide="ignore"):
        loss = heat.friction_loss(eta)
    return {
        "friction_static": hold,
        "friction_dynamic": mu_d,
        "efficiency": eta,
        "efficiency_static": eta_s,
        "efficiency_square_thread": efficiency.square_thread_efficiency(tan_l, mu_d),
        "backdrive_efficiency": efficiency.backdrive_efficiency(tan_l, hold, cos_a),
        "self_locking": hold >= efficiency.self_locking_limit_friction(tan_l, cos_a),
        "backdrive_efficiency_running": efficiency.backdrive_efficiency(tan_l, mu_d, cos_a),
        "backdrive_efficiency_signed": profile.signed_backdrive_efficiency(tan_l, mu_d, cos_a),
        "start_backdrive_efficiency_signed": profile.signed_backdrive_efficiency(
            tan_l, mu_s, cos_a
        ),
        "braking_backdrive_efficiency_signed": profile.signed_backdrive_efficiency(
            tan_l, np.where(ball, np.minimum(hold, mu_d), mu_d), cos_a
        ),
        "max_self_locking_lead_m": efficiency.max_self_locking_lead(d_p, hold, cos_a),
        "root_efficiency": np.minimum(eta, eta_s),
        "efficient_turn_rad": torque.efficient_turn(eta),
        "start_efficient_turn_rad": torque.efficient_turn(eta_s),
        "friction_loss": loss,
    }


def axis_free(c: dict[str, Array]) -> dict[str, Any]:
    """Numbers the operating point reads that follow from the catalog alone, each the
    same formula call it would make per query: tan of the lead angle and the static
    friction at which the thread self-locks (``efficiency``), the seed's contact area of
    three threads (``pv``), the transition slenderness (``buckling``), the engaged flank
    area at the catalog's nut length (``bearing``), the screw's endless fin conductance and fin
    parameter in still air and the nut's outside diameter (``heat``), and the root section's and the
    shaft's own terms of the column, stress and whirl formulas (``buckling``,
    ``critical_speed``). What follows from the friction is ``friction_columns``'s."""
    tan_l = np.tan(c["lead_angle_rad"])
    d_r, e = c["root_diameter_m"], c["youngs_modulus_pa"]
    with np.errstate(invalid="ignore", divide="ignore"):
        transition = buckling.transition_slenderness(e, c["yield_strength_pa"])
        wave, gyration = critical_speed.shaft_terms(d_r, e, c["density_kg_m3"])
    k, h = c["thermal_conductivity_w_m_k"], heat.FREE_CONVECTION_W_M2_K
    fin = heat.fin_conductance(d_r, k, h)
    nut_d = heat.NUT_OUTER_TO_D * c["outer_diameter_m"]
    flanks = bearing.engaged_flank_area(
        c["nut_length_m"], c["pitch_m"], c["flank_pitch_diameter_m"], c["flank_height_m"]
    )
    return {
        "tan_lead_angle": tan_l,
        "self_locking_friction": efficiency.self_locking_limit_friction(tan_l, c["cos_half_angle"]),
        "contact_area_m2": pv.contact_area(c["helix_travel_m"], c["thread_depth_m"]),
        "transition_slenderness": transition,
        "catalog_flank_area_m2": np.asarray(flanks, dtype=np.float64),
        "fin_conductance_w_k": fin,
        "fin_m_per_m": heat.fin_parameter(d_r, k, h),
        "nut_outer_diameter_m": nut_d,
        "root_area_m2": buckling.root_area(d_r),
        "root_second_moment_m4": buckling.second_moment_round(d_r),
        "root_pi_d_cubed_m3": buckling.root_pi_d_cubed(d_r),
        "wave_speed_m_s": wave,
        "root_gyration_m": gyration,
    }


def wear_geometry(
    flank_area_m2: Array, column: Callable[[str], Array]
) -> tuple[Array, Array, Array]:
    """What the nut's wear (``nut.wear_life``, Archard) runs over: the engaged flanks of a
    standard thread (area ``flank_area_m2``, not NaN; flank height; the helix at d2),
    else the seed's three threads (contact area, thread depth, the helix at the pitch
    diameter): the area that carries the thrust [m^2], the allowed wear depth [m] and
    the sliding per travel [-] (``wear.sliding_per_travel``); ``column``: the table's
    columns by name."""
    flanks = ~np.isnan(flank_area_m2)
    area = np.where(flanks, flank_area_m2, column("contact_area_m2"))
    height = np.where(flanks, column("flank_height_m"), column("thread_depth_m"))
    helix = np.where(flanks, column("flank_helix_travel_m"), column("helix_travel_m"))
    depth = column("allowed_wear_fraction") * height
    per_travel: Array = wear.sliding_per_travel(helix, column("lead_m"))
    return area, depth, per_travel


#: The catalog values whose presence (not NaN) the query reads, by their mask's column: a
#: limit a check judges where given, a rating or a life that replaces or caps another.
GIVEN = {
    "pv_limit_given": "pv_limit_pa_m_s",
    "max_length_given": "max_length_m",
    "traverse_limit_given": "traverse_limit_m_s",
    "temperature_given": "temperature_min_c",
    "max_sliding_speed_given": "max_sliding_speed_m_s",
    "design_load_given": "design_load_n",
    "life_min_given": "life_min_m",
    "life_max_given": "life_max_m",
    "pitch_given": "pitch_m",
    "travel_variation_given": "travel_variation_300mm_m",
}


def nut_rating(
    flank_area_m2: Array, nut_length_m: Array, column: Callable[[str], Array]
) -> tuple[Array, Array]:
    """The axial load a nut is rated to carry in motion [N]: its size's design load where
    the catalog gives one, else its dynamic flank pressure over the engaged flank area
    ``flank_area_m2`` (``bearing.dynamic_load``; NaN: neither); and the nut length whose
    turns carry the load [m] (``nut_length_m``; NaN without a thread pitch). ``column``:
    the table's columns by name."""
    dynamic = bearing.dynamic_load(column("dynamic_pressure_pa"), flank_area_m2)
    rated = np.where(column("design_load_given"), column("design_load_n"), dynamic)
    return rated, np.where(column("pitch_given"), nut_length_m, np.nan)


#: The nut's rating at the catalog's nut length (``nut_rating``), by its columns.
RATING = ("catalog_rated_load_n", "catalog_engaged_length_m")
#: The wear geometry at the catalog's nut length (``wear_geometry``), by its columns.
WEAR = ("wear_area_m2", "wear_depth_m", "wear_sliding_per_travel")


def screw_terms(c: dict[str, Array]) -> dict[str, Any]:
    """The screw's own terms of formulas the query works per candidate: the moving mass's
    reflected inertia per kilogram (``torque.reflected_mass_inertia`` at 1 kg), the
    nut's drag work per turn (``heat.drag_work_per_turn``) and a ball screw's DN speed limit
    (``ballscrew.dn_speed_limit``); where the catalog gives each value of ``GIVEN`` (not
    NaN); and the nut's wear geometry and rating at the catalog's nut length (``WEAR``,
    ``RATING``)."""
    given = {mask: ~np.isnan(c[name]) for mask, name in GIVEN.items()}
    rating = nut_rating(c["catalog_flank_area_m2"], c["nut_length_m"], (c | given).__getitem__)
    return {
        "reflected_inertia_per_kg_m2": torque.reflected_mass_inertia(1.0, c["lead_m"]),
        "drag_work_per_turn_j": heat.drag_work_per_turn(c["drag_max_nm"]),
        "dn_speed_limit_rpm": ballscrew.dn_speed_limit(
            c["dn_limit_mm_rpm"],
            ballscrew.dn_diameter(c["outer_diameter_m"], c["pitch_diameter_m"]),
        ),
        **given,
        **dict(zip(WEAR, wear_geometry(c["catalog_flank_area_m2"], c.__getitem__), strict=True)),
        **dict(zip(RATING, rating, strict=True)),
    }
