"""Robustness (app.core.robustness) through its one function, on every path that uses it.

``fixtures/robustness_queries.json`` holds, for twelve queries (a lead chosen, so the
candidates and their variants are screened together, and any lead, so the variants of
the returned ones are screened after; families, a nut material, a vertical axis, a move
with a motor curve, advice that rejects), the ranked candidates with their verdicts as
the selector gave them when each path kept its own code and caches. Four were recorded
again when the physics changed the answer: the nut's heat and wear life ("motion-motor":
Tr8x2 bronze nuts at 3,000 rpm without a pause overheat; "life-advice-reject": the ISO
nuts have a rated life), the peak thrust with m a on the nut and the bronze nut's
sliding-speed limit ("any-lead-vertical", "any-lead-fast"). Two more changed when
polymer nuts were held to a dynamic load, p_dyn (L / P) pi d2 H1 with p_dyn = 0.25 p_max
(PTFE-filled 1.75 MPa): "any-lead-loaded" loses the Tr8x8(P2) PTFE nuts (8 turns x pi x
7 mm x 1 mm = 175.9 mm^2, 308 N < 400 N) and "heavy-any-lead" the Tr14x6(P3) and
Tr16x8(P4) PTFE nuts (549.8 mm^2, 962 N, and 8 x pi x 14 x 2 = 703.7 mm^2, 1232 N,
both < 1500 N); the next-ranked screws fill the list. And two with a stroke
("motion-motor", "life-advice-reject") now rank "lowest torque" by the peak motor torque
the table shows rather than the accelerating torque, which changes which 30 screws make
the list. "life-advice-reject" was recorded again when the ISO nuts' allowed wear became
Helix Linear's end of life (a quarter of the pitch off the thread, 0.483 H1, was 0.25 H1
assumed): their wear lives nearly doubled, so the Tr14x3 and Tr8x8(P2) PTFE nuts now last
the 3 years asked and the Tr12x6(P3) and Tr14x6(P3) PTFE nuts no longer hinge on the nut
length. Two were recorded again when the ISO nuts were held to their maker's allowable
dynamic thrust (MISUMI's table; filled PTFE 0.7 x its plastic nut; an unlisted size at the
lowest listed flank pressure, Tr32x6's 0.7 x 2050 N over 10.667 x pi x 29 x 3 = 2915 mm^2,
0.4922 MPa for PTFE): "any-lead-loaded" (400 N) loses the Tr14x3, Tr12x6(P3), Tr14x6(P3),
Tr16x4 and Tr16x8(P4) PTFE nuts (Tr14x3's listed 343 N; Tr12x6(P3) 8 x pi x 10.5 x 1.5 =
395.8 mm^2, 195 N; Tr16x4 8 x pi x 14 x 2 = 703.7 mm^2, 346 N), while Tr22x5 PTFE
(8.8 x pi x 19.5 x 2.5 = 1348 mm^2, 663 N) and Tr18x8(P4) PTFE (its listed 611 N) stay;
"heavy-any-lead" (1500 N) loses the Tr18x8(P4), Tr20x4, Tr22x5 and Tr24x5 PTFE nuts
(686 N at Tr20x4, 798 N at Tr24x5's 1621 mm^2); bronze sizes and a seed screw fill the
lists. "life-advice-reject" was recorded once more when the seed's rated travel became
capped by the wear life of the same polyacetal nut at the cycle's wear thrust: at 60 N the
ZBX, KHD and VHD TFE nuts wear through in under the 3 years asked (ZBX8000-L10: 14,640 km N
/ 60 N = 244 km, 244e3 / (0.4 x 2000 x 365) = 0.84 years), so ISO nuts fill the list.
"any-lead-vertical" was recorded again when holding with the power off became a
requirement whose surest holds rank first: the screws whose thread alone holds. Seven were
recorded again when a bronze nut run dry (every query here leaves the nut unlubricated)
became a warning: its ratings are a lubricated nut's; the bronze nuts keep their verdicts
and their order among themselves, after the screws without a warning (or past the list's
limit; rejected where the advice rejects). "nut-bronze" was recorded again when a bronze
nut run dry came to be worked at its dry friction (0.19, Shigley Table 8-5, for 0.13
oiled): ranked by torque, the steeper leads of similar sizes move ahead (Tr12x6(P3)
before Tr16x4, Tr14x6(P3) before Tr18x4, Tr16x8(P4) before Tr22x5, Tr18x8(P4) before
Tr24x5); the same 30 nuts, every one still robust, and no other query moved (checked by
script against the recorded rankings). "motion-motor" and "life-advice-reject" were
recorded again when the screw's fins each side of a sliding nut came to be taken as long
as the screw there (Incropera Table 3.4, case B), not endless: one non-robust nut in each
now hinges on its friction too (its nut heat nearer the limit); the order and every other
verdict stayed. Three were recorded again when the polymer nuts' static friction came from
published data (an acetal nut 0.20, range 0.10-0.30, Shackelford's CRC table; a PTFE one
its running 0.15, PTFE starting without stick-slip; they were assumed above the running
friction, 0.30 and 0.20): on the vertical axis the Tr16x4, Tr18x4 and Tr22x5 PTFE and the
Tr20x8(P4) and Tr24x10(P5) acetal nuts no longer hold with the power off by their thread,
and larger, flatter leads (Tr36x6 to Tr44x7) take their places, each hinging on its static
friction; where a stroke ranks by the peak torque ("motion-motor", "life-advice-reject")
the PTFE nuts' start from rest costs less and they rank ahead. "nut-bronze" and
"heavy-any-lead" were recorded again when the torque shown and ranked without a stroke
became the one the drive-torque check judges, the peak of the moving segments and the
start from rest (it was the accelerating torque): the start at static friction costs
Tr12x3 more than Tr10x4(P2), which now ranks first, and in "heavy-any-lead" the Tr12x6(P3)
bronze nuts take the last two places from the Tr16x4 ones. Every path
must still give them: select, a catalog screw evaluated alone, and a screw outside the
catalog with the same values (its variant rows built on the fly).
"""

