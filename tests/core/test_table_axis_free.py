"""The candidate table's axis-free columns: each is the formula call the operating point
would make per query, worked out once at load, to the bit."""

import dataclasses
from functools import partial

import numpy as np
import pytest

from app.catalog import Catalog
from app.core.axis_free import GIVEN, RATING, WEAR, nut_rating, wear_geometry
from app.core.formulas import (
    ballscrew,
    bearing,
    buckling,
    critical_speed,
    efficiency,
    heat,
    pv,
    torque,
)
from app.core.model import Application
from app.core.quantities import operating_point
from app.core.table import CandidateTable


@pytest.fixture(scope="module")
def table(catalog: Catalog) -> CandidateTable:
    return catalog.index.table


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    """Equal element by element, NaN where the other is NaN."""
    return bool(np.array_equal(np.asarray(a), np.asarray(b), equal_nan=True))


def test_each_axis_free_column_is_its_formula(table: CandidateTable) -> None:
    t = table
    tan_l = np.tan(t.lead_angle_rad)
    with np.errstate(invalid="ignore", divide="ignore"):
        transition = buckling.transition_slenderness(t.youngs_modulus_pa, t.yield_strength_pa)
    h = heat.FREE_CONVECTION_W_M2_K
    expected = {
        "tan_lead_angle": tan_l,
        "self_locking_friction": efficiency.self_locking_limit_friction(tan_l, t.cos_half_angle),
        "contact_area_m2": pv.contact_area(t.helix_travel_m, t.thread_depth_m),
        "transition_slenderness": transition,
        "catalog_flank_area_m2": bearing.engaged_flank_area(
            t.nut_length_m, t.pitch_m, t.flank_pitch_diameter_m, t.flank_height_m
        ),
        "fin_conductance_w_k": heat.fin_conductance(
            t.root_diameter_m, t.thermal_conductivity_w_m_k, h
        ),
        "fin_m_per_m": heat.fin_parameter(t.root_diameter_m, t.thermal_conductivity_w_m_k, h),
        "nut_outer_diameter_m": heat.NUT_OUTER_TO_D * t.outer_diameter_m,
        "root_efficiency": np.minimum(t.efficiency, t.efficiency_static),
        "root_area_m2": buckling.root_area(t.root_diameter_m),
        "root_second_moment_m4": buckling.second_moment_round(t.root_diameter_m),
        "root_pi_d_cubed_m3": buckling.root_pi_d_cubed(t.root_diameter_m),
        "wave_speed_m_s": (t.youngs_modulus_pa / t.density_kg_m3) ** 0.5,
        "root_gyration_m": t.root_diameter_m / 4.0,
        "efficient_turn_rad": torque.efficient_turn(t.efficiency),
        "start_efficient_turn_rad": torque.efficient_turn(t.efficiency_static),
        "reflected_inertia_per_kg_m2": torque.reflected_mass_inertia(1.0, t.lead_m),
        "drag_work_per_turn_j": heat.drag_work_per_turn(t.drag_max_nm),
        "friction_loss": 1.0 / t.efficiency - 1.0,
        # the larger of the outer and the pitch circle diameter (a ball screw's nominal)
        "dn_speed_limit_rpm": ballscrew.dn_speed_limit(
            t.dn_limit_mm_rpm, np.maximum(t.outer_diameter_m, t.pitch_diameter_m)
        ),
        **{mask: ~np.isnan(getattr(t, name)) for mask, name in GIVEN.items()},
        **dict(zip(WEAR, wear_geometry(t.catalog_flank_area_m2, partial(getattr, t)), strict=True)),
        **dict(
            zip(
                RATING,
                nut_rating(t.catalog_flank_area_m2, t.nut_length_m, partial(getattr, t)),
                strict=True,
            )
        ),
    }
    assert {
        name: _same(getattr(t, name), value) for name, value in expected.items()
    } == dict.fromkeys(expected, True)


