"""The ordering line (app.catalog.ordering): the ISO 2903 designation with its tolerance
class, the seed series' specification, a custom screw's geometry, and what to confirm
with the maker exactly where the catalog assumes a value."""

import dataclasses
import math

import pytest

from app.catalog import Catalog
from app.catalog.ordering import (
    BALL_BASIS,
    CONFIRMABLE,
    CUSTOM_BASIS,
    HIWIN_NUT,
    ISO_BASIS,
    SEED_BASIS,
    as_rated,
    hiwin_nut_code,
    hiwin_order_code,
    hiwin_shaft_code,
    iso_designation,
    ordering_basis,
    ordering_line,
    to_confirm,
)
from app.catalog.own import OwnGeometry, own_screw
from app.core.model import Provenance

# ISO 2903 clause 12 (and iso-trapezoidal.md): "Tr d x P" for a single start,
# "Tr d x lead (P pitch)" for several; tolerance class 7e screw / 7H nut (ISO 2903 clause 9,
# medium class, normal length of engagement).
ISO_CASES = [
    ("Tr16x4-bronze", "Tr16x4", "C45 (1.0503) steel", "bronze (CuSn7Zn4 / CuSn12)"),
    ("Tr16x8(P4)-bronze", "Tr16x8(P4)", "C45 (1.0503) steel", "bronze (CuSn7Zn4 / CuSn12)"),
    ("Tr8x8(P2)-304-acetal", "Tr8x8(P2)", "1.4301 (304) stainless steel", "acetal (POM)"),
    ("Tr20x4-ptfe", "Tr20x4", "C45 (1.0503) steel", "PTFE-filled polymer"),
]


@pytest.mark.parametrize(
    ("cid", "thread", "screw", "nut"), ISO_CASES, ids=[c[0] for c in ISO_CASES]
)
def test_iso_screws_are_designated_with_their_tolerance_class(
    catalog: Catalog, cid: str, thread: str, screw: str, nut: str
) -> None:
    spec = catalog.by_id[cid]
    assert iso_designation(spec) == thread
    line = ordering_line(spec, 0.5)
    assert line.startswith(f"Trapezoidal leadscrew {thread}-7e right-hand, {screw}")
    assert f"nut {thread}-7H, {nut}" in line
    # the nut length the pressure checks read (2 x d, catalog) is what the buyer asks for
    assert f"at least {spec.nut_length_m * 1000:g} mm long" in line
    assert "500 mm between the supports plus the ends, end machining to drawing" in line
    assert "flange or cylindrical" in line
    assert ordering_basis(spec) == ISO_BASIS


def test_starts_follow_lead_over_pitch(catalog: Catalog) -> None:
    """Tr8x2 with 1, 2 and 4 starts (iso-trapezoidal.md: Tr8x2, Tr8x4(P2), Tr8x8(P2))."""
    found = {
        cid: iso_designation(catalog.by_id[cid])
        for cid in ("Tr8x2-acetal", "Tr8x4(P2)-acetal", "Tr8x8(P2)-acetal")
    }
    assert found == {
        "Tr8x2-acetal": "Tr8x2",
        "Tr8x4(P2)-acetal": "Tr8x4(P2)",
        "Tr8x8(P2)-acetal": "Tr8x8(P2)",
    }


# The seed's families: series number = sixteenths of an inch (catalog/README.md size rule),
# 303 stainless rolled screw and polyacetal nut (seed: Physical properties).
SEED_CASES = [
    ("B4000-L2", "B4000", "1/4 in (6.35 mm)", "free-wheeling", "uncoated"),
    ("ZBX6000-L10", "ZBX6000", "3/8 in (9.525 mm)", "anti-backlash (axial take-up)", "uncoated"),
    (
        "KHD6000-L5-TFE",
        "KHD6000",
        "3/8 in (9.525 mm)",
        "anti-backlash (axial take-up)",
        "TFE coated",
    ),
    ("VHD12000-L20", "VHD12000", "3/4 in (19.05 mm)", "anti-backlash (axial take-up)", "uncoated"),
    ("B14000-L25.4-TFE", "B14000", "7/8 in (22.225 mm)", "free-wheeling", "TFE coated"),
]


