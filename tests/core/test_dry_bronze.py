"""A bronze nut run dry is worked at its dry friction (``app.core.dry_run``).

The catalog's bronze nut is rated lubricated: its friction 0.13 is steel on bronze with
machine oil, 0.10-0.16 (Shigley's Mechanical Engineering Design, Table 8-5, after
Rothbart). Run dry the same table gives 0.15-0.23: the catalog takes the middle, 0.19, a
range from the oiled low end 0.10 (the nut may be oiled later; holding is judged there)
to the dry top 0.23 (torque), and static friction 1.25 x running as for the oiled nut
(0.24, from 0.13 to 0.29).
"""

import math
from dataclasses import replace

import numpy as np
import pytest

from app.catalog import Catalog
from app.catalog.own import OwnGeometry, own_screw
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.robustness import build_variants
from app.core.screening import screen_table
from app.core.selection import select, with_robustness

#: Tr20x4 (ISO 2904): lead 4 mm, pitch diameter d2 = d - 0.5 P = 18 mm, flank angle 30 deg
LEAD, D2, HALF_ANGLE = 0.004, 0.018, math.radians(15.0)
AXIS = Application(load_n=1000.0, speed_m_s=0.02, length_m=0.5)


def raise_torque(force_n: float, mu: float) -> float:
    """Torque to drive a load ``force_n`` up a trapezoidal thread [N m], Shigley eq. 8-1
    with the flank angle's sec(alpha) on the friction (eq. 8-5 style):
    T = F d_m / 2 (l + pi mu d_m sec a) / (pi d_m - mu l sec a), with d_m the pitch
    diameter d2 (the thread's normal flank angle taken as alpha, as the app does)."""
    sec = 1.0 / math.cos(HALF_ANGLE)
    return force_n * D2 / 2.0 * (LEAD + math.pi * mu * D2 * sec) / (math.pi * D2 - mu * LEAD * sec)


def test_the_torque_shown_is_at_the_dry_friction_when_the_nut_runs_dry(catalog: Catalog) -> None:
    """Tr20x4 bronze at 1000 N: by hand, oiled (mu 0.13) 1000 x 0.009 x (4 + pi 0.13 18
    1.03528) / (pi 18 - 0.13 x 4 x 1.03528) = 1.8657 N m; dry (mu 0.19) 2.4409 N m, 31 %
    more. The load torque shown is the dry one when the nut runs dry (the default), the
    oiled one when it is oiled or greased."""
    screw = catalog.by_id["Tr20x4-bronze"]
    oiled_nm, dry_nm = raise_torque(1000.0, 0.13), raise_torque(1000.0, 0.19)
    assert (oiled_nm, dry_nm) == pytest.approx((1.8657, 2.4409), abs=1e-4)
    dry = evaluate(AXIS, screw)
    assert AXIS.lubrication == "dry"
    assert dry.quantities.torque.load_nm == pytest.approx(dry_nm, rel=1e-9)
    for lubrication in ("oiled", "greased"):
        oiled = evaluate(replace(AXIS, lubrication=lubrication), screw)
        assert oiled.quantities.torque.load_nm == pytest.approx(oiled_nm, rel=1e-9)
    # the efficiency, the friction heat's loss and the start (static 0.24) follow
    assert dry.efficiency == pytest.approx(1000.0 * LEAD / (2 * math.pi * dry_nm), rel=1e-9)
    assert dry.quantities.torque.breakaway_nm > dry.quantities.torque.total_nm


def test_the_friction_shown_says_it_is_the_dry_one(catalog: Catalog) -> None:
    """The candidate's screw and its provenance name the dry friction; the advice says the
    numbers are the dry friction's and the pressure and wear ratings a lubricated nut's."""
    screw = catalog.by_id["Tr20x4-bronze"]
    dry = evaluate(AXIS, screw)
    assert (dry.screw.friction_dynamic, dry.screw.friction_static) == (0.19, 0.24)
    assert "run dry" in dry.provenance["friction_dynamic"].source
    assert "dry 0.15-0.23" in dry.provenance["friction_dynamic"].source
    assert "run dry" in dry.provenance["friction_static"].source
    (advice,) = [c for c in dry.checks if c.name == "lubrication"]
    assert not advice.passed and advice.kind == "advice"
    said = advice.message.template
    assert "dry friction" in said and "still a lubricated nut's" in said
    assert advice.message.values["mu_d"].value == 0.19
    oiled = evaluate(replace(AXIS, lubrication="oiled"), screw)
    assert (oiled.screw.friction_dynamic, oiled.screw.friction_static) == (0.13, 0.16)
    assert "machine oil" in oiled.provenance["friction_dynamic"].source


