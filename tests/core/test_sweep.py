"""The lead sweep (app.core.sweep): one size and nut at every lead, screened for an
application; each point equals the full evaluation of that screw."""

import math
from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.core.evaluate import evaluate
from app.core.index import size_of
from app.core.model import Application
from app.core.sweep import lead_sweep

APP = Application(load_n=100.0, speed_m_s=0.05, length_m=0.5, lead_m=0.01)
#: the torque the results show (and the drive-torque check judges) before the safety factor
SF = APP.torque_safety_factor
B8000 = ("B8000", "polyacetal", False, False)


def test_every_lead_of_the_size_in_order(catalog: Catalog) -> None:
    """B8000 uncoated: its 18 leads, shortest first, whatever lead the application asks
    for (the sweep is about choosing it)."""
    sweep = lead_sweep(APP, catalog.index, B8000)
    leads_mm = [round(p.lead_m * 1e3, 6) for p in sweep]
    assert leads_mm == [1, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 12.7, 15, 20, 25, 25.4, 30, 40, 50]
    assert lead_sweep(replace(APP, lead_m=0.002), catalog.index, B8000) == sweep


def test_each_point_equals_the_evaluation_of_its_screw(catalog: Catalog) -> None:
    """Drive torque (the peak of the moving segments and the start, which the check judges
    times the safety factor), speed share (n / n_allowed) and PV share (the PV check's
    utilisation) of every lead equal ``evaluate`` of that screw."""
    screws = [s for s in catalog.series["B8000"].screws if not s.coated]
    by_lead = {s.lead_m: s for s in screws}
    sweep = lead_sweep(APP, catalog.index, B8000)
    assert len(sweep) == len(screws)
    for point in sweep:
        ev = evaluate(APP, by_lead[point.lead_m])
        assert point.torque_nm == pytest.approx(ev.torque.required_nm / SF, rel=1e-12)
        allowed = ev.critical_speed.allowed_rpm
        assert point.speed_share == pytest.approx(ev.rpm / allowed, rel=1e-12)
        pv = next(c for c in ev.checks if c.name == "pv")
        assert point.pv_share == pytest.approx(pv.utilization, rel=1e-12)


def test_the_speed_share_at_10_mm_by_hand(catalog: Catalog) -> None:
    """50 mm/s on a 10 mm lead is n = 300 rpm. The critical speed of the 500 mm leadscrew
    fixed-simple is its makers' (Thomson, Roton): C_s 1.47 times the simple-simple
    n_ss = 60 / (2 pi) (pi / L)^2 sqrt(E / rho) d_r / 4 (Blevins, table 8-1, beta = pi),
    below the beam's (3.92660 / pi)^2 = 1.562; allowed at 0.8 n_c."""
    screw = catalog.by_id["B8000-L10"]
    length = 0.5
    n_ss = (
        60
        / (2 * math.pi)
        * (math.pi / length) ** 2
        * math.sqrt(screw.youngs_modulus_pa / screw.density_kg_m3)
        * screw.root_diameter_m
        / 4
    )
    n_c = 1.47 * n_ss
    (point,) = [p for p in lead_sweep(APP, catalog.index, B8000) if p.lead_m == 0.01]
    assert point.speed_share == pytest.approx(300.0 / (0.8 * n_c), rel=1e-5)


def test_a_size_the_catalog_lacks_has_no_sweep(catalog: Catalog) -> None:
    assert lead_sweep(APP, catalog.index, ("B8000", "polyacetal", True, True)) == []


def test_a_trapezoidal_size_sweeps_its_own_nut_material(catalog: Catalog) -> None:
    """Tr12 P3 comes with bronze, acetal and PTFE nuts at leads 3 and 6 mm (one and two
    starts); the sweep of the bronze nut holds the bronze screws alone, one per lead."""
    size = size_of(catalog.by_id["Tr12x3-bronze"])
    sweep = lead_sweep(APP, catalog.index, size)
    assert [round(p.lead_m * 1e3, 6) for p in sweep] == [3.0, 6.0]
    for point, sid in zip(sweep, ("Tr12x3-bronze", "Tr12x6(P3)-bronze"), strict=True):
        ev = evaluate(APP, catalog.by_id[sid])
        assert point.torque_nm == pytest.approx(ev.torque.required_nm / SF, rel=1e-12)


def test_with_a_move_each_point_is_the_torque_the_results_show(catalog: Catalog) -> None:
    """With a stroke the results show the peak motor torque of the move, break-away
    included (``selection.shown_torque``), not the torque while accelerating. An oiled
    bronze nut lifting 150 N and 10 kg at 20 mm/s (0.5 m/s^2 over a 400 mm stroke) on the
    23HS32-4004S's 530 g cm^2 rotor starts harder than it accelerates (static friction):
    Tr14x3-bronze needs 0.4044 N m accelerating up and 0.4550 N m starting from rest, its
    results' peak; the 6 mm lead 0.4977 and 0.5504 N m. Each point is that peak."""
    app = Application(
        load_n=150.0, speed_m_s=0.02, length_m=0.6, accel_m_s2=0.5, moving_mass_kg=10.0,
        orientation="vertical", stroke_m=0.4, motor_inertia_kg_m2=530e-7, lubrication="oiled",
    )  # fmt: skip
    sweep = lead_sweep(app, catalog.index, size_of(catalog.by_id["Tr14x3-bronze"]))
    for point, sid in zip(sweep, ("Tr14x3-bronze", "Tr14x6(P3)-bronze"), strict=True):
        ev = evaluate(replace(app, lead_m=point.lead_m), catalog.by_id[sid])
        peak = ev.torque.required_nm  # the peak times the torque safety factor, 1
        assert peak > ev.torque.total_nm
        assert point.torque_nm == pytest.approx(peak, rel=1e-12)
    assert [round(p.torque_nm, 4) for p in sweep] == [0.4550, 0.5504]


def test_an_iso_nuts_flank_pressure_share_is_its_check_at_every_lead(catalog: Catalog) -> None:
    """Tr8 (P2, 304 steel) with a bronze nut, made in leads 2, 4 and 8 mm (one, two and
    four starts): each lead's flank pressure share equals the nut contact pressure check's
    utilisation when that screw is evaluated; it falls as the lead grows (at 20 mm/s a
    longer lead turns the screw slower, so the flanks slide slower and bronze allows more
    pressure). The polymer nut B8000 has no flank data: no share."""
    app = Application(load_n=300.0, speed_m_s=0.02, length_m=0.5, lead_m=0.004)
    size = ("Tr8-P2-304", "bronze", False, False)
    sweep = lead_sweep(app, catalog.index, size)
    screws = [catalog.index.table.screws[r] for r in catalog.index.sizes[size]]
    assert [p.lead_m for p in sweep] == [s.lead_m for s in screws] == [0.002, 0.004, 0.008]
    for point, screw in zip(sweep, screws, strict=True):
        ev = evaluate(replace(app, lead_m=None), screw)
        check = next(c for c in ev.checks if c.name == "bearing_pressure")
        assert point.pressure_share == pytest.approx(check.utilization, rel=1e-12)
        assert point.pv_share is None
    shares = [p.pressure_share or 0.0 for p in sweep]
    assert shares == sorted(shares, reverse=True) and shares[-1] > 0
    assert all(p.pressure_share is None for p in lead_sweep(APP, catalog.index, B8000))
