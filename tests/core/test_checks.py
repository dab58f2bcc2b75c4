"""Which checks apply, and what each says (app.core.checks, via evaluate)."""

from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.contract.units import render
from app.core.batch import CheckResult
from app.core.evaluate import evaluate
from app.core.formulas import limits
from app.core.model import Application, ScrewSpec
from app.core.record import Candidate
from tests.core.conftest import light_app

ALWAYS = [
    "critical_speed",
    "buckling",
    "root_stress",
    "pv",
    "traverse_speed",
    "design_load",
    "length",
]


def names(ev: Candidate) -> list[str]:
    return [c.name for c in ev.checks]


def check(ev: Candidate, name: str) -> CheckResult:
    return next(c for c in ev.checks if c.name == name)


def test_default_application_runs_the_always_on_checks(zbx8000_l10: ScrewSpec) -> None:
    """Uncoated, horizontal, no duty, no tolerance, no drive: the seed's limits plus the
    temperature band (0-93 C), in a fixed order."""
    assert names(evaluate(light_app(), zbx8000_l10)) == [*ALWAYS, "temperature"]


def test_every_optional_check_switches_on(catalog: Catalog) -> None:
    app = light_app(
        max_torque_nm=1.0,
        orientation="vertical",
        require_anti_backlash=True,
        stroke_m=0.2,
        cycles_per_day=50.0,
        required_life_years=2.0,
        positioning_tolerance_m=1e-3,
    )
    ev = evaluate(app, catalog.by_id["ZBX8000-L10-TFE"])
    assert names(ev) == [
        "torque",
        *ALWAYS,
        "coating_environment",
        "temperature",
        "back_driving",
        "anti_backlash",
        "life",
        "accuracy",
    ]


def test_no_buckling_check_when_never_pushed(zbx8000_l10: ScrewSpec) -> None:
    """A hanging vertical axis (thrust bearing above the nut) only ever pulls the screw; a
    horizontal one marked tension is pushed on the move back, when friction reverses."""
    hanging = light_app(compression=False, orientation="vertical")
    assert "buckling" not in names(evaluate(hanging, zbx8000_l10))
    assert "buckling" in names(evaluate(light_app(compression=False), zbx8000_l10))


@pytest.mark.parametrize(
    ("screw_id", "oil", "passed"),
    [
        pytest.param("ZBX8000-L10-TFE", True, False, id="TFE-with-oil-fails"),
        pytest.param("ZBX8000-L10-TFE", False, True, id="TFE-dry-passes"),
    ],
)
def test_tfe_and_oil(catalog: Catalog, screw_id: str, oil: bool, passed: bool) -> None:
    """Seed, "TFE Coating": no additional lubrication, no oil contamination."""
    c = check(evaluate(light_app(oil_present=oil), catalog.by_id[screw_id]), "coating_environment")
    assert c.passed is passed


@pytest.mark.parametrize("lubrication", ["greased", "oiled"])
def test_a_lubricated_nut_fails_a_dry_film_coating(catalog: Catalog, lubrication: str) -> None:
    """Seed, "TFE Coating": no additional lubrication. Greasing or oiling the nut brings
    the lubricant to the coating as surely as oil around the axis does; dry passes."""
    screw = catalog.by_id["ZBX8000-L10-TFE"]
    c = check(evaluate(light_app(lubrication=lubrication), screw), "coating_environment")
    assert not c.passed
    assert lubrication in render(c.message)
    assert c.fix is not None and "dry" in render(c.fix)
    dry = check(evaluate(light_app(lubrication="dry"), screw), "coating_environment")
    assert dry.passed


def test_uncoated_screw_has_no_oil_check(zbx8000_l10: ScrewSpec) -> None:
    assert "coating_environment" not in names(evaluate(light_app(oil_present=True), zbx8000_l10))


def test_coated_screw_over_2_4_m_fails_the_length_check(catalog: Catalog) -> None:
    """Seed: lengths up to 4 m, up to 2.4 m (8 ft) with TFE coating; the fix proposes
    5 % inside it, 2280 mm."""
    app = light_app(length_m=3.0, speed_m_s=0.001, compression=False)
    coated = check(evaluate(app, catalog.by_id["ZBX10000-L10-TFE"]), "length")
    uncoated = check(evaluate(app, catalog.by_id["ZBX10000-L10"]), "length")
    assert not coated.passed and coated.limit == pytest.approx(2.4)
    assert coated.fix is not None and "at most 2280 mm" in render(coated.fix)
    assert uncoated.passed and uncoated.limit == pytest.approx(4.0)
    # the input is the length between the supports; the limit holds the whole screw
    assert "machined ends beyond the supports count against it" in render(uncoated.message)