def test_robustness_runs_the_dry_nut_at_the_ends_of_its_range(catalog: Catalog) -> None:
    """The dry running friction's variant rows run at 0.10 and 0.23 (the torque by hand at
    each), its static friction's start at 0.13 and 0.29 and hold at no more than the oiled
    0.16 (0.13 and 0.16); every other row at the dry 0.19. Oiled, the same rows run at the
    oiled values (0.13, the oiled ends 0.10 and 0.16)."""
    screw = catalog.by_id["Tr20x4-bronze"]
    variants = build_variants([screw])
    names = np.array(variants.names)
    dry = screen_table(AXIS, variants.table)
    running = dry.table.friction_dynamic[names == "dry_friction_dynamic"]
    assert running.tolist() == [0.10, 0.23]
    torques = dry.quantities.torque.load_nm[names == "dry_friction_dynamic"]
    assert torques == pytest.approx([raise_torque(1000.0, 0.10), raise_torque(1000.0, 0.23)])
    ends = names == "dry_friction_static"
    assert dry.table.friction_static[ends].tolist() == [0.13, 0.16]
    # the start at each end: eta = cos a - mu tan l over cos a + mu / tan l (ISO 2904 d2)
    tan_l, cos_a = LEAD / (math.pi * D2), math.cos(HALF_ANGLE)
    start = [(cos_a - mu * tan_l) / (cos_a + mu / tan_l) for mu in (0.13, 0.29)]
    assert dry.table.efficiency_static[ends] == pytest.approx(start, rel=1e-9)
    others = ~np.isin(names, ["dry_friction_dynamic", "dry_friction_static"])
    assert set(dry.table.friction_dynamic[others & (names != "friction_dynamic")]) == {0.19}
    oiled = screen_table(replace(AXIS, lubrication="oiled"), variants.table)
    assert oiled.table.friction_dynamic[names == "friction_dynamic"].tolist() == [0.10, 0.16]
    assert set(oiled.table.friction_dynamic[names == "dry_friction_dynamic"]) == {0.13}


def test_holding_is_still_judged_at_the_oiled_low_end(catalog: Catalog) -> None:
    """A 20 kg vertical axis held by the thread alone on Tr20x4 bronze: it self-locks with
    margin while f mu_s >= cos 15 tan(lambda) = 0.96593 x 4 / (pi 18) = 0.06833. Run dry it
    starts at 0.24 but holds at no more than the oiled 0.16 (the nut may be oiled later):
    0.5 x 0.16 = 0.08 holds, and the longest self-locking lead is pi 18 x 0.16 / cos 15 =
    9.367 mm, not the dry 0.24's 14.05 mm; both ranges reach down to 0.13 static
    (0.5 x 0.13 = 0.065 < 0.06833): it is marginal, hinging on both."""
    screw = catalog.by_id["Tr20x4-bronze"]
    limit = math.cos(HALF_ANGLE) * LEAD / (math.pi * D2)
    assert limit == pytest.approx(0.06833, abs=1e-5)
    assert 0.5 * 0.13 < limit <= 0.5 * 0.24
    app = Application(
        load_n=0.0, moving_mass_kg=20.0, orientation="vertical", speed_m_s=0.02, length_m=0.5
    )
    judged = with_robustness(app, evaluate(app, screw), build_variants([screw]), 0)
    assert judged.passed and judged.self_locking_with_margin
    lead = math.pi * D2 * 0.16 / math.cos(HALF_ANGLE)
    assert judged.max_self_locking_lead_m == pytest.approx(lead, rel=1e-9)
    assert lead == pytest.approx(0.009367, abs=1e-6)
    assert (judged.robust, set(judged.hinges_on)) == (
        False,
        {"friction_static", "dry_friction_static"},
    )
    variants = build_variants([screw])
    low = variants.names.index("dry_friction_static")
    at_low = screen_table(app, variants.table)
    assert at_low.table.friction_static[low] == 0.13
    assert not at_low.passed[low]