@pytest.mark.parametrize(
    ("cid", "series", "size", "nut", "coating"), SEED_CASES, ids=[c[0] for c in SEED_CASES]
)
def test_seed_series_get_a_specification_not_a_code(
    catalog: Catalog, cid: str, series: str, size: str, nut: str, coating: str
) -> None:
    spec = catalog.by_id[cid]
    assert iso_designation(spec) is None  # a 29 deg Acme form, no pitch: no Tr designation
    line = ordering_line(spec, 0.75)
    lead = f"{spec.lead_m * 1000:g}"
    assert line.startswith(f"{series} leadscrew assembly: screw {size} OD, lead {lead} mm")
    assert f"303 stainless steel, rolled, {coating}, 750 mm between the supports" in line
    assert f"nut {nut}, polyacetal with lubricating additive" in line
    # the seed prints no part-number scheme; the maker is inferred, and the basis says so
    assert ordering_basis(spec) == SEED_BASIS
    assert "no part-number scheme" in SEED_BASIS and "inferred, not published" in SEED_BASIS


def test_seed_lines_name_the_assumed_lead_root_and_nut_rating(catalog: Catalog) -> None:
    """ZBX6000-L10: the lead list, the root diameter (0.78 x OD) and the PV limit are
    assumed in catalog/common.toml; the design load, worked from the assumed 3 MPa, is
    assumed too."""
    spec = catalog.by_id["ZBX6000-L10"]
    line = ordering_line(spec, 0.5)
    _, _, confirm = line.partition(" Confirm with the maker: ")
    assert "that this lead is made in this size (taken as 10 mm)" in confirm
    assert f"the root diameter (taken as {0.78 * 9.525:.3g} mm)" in confirm
    assert "the nut's PV limit (taken as 0.105 MPa m/s)" in confirm
    assert f"the nut's design load (taken as {spec.design_load_n:.3g} N)" in confirm
    assert "the thread form (taken as 29° flank angle)" in confirm


def test_confirmation_appears_exactly_where_the_provenance_says_assumed(
    catalog: Catalog,
) -> None:
    for spec in catalog.screws:
        confirm = " ".join(to_confirm(spec))
        for key, what, _ in CONFIRMABLE:
            kind = spec.provenance[key].kind if key in spec.provenance else None
            if kind == "assumed":
                assert what in confirm, (spec.id, key)
            elif key not in ("pv_limit", "bearing_pv_limit"):  # two keys, one phrase
                assert what not in confirm, (spec.id, key)


def test_a_published_value_drops_out_of_the_confirmation(catalog: Catalog) -> None:
    spec = catalog.by_id["ZBX6000-L10"]
    published = {**spec.provenance, "lead": Provenance("vendor", "a maker's size chart")}
    line = ordering_line(dataclasses.replace(spec, provenance=published), 0.5)
    assert "that this lead is made" not in line
    assert "that this lead is made" in ordering_line(spec, 0.5)


def test_nothing_assumed_means_no_confirmation(catalog: Catalog) -> None:
    spec = catalog.by_id["Tr16x4-bronze"]
    sure = {k: Provenance("vendor", "maker") for k in spec.provenance}
    line = ordering_line(dataclasses.replace(spec, provenance=sure), 0.5)
    assert "Confirm" not in line and line.endswith("the nut's shape).")


def test_a_custom_screw_is_specified_by_its_geometry(catalog: Catalog) -> None:
    """The user's own screw: every value 'user', so nothing to confirm; a 30 deg flank
    without a pitch is not given an ISO designation (the pitch is unknown)."""
    geometry = OwnGeometry(
        outer_diameter_m=0.016,
        root_diameter_m=0.0115,
        lead_m=0.008,
        thread_half_angle_rad=math.radians(15.0),
        friction_static=0.2,
        friction_dynamic=0.15,
    )
    spec = own_screw(geometry, catalog.materials["steel"], "steel")
    assert iso_designation(spec) is None
    assert ordering_line(spec, 0.4) == (
        "Leadscrew to your geometry: outer diameter 16 mm, root diameter 11.5 mm, lead 8 mm, "
        "30° flank angle, carbon steel, 400 mm between the supports plus the ends, end "
        "machining to drawing; nut to match: material and shape to state."
    )
    assert ordering_basis(spec) == CUSTOM_BASIS