@pytest.mark.parametrize(
    ("ambient_c", "passed"),
    [pytest.param(-5.0, False, id="-5C"), pytest.param(50.0, True, id="50C")],
)
def test_temperature_band(zbx8000_l10: ScrewSpec, ambient_c: float, passed: bool) -> None:
    """Seed: standard operating temperature 0-93 C."""
    assert check(evaluate(light_app(ambient_c=ambient_c), zbx8000_l10), "temperature").passed is (
        passed
    )


def test_back_driving_check_uses_the_self_locking_lead_with_margin(catalog: Catalog) -> None:
    """Vertical axis, no brake: passes iff lead <= pi d_p (f mu_s) / cos(a_n), f = 0.5.
    ZBX8000: d_p = (12.7 + 9.906) / 2 = 11.303 mm, mu_s 0.08, a_n 14.5 deg:
    pi x 11.303 x 0.04 / 0.96815 = 1.4671 mm (2.934 mm without the margin)."""
    app = light_app(orientation="vertical")
    fine = evaluate(app, catalog.by_id["ZBX8000-L1"])
    steep = evaluate(app, catalog.by_id["ZBX8000-L10"])
    assert check(fine, "back_driving").passed and fine.self_locking_with_margin
    c = check(steep, "back_driving")
    assert not c.passed and not steep.self_locking
    assert c.limit == pytest.approx(1.4671e-3, rel=1e-4)
    assert steep.max_self_locking_lead_m == pytest.approx(2.9342e-3, rel=1e-4)
    assert "seed method" in render(c.message) and "physics" in render(c.message)


def test_anti_backlash_requirement(catalog: Catalog) -> None:
    """Free-wheeling B series: typical backlash 0.076-0.25 mm; anti-backlash series ~0."""
    app = light_app(require_anti_backlash=True)
    b = check(evaluate(app, catalog.by_id["B8000-L10"]), "anti_backlash")
    assert not b.passed and "0.25 mm" in render(b.message)
    assert check(evaluate(app, catalog.by_id["ZBX8000-L10"]), "anti_backlash").passed


def test_unrated_screw_fails_a_required_life(b8000_l10: ScrewSpec) -> None:
    """A screw with neither a rated travel nor a wear rate (the B8000 without its nut's
    wear rating) fails a required life as unrated; the catalog's B8000 is judged by its
    nut's wear life instead."""
    app = light_app(stroke_m=0.1, cycles_per_day=10.0, required_life_years=1.0)
    unrated = replace(b8000_l10, wear_rate_m2_n=None, allowed_wear_fraction=None)
    c = check(evaluate(app, unrated), "life")
    assert not c.passed and c.utilization is None
    names = {c.name for c in evaluate(app, b8000_l10).checks}
    assert "wear_life" in names and "life" not in names


def test_life_check_uses_the_low_end_of_the_rated_range(zbx8000_l10: ScrewSpec) -> None:
    """ZBX8000 uncoated 100-150 million cm; 0.3 m stroke, 2000 cycles a day:
    1e6 / (0.6 x 2000 x 365) = 2.283 years at the low end, 3.425 at the high end. At 1 N
    the nut's own wear life (14,640 km, test_life) is longer than the rating, which
    governs."""
    app = light_app(load_n=1.0, stroke_m=0.3, cycles_per_day=2000.0, required_life_years=3.0)
    c = check(evaluate(app, zbx8000_l10), "life")
    assert c.limit == pytest.approx(2.283, rel=1e-3)
    assert not c.passed