def test_a_nut_length_typed_as_the_catalogs_gives_the_catalogs_flank_area(
    table: CandidateTable,
) -> None:
    """The user's nut length goes through the formula per query; typed equal to a
    screw's catalog length it must give the area worked out at load."""
    rows = np.flatnonzero(~np.isnan(table.catalog_flank_area_m2))
    assert rows.size
    one = table.take(rows[:1])
    app = Application(load_n=100.0, speed_m_s=0.05, length_m=0.5)
    typed = dataclasses.replace(app, nut_length_m=float(one.nut_length_m[0]))
    catalog_area = operating_point(app, one).nut.flank_area_m2
    typed_area = operating_point(typed, one).nut.flank_area_m2
    assert catalog_area[0] > 0.0
    assert typed_area[0] == catalog_area[0]


def test_von_mises_of_the_two_root_stresses_is_the_combined_formula() -> None:
    """Shigley 9th ed., Example 8-1 (F = 6.4 kN, T_R = 26.18 N m, d_r = 28 mm): the body's
    combined stress 14.79 MPa, the same from its two stresses as from the load and
    torque."""
    sigma = buckling.root_stress(6.4e3, 0.028)
    tau = buckling.root_shear_stress(26.18, 0.028)
    combined = buckling.root_von_mises_stress(6.4e3, 26.18, 0.028)
    assert buckling.von_mises_stress(sigma, tau) == combined
    assert combined / 1e6 == pytest.approx(14.79, abs=0.005)


@pytest.mark.parametrize("fixity", ["fixed-free", "simple-simple", "fixed-simple", "fixed-fixed"])
@pytest.mark.parametrize("length_m", [0.05, 0.3, 1.5])
def test_the_column_and_whirl_formulas_give_the_same_numbers_from_the_columns(
    table: CandidateTable, fixity: str, length_m: float
) -> None:
    """Each formula from the table's worked-out terms, to the bit, at lengths where
    Johnson (short) and Euler (slender) govern."""
    t = table
    d_r, e, s_y = t.root_diameter_m, t.youngs_modulus_pa, t.yield_strength_pa
    with np.errstate(invalid="ignore", divide="ignore"):
        whole = buckling.column_critical_load(e, d_r, length_m, fixity, s_y)
    section = (t.root_area_m2, t.root_second_moment_m4, t.transition_slenderness)
    s = buckling.slenderness(d_r, length_m, fixity)
    pieces = buckling.column_critical_load(
        e, d_r, length_m, fixity, s_y, section=section, slenderness_ratio=s
    )
    assert _same(pieces, whole)
    # the shortest column is Johnson's for some screws, the longest Euler's for some
    short = s < t.transition_slenderness
    if length_m == 0.05:
        assert bool(np.any(short))
    if length_m == 1.5:
        assert bool(np.any(~short))
    rho = t.density_kg_m3
    assert _same(
        critical_speed.critical_speed_rpm(
            d_r, length_m, e, rho, fixity, (t.wave_speed_m_s, t.root_gyration_m)
        ),
        critical_speed.critical_speed_rpm(d_r, length_m, e, rho, fixity),
    )
    torque_nm = np.linspace(0.01, 5.0, len(t))
    assert _same(
        buckling.root_shear_stress(torque_nm, d_r, t.root_pi_d_cubed_m3),
        buckling.root_shear_stress(torque_nm, d_r),
    )
    assert _same(
        buckling.root_stress(1234.5, d_r, t.root_area_m2), buckling.root_stress(1234.5, d_r)
    )


def test_the_seed_pv_from_the_contact_area_column_is_the_formulas(table: CandidateTable) -> None:
    t = table
    rpm = np.linspace(10.0, 3000.0, len(t))
    whole = pv.pv_value(250.0, rpm, t.helix_travel_m, t.thread_depth_m)
    assert _same(
        pv.pv_value(250.0, rpm, t.helix_travel_m, t.thread_depth_m, t.contact_area_m2), whole
    )