import json
import math
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

from app.catalog import Catalog, load_catalog
from app.catalog.errors import CatalogError
from app.catalog.own import OwnGeometry, own_screw
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.robustness import at_values, build_variants
from app.core.selection import select, with_robustness
from app.core.verdict import verdict
from tests.leadscrews import leadscrew_families

ROOT = Path(__file__).parents[2]
QUERIES: dict[str, Any] = json.loads(
    (ROOT / "tests" / "fixtures" / "robustness_queries.json").read_text()
)


def _application(fields: dict[str, Any]) -> Application:
    """The recorded application (lists back to the tuples the core takes)."""
    tuples = {"families": tuple, "motor_curve": lambda v: tuple(map(tuple, v))}
    return Application(**{k: tuples.get(k, lambda v: v)(v) for k, v in fields.items()})


@pytest.mark.parametrize("name", QUERIES)
def test_select_gives_the_recorded_verdicts(catalog: Catalog, name: str) -> None:
    app = _application(QUERIES[name]["application"])
    # recorded over the leadscrews: name them where the query names no family
    app = app if app.families else replace(app, families=leadscrew_families(catalog))
    sel = select(app, catalog.index)
    found = [
        [ev.screw.id, r.robust, list(r.hinges_on)]
        for ev, r in zip(sel.candidates, sel.robustness, strict=True)
    ]
    assert found == QUERIES[name]["ranked"]


@pytest.mark.parametrize("name", QUERIES)
def test_one_screw_gives_the_recorded_verdicts(catalog: Catalog, name: str) -> None:
    """The first three ranked screws alone: from the index's variant rows (a catalog
    screw's detail and POST /evaluate) and from rows built for a copy of it that the
    catalog does not hold (a screw of the user's own)."""
    app = _application(QUERIES[name]["application"])
    index = catalog.index
    assert index.variants is not None
    for sid, robust, hinges_on in QUERIES[name]["ranked"][:3]:
        at = index.positions[sid]
        ev = with_robustness(app, evaluate(app, index.row(at)), index.variants, at)
        assert (ev.passed, ev.robust, list(ev.hinges_on)) == (True, robust, hinges_on), sid
        mine = replace(index.table.screws[at], id="mine")
        own = with_robustness(app, evaluate(app, mine), build_variants([mine]), 0)
        assert (own.robust, list(own.hinges_on)) == (robust, hinges_on), sid


def test_a_failing_screw_is_left_unjudged(catalog: Catalog) -> None:
    """A screw that fails as catalogued is not re-screened: it fails anyway."""
    app = Application(load_n=3000.0, speed_m_s=0.5, length_m=2.0)
    at = catalog.index.positions["B4000-L2"]
    ev = evaluate(app, catalog.index.row(at))
    assert not ev.passed
    assert catalog.index.variants is not None
    judged = with_robustness(app, ev, catalog.index.variants, at)
    assert judged is ev and judged.robust is None and judged.hinges_on == ()


