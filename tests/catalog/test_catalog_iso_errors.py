"""Catalog errors for the fields of standard threads, nut bearing limits, ranges and a
user's file-wide provenance: each names the file, the entry and the field."""

import math
from pathlib import Path

import pytest

from app.catalog import CatalogError, load_catalog

#: A minimal family of one ISO size with a bronze nut rated by contact pressure (@H: a
#: handbook value with its source).
FAMILY = """schema = 2

[family]
id = "X"
name = "Test family"
id_pattern = "X{d_mm:g}x{lead_mm:g}{multi_start}-{variant}"
thread_form = { name = "ISO 2904", half_angle_deg = 15.0, @H }

[nut_types.plain]
anti_backlash = false

[variants.bronze]
coated = false
oil_compatible = { value = true, provenance = "handbook", source = "oiled" }
friction_dynamic = { value = 0.13, range = [0.10, 0.16], @H }
friction_static = { value = 0.16, @H }
bearing_pressure_mpa_by_speed_m_s = { value = [[0.05, 11.0], [0.25, 1.0]], @H }

[defaults]
type = { value = "plain", provenance = "handbook", source = "plain nut" }
nut_variants = { value = ["bronze"], provenance = "handbook", source = "x" }
screw_material = { value = "x-steel", provenance = "handbook", source = "x" }
nut_material = { value = "bronze", provenance = "handbook", source = "x" }
drag_torque_nm = { min = 0.0, max = 0.0, provenance = "assumed", source = "x" }
backlash_mm = { min = 0.05, max = 0.3, provenance = "assumed", source = "x" }
nut_length_to_d = { value = 2.0, range = [1.5, 2.5], provenance = "assumed", source = "x" }

[materials.x-steel]
youngs_modulus_gpa = { value = 207.0, provenance = "handbook", source = "x" }
density_kg_m3 = { value = 7800.0, provenance = "handbook", source = "x" }
expansion_per_c = { value = 11.7e-6, provenance = "handbook", source = "x" }

[[series]]
id = "X10"
outer_diameter_mm = { value = 10.0, provenance = "handbook", source = "ISO 2904" }
pitch_mm = { value = 2.0, provenance = "handbook", source = "ISO 2904" }
starts = { value = [1, 2], provenance = "handbook", source = "x" }
""".replace("@H", 'provenance = "handbook", source = "S"')


def _load(tmp_path: Path, text: str) -> None:
    directory = tmp_path / "extra"
    directory.mkdir()
    (directory / "x.toml").write_text(text)
    load_catalog([directory])


def _changed(old: str, new: str) -> str:
    assert old in FAMILY, old
    return FAMILY.replace(old, new)


def test_the_minimal_family_loads(tmp_path: Path) -> None:
    directory = tmp_path / "extra"
    directory.mkdir()
    (directory / "x.toml").write_text(FAMILY)
    merged = load_catalog([directory])
    assert [s.id for s in merged.series["X10"].screws] == ["X10x2-bronze", "X10x4(P2)-bronze"]


#: The bronze nut's line of the fixture under which a thrust table is added.
BEARING_LINE = "bearing_pressure_mpa_by_speed_m_s = { value = [[0.05, 11.0], [0.25, 1.0]], "


def _thrust(rows: str, extra: str = "") -> str:
    """The fixture with a maker's thrust table ``rows`` (and ``extra`` lines) on its nut."""
    line = f'dynamic_thrust_n_by_size = {{ value = {rows}, provenance = "vendor", source = "T" }}'
    return _changed(BEARING_LINE, f"{line}\n{extra}{BEARING_LINE}")


THRUST = "dynamic_thrust_n_by_size"
THRUST_ERRORS = [
    pytest.param(_thrust("[[10.0, 2.0]]"), "rows of 3 numbers", id="thrust-row-short"),
    pytest.param(_thrust("[[10.0, 2.0, -5.0]]"), "numbers >= 0", id="thrust-negative"),
    pytest.param(_thrust("[[10.0, 2.0, 0.0]]"), "the thrust must be > 0", id="thrust-zero"),
    pytest.param(_thrust("[]"), "at least one row", id="thrust-empty"),
    pytest.param(_thrust("[[2.0, 2.0, 90.0]]"), "below d", id="thrust-pitch-not-below-d"),
    pytest.param(_thrust("[[10.0, 0.0, 90.0]]"), "pitch must be > 0", id="thrust-pitch-zero"),
    pytest.param(
        _thrust("[[10.0, 2.0, 255.0], [10.0, 2.0, 278.0]]"),
        "size Tr10x2 is listed twice",
        id="thrust-size-twice",
    ),
    pytest.param(
        _thrust(
            "[[10.0, 2.0, 255.0]]",
            'dynamic_pressure_mpa = { value = 2.5, provenance = "assumed", source = "x", '
            "range = [2.5, 7.5] }\n",
        ),
        "either this or dynamic_pressure_mpa",
        id="thrust-beside-a-pressure",
    ),
]