def test_accuracy_sums_lead_error_backlash_and_repeatability(catalog: Catalog) -> None:
    """Seed: lead accuracy 0.0006 mm/mm, repeatability 0.0013 mm; B series backlash up to
    0.25 mm. Stroke 300 mm: 0.18 + 0.25 + 0.0013 = 0.4313 mm."""
    app = light_app(stroke_m=0.3, positioning_tolerance_m=0.4e-3)
    b = check(evaluate(app, catalog.by_id["B8000-L10"]), "accuracy")
    zbx = check(evaluate(app, catalog.by_id["ZBX8000-L10"]), "accuracy")
    assert b.value == pytest.approx(0.4313e-3, rel=1e-6) and not b.passed
    assert zbx.value == pytest.approx(0.1813e-3, rel=1e-6) and zbx.passed


@pytest.mark.parametrize(
    ("ambient_c", "passed"),
    [
        pytest.param(20.0, True, id="at-the-20C-reference"),
        pytest.param(60.0, False, id="60C-grows"),
        pytest.param(-20.0, False, id="minus-20C-shrinks"),
    ],
)
def test_accuracy_adds_the_screws_thermal_growth(
    zbx8000_l10: ScrewSpec, ambient_c: float, passed: bool
) -> None:
    """Issue 29, item 4. ZBX8000-L10 over a 300 mm stroke, 0.2 mm tolerance: lead error
    0.0006 x 300 = 0.18 mm + repeatability 0.0013 mm + no backlash = 0.1813 mm (seed,
    Screw Accuracy). 303 stainless grows 17.3e-6 /K (ASM Handbook): at 60 C, 40 K above
    the 20 C reference, 17.3e-6 x 300 x 40 = 0.2076 mm, and as much shrinking at -20 C;
    the worst case adds it (THK, Studying the Positioning Accuracy: thermal displacement
    a cause of error beside the lead accuracy): 0.3889 mm, over the tolerance."""
    app = light_app(stroke_m=0.3, positioning_tolerance_m=0.2e-3, ambient_c=ambient_c)
    c = check(evaluate(app, zbx8000_l10), "accuracy")
    growth_mm = 17.3e-6 * 300 * abs(ambient_c - 20.0)
    assert c.value == pytest.approx((0.1813 + growth_mm) * 1e-3, rel=1e-9)
    assert c.passed is passed
    text = render(c.message)
    assert f"thermal growth {growth_mm:.4g} mm" in text and "lead error 0.18 mm" in text
    assert f"{abs(ambient_c - 20.0):.3g} K from the 20 °C reference" in text


def test_accuracy_fix_names_the_thermal_growth(zbx8000_l10: ScrewSpec) -> None:
    app = light_app(stroke_m=0.3, positioning_tolerance_m=0.2e-3, ambient_c=60.0)
    c = check(evaluate(app, zbx8000_l10), "accuracy")
    assert c.fix is not None and "its growth is 0.2076 mm" in render(c.fix)


def test_traverse_fix_offers_a_lead_band_that_allows_the_speed(catalog: Catalog) -> None:
    """200 mm/s on a 10 mm lead exceeds the 100 mm/s band; the 12-25 mm band allows 250."""
    c = check(evaluate(light_app(speed_m_s=0.2), catalog.by_id["ZBX8000-L10"]), "traverse_speed")
    assert not c.passed
    assert c.fix is not None and "lead of at least 12 mm" in render(c.fix)
    assert limits.band_speed_m_s(0.012, catalog.by_id["ZBX8000-L10"].traverse_bands) >= 0.2


def test_torque_check_against_the_available_drive(zbx8000_l10: ScrewSpec) -> None:
    ev = evaluate(light_app(max_torque_nm=0.01), zbx8000_l10)
    c = check(ev, "torque")
    assert c.value == pytest.approx(ev.torque.required_nm)
    assert not c.passed


def test_vertical_load_remedy_subtracts_the_weight(zbx8000_l10: ScrewSpec) -> None:
    """The design-load check offers a user load such that the peak thrust, load + m g + m a,
    is the design load (a = 1 m/s^2 in light_app)."""
    app: Application = light_app(load_n=600.0, orientation="vertical", moving_mass_kg=5.0)
    c = check(evaluate(app, zbx8000_l10), "design_load")
    assert not c.passed and c.limit is not None and c.input_limits
    assert c.input_limits["load_n"] == pytest.approx(c.limit - 5.0 * 9.80665 - 5.0 * 1.0)
    again = check(
        evaluate(replace(app, load_n=c.input_limits["load_n"]), zbx8000_l10), "design_load"
    )
    assert again.utilization == pytest.approx(1.0, rel=1e-9)