def test_each_variant_is_its_screw_with_one_end_of_one_range(catalog: Catalog) -> None:
    """Every variant row ``at_values`` builds for the catalog equals ``dataclasses.replace``
    of its screw with that end's values, each changed value in place."""
    count = 0
    for screw in catalog.screws:
        for ends in screw.assumption_ends.values():
            for changes in ends:
                if changes:
                    variant = at_values(screw, changes)
                    assert variant == replace(screw, **changes)
                    assert all(getattr(variant, k) == v for k, v in changes.items())
                    count += 1
    assert count > 1000


def test_a_material_value_with_a_range_is_screened_at_its_ends(catalog: Catalog) -> None:
    """303 stainless's thermal conductivity is 15.1 W/(m K), range 14.9-16.3 (assumed,
    catalog/common.toml): every screw of it carries the range, and one whose nut heat sits
    within it hinges on it. A Tr16x4 of 303 with the catalog's bronze nut (32 mm long,
    greased, 8 h a day over a 300 mm stroke at 10 mm/s, 140 C ambient against the nut's
    150 C) at 50.5 N heats its nut to 0.9991 of the room at 15.1 W/(m K) and to 1.0022 at
    14.9: it was called robust, its conductivity's range never screened."""
    ranged = "thermal_conductivity_w_m_k"
    of_303 = [s for s in catalog.screws if s.material_name == "stainless-303"]
    assert of_303 and all(
        s.assumption_ends[ranged] == ({ranged: 14.9}, {ranged: 16.3}) for s in of_303
    )
    geometry = OwnGeometry(0.016, 0.0115, 0.004, math.radians(15.0), 0.16, 0.13)
    geometry = replace(geometry, pitch_m=0.004, nut_length_m=0.032)
    material = catalog.materials["stainless-303"]
    mine = own_screw(geometry, material, "stainless-303", catalog.nut_materials["bronze"])
    app = Application(
        load_n=50.5,
        speed_m_s=0.01,
        length_m=0.5,
        stroke_m=0.3,
        lubrication="greased",
        hours_per_day=8.0,
        ambient_c=140.0,
    )
    ev = evaluate(app, mine)
    heat = {c.name: c for c in ev.checks}["nut_heat"]
    assert ev.passed and heat.utilization == pytest.approx(0.9991, abs=1e-4)
    low = evaluate(app, at_values(mine, {ranged: 14.9}))
    assert not low.passed and [c.name for c in low.checks if not c.passed] == ["nut_heat"]
    judged = with_robustness(app, ev, build_variants([mine]), 0)
    assert (judged.robust, judged.hinges_on) == (False, (ranged,))
    hinged = [r.label for r in verdict(judged).rests_on if r.hinges]
    assert hinged == ["screw thermal conductivity"]


def test_a_users_material_range_is_carried_and_a_density_range_refused(
    tmp_path: Path,
) -> None:
    """The example family's material given with a range on its Young's modulus: every
    screw of it carries that range's ends (193 GPa, range 180-200). No variant carries a
    density's range (the inertia derives from it): one given stops the load rather than
    call a screw robust without screening it."""
    text = (ROOT / "examples" / "my-family" / "my-family.toml").read_text()
    plain = "youngs_modulus_gpa = { value = 193.0 }"
    assert plain in text
    ranged = "youngs_modulus_gpa = { value = 193.0, range = [180.0, 200.0] }"
    (tmp_path / "my-family.toml").write_text(text.replace(plain, ranged))
    mine = [s for s in load_catalog([tmp_path]).screws if s.family_id == "MY"]
    ends = ({"youngs_modulus_pa": 180e9}, {"youngs_modulus_pa": 200e9})
    assert mine and all(s.assumption_ends["youngs_modulus_gpa"] == ends for s in mine)
    density = "density_kg_m3 = { value = 8000.0 }"
    dense = "density_kg_m3 = { value = 8000.0, range = [7900.0, 8100.0] }"
    (tmp_path / "my-family.toml").write_text(text.replace(density, dense))
    with pytest.raises(CatalogError, match="density_kg_m3"):
        load_catalog([tmp_path])