@pytest.mark.parametrize(("text", "reason"), THRUST_ERRORS)
def test_a_bad_thrust_table_names_file_entry_and_field(
    tmp_path: Path, text: str, reason: str
) -> None:
    """A maker's allowable dynamic thrust table (rows [d mm, P mm, thrust N]) that is not
    one positive thrust per size stops start-up, naming the file, variant and field."""
    with pytest.raises(CatalogError) as caught:
        _load(tmp_path, text)
    error = caught.value
    assert (error.file, error.entry, error.field) == ("x.toml", "X10.variants.bronze", THRUST)
    assert reason in str(error)


def test_a_thrust_table_rates_its_size_at_the_published_thrust(tmp_path: Path) -> None:
    """A listed size rates at its row's thrust, whatever the assumed nut length (the
    pressure is recomputed at both ends of nut_length_to_d, 1.5 and 2.5 d): X10 rows
    255 N; a nut 2 d = 20 mm long over P 2 mm engages 10 turns of pi d2 H1 = pi 9 1 mm^2,
    282.7 mm^2, so 0.902 MPa; at 1.5 d, 15 mm, 212.1 mm^2 and 1.202 MPa."""
    directory = tmp_path / "extra"
    directory.mkdir()
    (directory / "x.toml").write_text(_thrust("[[10.0, 2.0, 255.0], [20.0, 4.0, 980.0]]"))
    screw = load_catalog([directory]).by_id["X10x2-bronze"]
    assert screw.dynamic_pressure_pa == pytest.approx(255.0 / (10 * math.pi * 9e-3 * 1e-3))
    low, high = screw.assumption_ends["nut_length_to_d"]
    for end in (low, high):
        area = end["nut_length_m"] / 2e-3 * math.pi * 9e-3 * 1e-3
        assert end["dynamic_pressure_pa"] * area == pytest.approx(255.0)
    assert low["dynamic_pressure_pa"] == pytest.approx(1.202e6, rel=1e-3)
    prov = screw.provenance["dynamic_pressure"]
    assert (prov.kind, prov.source) == ("vendor", f"{prov.source.split(': ')[0]}: T")
    assert prov.source.startswith("Tr10x2 255 N over 283 mm^2")


