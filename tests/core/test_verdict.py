"""A candidate's verdict (app.core.verdict): what governs with its utilisation and margin,
the assumed values it rests on in words, and what to watch."""

from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.contract.units import DEFAULT_UNITS, render
from app.core.checks import BY_NAME
from app.core.model import Application
from app.core.record import governing
from app.core.selection import select
from app.core.verdict import LEADSCREW_NUT_CHECKS, missing_values, verdict
from app.core.wording import percent, value_label
from tests.leadscrews import leadscrew_families

#: A horizontal axis where most screws pass with room (100 N, 50 mm/s, 300 mm).
EASY = Application(load_n=100.0, speed_m_s=0.05, length_m=0.3)


@pytest.mark.parametrize(
    ("key", "words"),
    [
        ("pv_limit_mpa_m_s", "PV limit"),
        ("dynamic_load_lbf", "dynamic load rating"),
        ("bearing_pv_limit_mpa_m_s", "nut PV limit"),
        ("max_sliding_speed_m_s", "maximum sliding speed"),
        ("specific_wear_rate_mm3_n_m", "specific wear rate"),
        ("friction_static_bronze", "static friction"),
        ("nut_length_to_d", "rated nut length"),
    ],
)
def test_catalog_keys_are_named_in_words(key: str, words: str) -> None:
    assert value_label(key) == words
    assert "_" not in value_label(key)


def test_percent_never_rounds_a_near_limit_to_100() -> None:
    assert percent(0.9962) == "99.6 %"
    assert percent(1.0002) == "100.02 %"
    assert percent(0.5) == "50 %"


def test_the_verdict_names_the_check_closest_to_its_limit(catalog: Catalog) -> None:
    sel = select(EASY, catalog.index)
    assert sel.candidates
    for c in sel.candidates[:10]:
        v = verdict(c)
        limits = [k for k in c.checks if k.kind == "limit" and k.utilization is not None]
        top = max(limits, key=lambda k: k.utilization or 0.0)
        assert v.governs == top.name == governing(EASY, c.checks).name
        assert v.utilization == top.utilization
        assert v.margin == pytest.approx(1.0 - top.utilization)
        assert f"{top.label} at {percent(top.utilization)}" in render(v.text, DEFAULT_UNITS)
        # the runner-up is the second-highest utilisation among the limits
        rest = sorted((k.utilization for k in limits if k is not top), reverse=True)
        if rest:
            assert any(percent(rest[0]) in w.template for w in v.watch)


def test_the_verdict_rests_on_the_assumed_values_of_its_governing_check(
    catalog: Catalog,
) -> None:
    """Every assumed catalog value the governing check reads is named, in words; every
    ranged value the pass hinges on is named and marked as hinging. The leadscrew families
    by name: a ball screw's ratings are the maker's, none assumed."""
    sel = select(replace(EASY, families=leadscrew_families(catalog)), catalog.index)
    seen_assumed = seen_hinge = False
    for c in sel.candidates:
        v = verdict(c)
        g = c.governing
        assert g is not None
        assumed = {
            value_label(k)
            for k in g.check.sources
            if k in c.screw.provenance and c.screw.provenance[k].kind == "assumed"
        }
        assert assumed <= {r.label for r in v.rests_on}
        assert {value_label(h) for h in c.hinges_on} == {r.label for r in v.rests_on if r.hinges}
        seen_assumed |= bool(assumed)
        seen_hinge |= bool(c.hinges_on)
    assert seen_assumed and seen_hinge  # the property was exercised both ways


def test_a_back_driving_vertical_screw_says_what_holds_it_power_off(catalog: Catalog) -> None:
    """Vertical, 10 kg on the nut: a screw that does not self-lock with margin names the
    brake it needs (the torque to hold times the brake's safety factor, as the holding
    check asks) in its watch list; with a 5 N m brake given, the share of it the hold
    takes. (The surest power-off holds rank first, the self-locking ones among them: the
    list goes to 100 to reach the others.)"""
    app = Application(
        load_n=0.0, speed_m_s=0.05, length_m=0.3, moving_mass_kg=10.0,
        orientation="vertical", limit=100,
    )  # fmt: skip
    for braked in (False, True):
        given = replace(app, brake_torque_nm=5.0) if braked else app
        sel = select(given, catalog.index)
        # without a brake they fail, not held: among the rejected
        pool = sel.candidates if braked else sel.rejected
        loose = [c for c in pool if not c.self_locking_with_margin]
        assert loose
        for c in loose[:5]:
            watch = [w for w in verdict(c).watch if "brake" in w.template]
            assert len(watch) == 1
            if braked:
                held = percent(c.brake_needed_nm / 5.0)
                assert watch[0].template == f"power off: held by the brake at {held}"
                continue
            brake = watch[0].values["t"]
            assert brake.value == pytest.approx(c.brake_to_fit_nm)  # type: ignore[union-attr]
            assert brake.value == pytest.approx(1.5 * c.brake_nm)  # type: ignore[union-attr]