def test_a_screw_of_ones_own_with_the_bronze_nut_runs_dry_alike(catalog: Catalog) -> None:
    """The catalog's bronze nut on a screw of one's own: run dry it takes the nut's dry
    friction in place of the friction typed, as the catalog's Tr20x4 does."""
    geometry = OwnGeometry(
        outer_diameter_m=0.020, root_diameter_m=0.0155, lead_m=LEAD,
        thread_half_angle_rad=HALF_ANGLE, friction_static=0.16, friction_dynamic=0.13,
        pitch_m=0.004,
    )  # fmt: skip
    material = catalog.materials["c45-steel"]
    mine = own_screw(geometry, material, "C45", catalog.nut_materials["bronze"])
    dry = evaluate(AXIS, mine)
    assert dry.quantities.torque.load_nm == pytest.approx(raise_torque(1000.0, 0.19), rel=1e-9)
    assert "run dry" in dry.provenance["friction_dynamic"].source
    typed = evaluate(replace(AXIS, lubrication="greased"), mine)
    assert typed.quantities.torque.load_nm == pytest.approx(raise_torque(1000.0, 0.13), rel=1e-9)
    assert typed.provenance["friction_dynamic"].kind == "user"


def test_a_lubricated_polymer_nut_holds_at_its_eased_friction(catalog: Catalog) -> None:
    """Tr12x3-acetal lifting 20 kg: dry it holds at its static friction 0.2, half of it
    counted (0.1 against cos 15 deg tan lambda = 0.0878): self-locking with margin.
    Oiled, its PV is credited twice the dry rating because the oil takes the friction heat
    away (pv_derating: BNB's "up to 100 %"); the friction falls as much, 0.1, and half of
    it, 0.05, holds nothing: the screw back-drives. Greased, 0.2 / 1.3. It was held at its
    dry friction whatever its lubrication, and passed without a brake."""
    screw = catalog.by_id["Tr12x3-acetal"]
    base = Application(
        load_n=0.0, moving_mass_kg=20.0, orientation="vertical", speed_m_s=0.01,
        length_m=0.5, stroke_m=0.3, dwell_s=30.0,
    )  # fmt: skip
    dry = evaluate(base, screw)
    assert dry.screw.friction_static == 0.2 and dry.self_locking_with_margin and dry.passed
    for lubrication, factor in (("oiled", 2.0), ("greased", 1.3)):
        ev = evaluate(replace(base, lubrication=lubrication), screw)
        assert ev.screw.friction_static == pytest.approx(0.2 / factor, rel=1e-12)
        assert not ev.self_locking_with_margin
        assert "back_driving" in {c.name for c in ev.failed_checks}
        provenance = ev.value_provenance["friction_static"]
        assert provenance.kind == "assumed" and "lowered by its lubricant" in provenance.source
    # a bronze nut's friction is an oiled nut's already: oiling it changes nothing
    bronze = catalog.by_id["Tr12x3-bronze"]
    oiled = evaluate(replace(base, lubrication="oiled"), bronze)
    assert oiled.screw.friction_static == bronze.friction_static


def test_rows_kept_for_one_lubricant_are_not_read_for_another(catalog: Catalog) -> None:
    """The index keeps each query's eligible rows as run (``index.EligibleCache``); oiled
    and greased rows hold at different frictions, so an oiled query's rows must not
    answer a greased one (they did while the key said only "lubricated")."""
    app = Application(
        load_n=0.0, moving_mass_kg=20.0, orientation="vertical", speed_m_s=0.01,
        length_m=0.5, stroke_m=0.3, families=("TR-C45",), nut_material="acetal", limit=100,
    )  # fmt: skip
    held = {}
    for lubrication in ("oiled", "greased"):
        sel = select(replace(app, lubrication=lubrication), catalog.index)
        record = next(c for c in (*sel.candidates, *sel.rejected) if c.screw.id == "Tr12x3-acetal")
        held[lubrication] = record.screw.friction_static
    assert held == {"oiled": pytest.approx(0.1), "greased": pytest.approx(0.2 / 1.3)}