@pytest.mark.parametrize(
    ("text", "entry", "field", "reason"),
    [
        pytest.param(
            _changed("[[0.05, 11.0], [0.25, 1.0]]", "[[0.25, 11.0], [0.05, 1.0]]"),
            "X10.variants.bronze",
            "bearing_pressure_mpa_by_speed_m_s",
            "rise in sliding speed",
            id="table-not-rising",
        ),
        pytest.param(
            _changed("[[0.05, 11.0], [0.25, 1.0]]", "[[0.05, 1.0], [0.25, 11.0]]"),
            "X10.variants.bronze",
            "bearing_pressure_mpa_by_speed_m_s",
            "must not rise with the sliding speed",
            id="table-pressure-rising-with-speed",
        ),
        pytest.param(
            _changed("[[0.05, 11.0], [0.25, 1.0]]", "[[0.05, 11.0], [0.25]]"),
            "X10.variants.bronze",
            "bearing_pressure_mpa_by_speed_m_s",
            "rows of 2 numbers",
            id="table-row-short",
        ),
        pytest.param(
            _changed(
                "[defaults]",
                'specific_wear_rate_mm3_n_m = { value = 1e-8, provenance = "assumed", '
                'source = "x" }\n\n[defaults]',
            ),
            "X10.variants.bronze",
            "allowed_wear_to_flank_height",
            "needs both the wear rate and the allowed wear",
            id="wear-rate-without-allowed-wear",
        ),
        pytest.param(
            _changed(
                "[defaults]",
                'specific_wear_rate_mm3_n_m = { value = 1e-8, provenance = "assumed", '
                'source = "x" }\nallowed_wear_to_flank_height = { value = 1.5, '
                'provenance = "assumed", source = "x" }\n\n[defaults]',
            ),
            "X10.variants.bronze",
            "allowed_wear_to_flank_height",
            "must be a fraction",
            id="allowed-wear-above-one",
        ),
        pytest.param(
            _changed("range = [0.10, 0.16]", "range = [0.14, 0.16]"),
            "X10.variants.bronze",
            "friction_dynamic",
            "outside its range",
            id="value-outside-range",
        ),
        pytest.param(
            _changed("range = [0.10, 0.16]", 'range = [0.1, "high"]'),
            "X10.variants.bronze",
            "friction_dynamic",
            "'range' must be [low, high]",
            id="range-not-numbers",
        ),
        pytest.param(
            _changed(
                "starts = {",
                'leads_mm = { value = [2.0], provenance = "handbook", source = "x" }\nstarts = {',
            ),
            "X10",
            "leads_mm",
            "either leads_mm or starts",
            id="starts-and-leads",
        ),
        pytest.param(
            _changed(
                "starts = {",
                'root_diameter_mm = { value = 7.5, provenance = "handbook", source = "x" }\n'
                "starts = {",
            ),
            "X10",
            "root_diameter_mm",
            "follows from pitch_mm",
            id="root-beside-pitch",
        ),
        pytest.param(
            _changed("value = [1, 2]", "value = [1, 1.5]"),
            "X10",
            "starts",
            "whole numbers",
            id="starts-not-whole",
        ),
        pytest.param(
            _changed("pitch_mm = { value = 2.0", "pitch_mm = { value = 50.0"),
            "X10",
            "pitch_mm",
            "above the ISO 2904 range",
            id="pitch-above-the-standard",
        ),
        pytest.param(
            _changed("half_angle_deg = 15.0", "half_angle_deg = 14.5"),
            "X10",
            "pitch_mm",
            "15 deg half-angle",
            id="pitch-on-an-acme-thread",
        ),
        pytest.param(
            _changed(
                'nut_length_to_d = { value = 2.0, range = [1.5, 2.5], provenance = "assumed", '
                'source = "x" }\n',
                "",
            ),
            "X10",
            "nut_length_mm",
            "rated by contact pressure",
            id="bearing-limit-without-nut-length",
        ),
        pytest.param(
            _changed(
                'friction_static = { value = 0.16, provenance = "handbook", source = "S" }\n', ""
            ),
            "X10",
            "friction_static",
            "missing (here or in variant 'bronze')",
            id="no-static-friction-anywhere",
        ),
        pytest.param(
            _changed("schema = 2\n", 'schema = 2\nprovenance = "handbook"\n'),
            "-",
            "provenance",
            'must be "user"',
            id="file-wide-provenance-not-user",
        ),
        pytest.param(
            _changed(
                "[variants.bronze]\n",
                '[variants.bronze]\nmax_pressure_mpa = { value = -1.0, provenance = "handbook", '
                'source = "x" }\n',
            ),
            "X10.variants.bronze",
            "max_pressure_mpa",
            "> 0",
            id="negative-max-pressure",
        ),
    ],
)
def test_new_fields_name_file_entry_and_field(
    tmp_path: Path, text: str, entry: str, field: str, reason: str
) -> None:
    with pytest.raises(CatalogError) as caught:
        _load(tmp_path, text)
    error = caught.value
    assert (error.file, error.entry, error.field) == ("x.toml", entry, field), str(error)
    assert reason in str(error)


def test_a_users_file_wide_provenance_fills_only_what_is_missing(tmp_path: Path) -> None:
    text = _changed("schema = 2\n", 'schema = 2\nprovenance = "user"\n').replace(
        'outer_diameter_mm = { value = 10.0, provenance = "handbook", source = "ISO 2904" }',
        "outer_diameter_mm = { value = 10.0 }",
    )
    directory = tmp_path / "extra"
    directory.mkdir()
    (directory / "x.toml").write_text(text)
    series = load_catalog([directory]).series["X10"]
    assert series.fields["outer_diameter"].provenance.kind == "user"
    assert series.fields["outer_diameter"].provenance.source == "user catalog file x.toml"
    assert series.fields["pitch"].provenance.kind == "handbook"