def test_a_pass_with_skipped_checks_never_says_every_check(catalog: Catalog) -> None:
    """The summary every page shows: a check that runs for the application but not for a
    screw (a value it reads is missing) turns "Passes every check." into the count that
    ran and the checks that did not, each with the values it lacks."""
    sel = select(EASY, catalog.screws)
    passing = [c for c in sel.candidates if c.passed]
    skipped = [c for c in passing if c.verdict.skipped]
    complete = [c for c in passing if not c.verdict.skipped]
    assert skipped, "some catalog screw lacks a value a check reads"
    for c in skipped:
        text = render(c.verdict.summary, DEFAULT_UNITS)
        limits = [k for k in c.checks if k.kind == "limit"]
        assert "every check" not in text
        advice = len(c.checks) - len(limits)
        besides = f", besides {advice} piece{'s' if advice > 1 else ''} of advice" if advice else ""
        assert text.startswith(f"Passes the {len(limits)} limits that ran{besides}.")
        for skip in c.verdict.skipped:
            assert skip.missing and f"{skip.label} (no " in text
            assert skip.check not in {k.name for k in c.checks}
    for c in complete:
        text = render(c.verdict.summary, DEFAULT_UNITS)
        tail = (
            " Leadscrew-nut checks do not apply to a ball screw."
            if c.screw.screw_type == "ball"
            else ""
        )
        assert text == "Passes every check." + tail


def test_a_ball_screw_is_not_skipped_on_checks_its_nut_has_no_rating_for(
    catalog: Catalog,
) -> None:
    """A ball nut rolls (HIWIN BS-08-2-EN-1704-K rates it by Cdyn, C0 and the DN speed,
    no PV or flank pressure): the leadscrew nut's checks do not apply to it, so they are
    said once as not applicable and never listed under "Not checked"; a leadscrew has
    none not applicable."""
    sel = select(EASY, catalog.screws)
    balls = [c for c in sel.candidates if c.screw.screw_type == "ball"]
    leads = [c for c in sel.candidates if c.screw.screw_type == "lead"]
    assert balls and leads
    for c in balls:
        text = render(c.verdict.summary, DEFAULT_UNITS)
        assert c.verdict.not_applicable, c.screw.id
        assert "PV (nut material)" in c.verdict.not_applicable
        assert text.count("Leadscrew-nut checks do not apply to a ball screw.") == 1
        skipped = {s.check for s in c.verdict.skipped}
        assert not skipped & LEADSCREW_NUT_CHECKS, (c.screw.id, skipped)
        for label in c.verdict.not_applicable:
            assert f"{label} (no " not in text
    assert all(c.verdict.not_applicable == () for c in leads)
    assert set(BY_NAME) >= LEADSCREW_NUT_CHECKS


def test_a_nut_rated_by_pressure_without_its_thread_lacks_only_the_thread(
    catalog: Catalog,
) -> None:
    """A bronze nut (pressure-speed table) on a screw without pitch and nut length: the
    contact-pressure check could not run for want of those two, not of a rating."""
    row = catalog.by_id["Tr12x3-bronze"]
    bare = replace(row, pitch_m=None, nut_length_m=None)
    check = BY_NAME["bearing_pressure"]
    assert missing_values(check, row) == ()
    assert missing_values(check, bare) == ("nut length", "pitch")
    unrated = replace(bare, bearing_pressure_table=())
    assert missing_values(check, unrated) == (
        "allowed contact pressure",
        "maximum contact pressure",
        "nut PV limit",
        "nut length",
        "pitch",
    )