def test_a_custom_screw_with_a_pitch_and_a_nut_is_ordered_as_it_was_rated(
    catalog: Catalog,
) -> None:
    """Tr16x8(P4) typed in with the catalog's bronze nut: the flank pressure, the lead
    angle and the torque were worked on d2 = 16 - 0.5 x 4 = 14 mm and the nut's bronze
    limits over a 2 d = 32 mm nut, so the line names the pitch and starts (a single-start
    8 mm pitch has d2 = 12 mm and other flanks) and the nut's material and length; it said
    "nut to match: material and shape to state"."""
    geometry = OwnGeometry(
        outer_diameter_m=0.016,
        root_diameter_m=0.0115,
        lead_m=0.008,
        thread_half_angle_rad=math.radians(15.0),
        friction_static=0.16,
        friction_dynamic=0.13,
        pitch_m=0.004,
    )
    nut = catalog.nut_materials["bronze"]
    spec = own_screw(geometry, catalog.materials["c45-steel"], "c45-steel", nut)
    line = ordering_line(spec, 0.4)
    assert line.startswith(
        "Leadscrew to your geometry: outer diameter 16 mm, root diameter 11.5 mm, lead 8 mm, "
        "pitch 4 mm (2 starts), 30° flank angle, C45 (1.0503) steel, rolled, 400 mm"
    )
    assert "nut to match, bronze (CuSn7Zn4 / CuSn12), at least 32 mm long, shape to state" in line


def test_the_line_orders_the_nut_length_the_checks_rated(catalog: Catalog) -> None:
    """Tr20x4 bronze rated with a 60 mm nut (the application's): its flanks carry
    60 / 4 x pi x 18 x 2 mm^2 = 1696 mm^2, 1.5 x the catalog's 40 mm nut, so the line asks
    for at least 60 mm, the user's value with nothing to confirm; it asked for 40 mm and
    to confirm 40 mm, a nut of two thirds the flank area the numbers were worked on. No
    nut length read (NaN: no pitch), the spec is the catalog's."""
    spec = catalog.by_id["Tr20x4-bronze"]
    typed = Provenance("user", "typed in")
    rated = as_rated(spec, 0.060, {"nut_length": typed})
    line = ordering_line(rated, 0.5)
    assert "nut Tr20x4-7H, bronze (CuSn7Zn4 / CuSn12), at least 60 mm long" in line
    assert "the nut length" not in line
    assert as_rated(spec, 0.040, {}) == spec
    seed = next(s for s in catalog.screws if s.family_id == "ZBX")
    assert as_rated(seed, math.nan, {"nut_length": typed}) == seed


# HIWIN's order code (HIWIN GmbH ballscrew catalogue, section "HIWIN order code"):
# [R/L][d]-[lead][recirculation][circuits]-[nut type]-[thread length]-[total length]-
# [lead deviation per 300 mm], e.g. 2R40-20K4-FSCDIN-800-1000-0,052. Tolerance classes of
# BS-08-2-EN-1704-K: rolled T7 (52 um / 300 mm, Table 4.1), ground T3 (12 um, Table 6.1).
BALL_CASES = [
    ("R20-10K3-FSCDIN", "-0,052", "nominal diameter 20 x lead 10 mm, rolled", "T7"),
    ("R08-02.5T2-RSIT", "-0,052", "nominal diameter 8 x lead 2.5 mm, rolled", "T7"),
    ("R20-05K4-FSC", "-0,012", "nominal diameter 20 x lead 5 mm, ground", "T3"),
]


@pytest.mark.parametrize(
    ("cid", "deviation", "size", "grade"), BALL_CASES, ids=[c[0] for c in BALL_CASES]
)
def test_a_ball_screw_is_ordered_by_hiwins_code_not_as_a_leadscrew(
    catalog: Catalog, cid: str, deviation: str, size: str, grade: str
) -> None:
    spec = catalog.by_id[cid]
    line = ordering_line(spec, 0.5)
    assert line.startswith(f"HIWIN {cid}-<thread length>-<total length>{deviation} ")
    assert "ball screw per ISO 3408 (DIN 69051)" in line and size in line
    assert f"tolerance class {grade}," in line
    assert "leadscrew" not in line and "anti-backlash" not in line
    assert "500 mm between the supports plus the ends, end machining to drawing" in line
    assert ordering_basis(spec) == BALL_BASIS


def test_a_rolled_ball_nut_has_play_and_a_ground_one_an_assumed_preload(catalog: Catalog) -> None:
    """HIWIN sec. 3.6: rolled nuts come with slight play (Table 4.4: at most 0.04 mm for
    R20-10K3-FSCDIN); the ground nut's preload is the catalog's assumption, 5 % of Ca
    (sec. 3.6.2's most for a single nut): 0.05 x 14,900 N = 745 N (Table 6.4, R20-05K4-FSC)."""
    rolled = ordering_line(catalog.by_id["R20-10K3-FSCDIN"], 0.5)
    assert "axial play at most 0.04 mm, no preload" in rolled
    assert "the preload" not in rolled
    ground = ordering_line(catalog.by_id["R20-05K4-FSC"], 0.5)
    assert "preloaded (745 N, 5 % of Ca)" in ground
    confirm = ground.split("Confirm with the maker: ", 1)[1]
    assert confirm.startswith("the preload (taken as 745 N")
    for line in (rolled, ground):
        assert "the operating temperature range (taken as -20 to 80 °C)" in line


# HIWIN GmbH's combined catalogue, sec. 2.2.4 "HIWIN order code", p. 95
# (https://vettevideo.com/hiwin_catalogues/linear_guideways/hiwin_linear_guideways_95.html):
# its three printed examples, each built from the parameters the page names.
def test_hiwins_printed_order_codes_are_built_from_their_parameters() -> None:
    nut = hiwin_nut_code("R", 40.0, 20.0, "K", 4, "FSCDIN")
    assert hiwin_order_code(nut, 800.0, 1000.0, 0.052, starts=2) == (
        "2R40-20K4-FSCDIN-800-1000-0,052"
    )
    assert hiwin_shaft_code("R", 40.0, 10.0, 800.0, 1000.0, 0.052, starts=1) == (
        "1R40-10-800-1000-0,052"
    )
    assert hiwin_nut_code("R", 40.0, 10.0, "K", 3, "FSCDIN") == "R40-10K3-FSCDIN"


def test_every_hiwin_nut_id_of_the_catalog_follows_the_makers_scheme(catalog: Catalog) -> None:
    """Each HIWIN nut id read back into its parts rebuilds itself, and its lead and
    nominal diameter are the row's (R20-10K3-FSCDIN: 20 mm nominal, lead 10 mm)."""
    hiwin = [s for s in catalog.by_id.values() if s.family_id.startswith("HIWIN")]
    assert len(hiwin) >= 20
    for spec in hiwin:
        found = HIWIN_NUT.fullmatch(spec.id)
        assert found, spec.id
        hand, nominal, lead, recirculation, circuits, nut = found.groups()
        rebuilt = hiwin_nut_code(
            hand, float(nominal), float(lead), recirculation, int(circuits), nut
        )
        assert rebuilt == spec.id
        assert float(lead) / 1000 == pytest.approx(spec.lead_m)
        # the shaft's outer diameter is at most the nominal one, down to 14.0 mm for
        # the 16 mm high-lead R16-20K2-FSCDIN (Table 4.4)
        nominal_m = float(nominal) / 1000
        assert 0.85 * nominal_m <= spec.outer_diameter_m <= 1.01 * nominal_m, spec.id
