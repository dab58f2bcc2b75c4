"""Faults of the file system and of the family schema stop the loader with a CatalogError
naming the file, the entry and the field (file-level faults name "-" for both), never a
traceback: the CLI turns the error into one line and exit code 2."""

import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from app.catalog import CatalogError, load_catalog

ROOT = Path(__file__).resolve().parents[2]
FIXTURES = Path(__file__).parents[1] / "fixtures"
ISO_TEXT = (FIXTURES / "catalog_iso" / "tr-family.toml").read_text()
MY_TEXT = (FIXTURES / "catalog_extra" / "my-series.toml").read_text()
FILE_LEVEL = ("-", "-")


def _dir(tmp_path: Path, files: dict[str, str | bytes]) -> Path:
    directory = tmp_path / "extra"
    directory.mkdir(exist_ok=True)
    for name, content in files.items():
        path = directory / name
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content)
    return directory


def _error(directory: Path) -> CatalogError:
    with pytest.raises(CatalogError) as caught:
        load_catalog([directory])
    return caught.value


def _iso(old: str, new: str) -> str:
    """The ISO fixture with one piece of text replaced (which must be there)."""
    assert old in ISO_TEXT, old
    return ISO_TEXT.replace(old, new, 1)


# ---------------------------------------------------------------------------------------
# the file system


def test_a_symlink_loop_between_files(tmp_path: Path) -> None:
    directory = _dir(tmp_path, {})
    (directory / "a.toml").symlink_to(directory / "b.toml")
    (directory / "b.toml").symlink_to(directory / "a.toml")
    error = _error(directory)
    assert (error.file, error.entry, error.field) == ("a.toml", *FILE_LEVEL)
    assert "cannot read" in str(error)


def test_a_symlink_loop_between_directories(tmp_path: Path) -> None:
    """A subdirectory linking back to its parent would load every series twice."""
    directory = _dir(tmp_path, {"tr-family.toml": ISO_TEXT})
    (directory / "again").symlink_to(directory)
    error = _error(directory)
    assert (error.file, error.entry, error.field) == (str(directory / "again"), *FILE_LEVEL)
    assert "symlink loop" in str(error)


def test_invalid_utf8(tmp_path: Path) -> None:
    text = ISO_TEXT.encode().replace(b"ISO 2904 trapezoidal", b"ISO 2904 \xff", 1)
    error = _error(_dir(tmp_path, {"tr-family.toml": text}))
    assert (error.file, error.entry, error.field) == ("tr-family.toml", *FILE_LEVEL)
    assert "not valid UTF-8 at byte" in str(error)


def test_an_unreadable_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Permission denied (simulated: the tests may run as root, who reads anything)."""
    directory = _dir(tmp_path, {"tr-family.toml": ISO_TEXT})
    real_open = Path.open

    def open_file(path: Path, *args: Any, **kwargs: Any) -> Any:
        if path.name == "tr-family.toml":
            raise PermissionError(13, "Permission denied", str(path))
        return real_open(path, *args, **kwargs)

    monkeypatch.setattr(Path, "open", open_file)
    error = _error(directory)
    assert (error.file, error.entry, error.field) == ("tr-family.toml", *FILE_LEVEL)
    assert "Permission denied" in str(error)


def test_an_unreadable_directory(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    directory = _dir(tmp_path, {"tr-family.toml": ISO_TEXT})
    real_iterdir = Path.iterdir

    def iterdir(path: Path) -> Iterator[Path]:
        if path == directory:
            raise PermissionError(13, "Permission denied", str(path))
        return real_iterdir(path)

    monkeypatch.setattr(Path, "iterdir", iterdir)
    error = _error(directory)
    assert (error.file, error.entry, error.field) == (str(directory), *FILE_LEVEL)
    assert "Permission denied" in str(error)


# ---------------------------------------------------------------------------------------
# tables of the wrong TOML type and schema faults

WRONG = [
    pytest.param("family = 3", "-", "family", "an integer", id="family-3"),
    pytest.param("defaults = [1]", "-", "defaults", "an array", id="defaults-array"),
    pytest.param("materials = 3", "-", "materials", "an integer", id="materials-3"),
    pytest.param("materials.steel = 3", "materials", "steel", "an integer", id="material-3"),
    pytest.param("variants.bronze = 3", "variants", "bronze", "an integer", id="variant-3"),
    pytest.param('nut_types = "plain"', "-", "nut_types", "text", id="nut-types-text"),
    pytest.param("rules = [2]", "-", "rules", "an array", id="rules-array"),
    pytest.param(
        'rules.traverse_speed = "fast"', "rules", "traverse_speed", "text", id="rule-text"
    ),
]


@pytest.mark.parametrize(("line", "entry", "field", "got"), WRONG)
def test_a_table_of_the_wrong_type(
    tmp_path: Path, line: str, entry: str, field: str, got: str
) -> None:
    error = _error(_dir(tmp_path, {"tr-family.toml": f"schema = 2\n{line}\n"}))
    assert (error.file, error.entry, error.field) == ("tr-family.toml", entry, field)
    assert f"must be a table, got {got}" in str(error)


SCHEMA_FAULTS = [
    pytest.param(
        _iso('[[series]]\nid = "Tr10x2"\n', '[[series]]\nid = "Tr10x2"\nvariants = 3\n'),
        "Tr10x2",
        "variants",
        "table of variant tables",
        id="series-variants-3",
    ),
    pytest.param(
        _iso(
            'value = [2.0, 4.0], provenance = "handbook"',
            'value = [2.0, 4.0, 2.0], provenance = "handbook"',
        ),
        "Tr10x2",
        "leads_mm",
        "lead 2 mm is listed twice",
        id="duplicate-lead",
    ),
    pytest.param(
        _iso('value = ["bronze", "acetal"]', 'value = ["bronze", "brass"]'),
        "Tr10x2",
        "nut_variants",
        "no variant 'brass'",
        id="undeclared-variant",
    ),
    pytest.param(
        _iso("-{variant}", "-{variant.__class__}"),
        "family",
        "id_pattern",
        "unknown placeholder",
        id="pattern-attribute-walk",
    ),
    pytest.param(
        _iso("-{variant}", ""),
        "Tr10x2",
        "id_pattern",
        "also made by Tr10x2",
        id="pattern-without-variant",
    ),
    pytest.param(
        _iso("half_angle_deg = 15.0", "half_angle_deg = 50.0"),
        "family",
        "thread_form",
        "below 45",
        id="half-angle-50",
    ),
    pytest.param(
        _iso('id_pattern = "', 'extends = 3\nid_pattern = "'),
        "family",
        "extends",
        "group id",
        id="extends-not-text",
    ),
    pytest.param(
        _iso('id_pattern = "', 'extends = "kerk"\nid_pattern = "'),
        "family",
        "extends",
        "no group 'kerk'",
        id="extends-unknown-group",
    ),
    pytest.param(
        _iso("[defaults]\n", "[rules.max_rpm]\nlimit = 3\n[defaults]\n"),
        "rules",
        "max_rpm",
        "unknown rule",
        id="unknown-rule",
    ),
    pytest.param(
        _iso(
            "[defaults]\n",
            "[rules.traverse_speed]\nbands_lead_mm_speed_mm_s = { value = [[12.0, 2.5, 100.0]], "
            'provenance = "assumed", source = "x" }\n[defaults]\n',
        ),
        "rules.traverse_speed",
        "bands_lead_mm_speed_mm_s",
        "from < to",
        id="band-upside-down",
    ),
    pytest.param(
        _iso(
            "coated = false\noil_compatible = { value = true",
            "coated = false\noil_compatible = { value = 1",
        ),
        "Tr10x2.variants.bronze",
        "oil_compatible",
        "true or false",
        id="oil-rule-not-boolean",
    ),
    pytest.param(_iso("schema = 2", "schema = 3"), "-", "schema", "must be 2", id="schema-3"),
    pytest.param(
        _iso("schema = 2", "schema = 2\nseries_names = 1"),
        "-",
        "series_names",
        "unknown top-level",
        id="unknown-table",
    ),
]


@pytest.mark.parametrize(("text", "entry", "field", "reason"), SCHEMA_FAULTS)
def test_a_family_schema_fault(
    tmp_path: Path, text: str, entry: str, field: str, reason: str
) -> None:
    error = _error(_dir(tmp_path, {"tr-family.toml": text}))
    assert (error.file, error.entry, error.field) == ("tr-family.toml", entry, field)
    assert reason in str(error)


def test_a_group_that_extends_itself(tmp_path: Path) -> None:
    group = 'schema = 2\n[group]\nid = "mine"\nextends = "mine"\n'
    error = _error(
        _dir(
            tmp_path,
            {"common.toml": group, "my-series.toml": MY_TEXT.replace('extends = "seed"\n', "")},
        )
    )
    assert (error.file, error.entry, error.field) == ("common.toml", "group", "extends")
    assert "extends itself" in str(error)


def test_a_group_of_the_wrong_type(tmp_path: Path) -> None:
    error = _error(_dir(tmp_path, {"common.toml": "schema = 2\ngroup = 3\n"}))
    assert (error.file, error.entry, error.field) == ("common.toml", "-", "group")


# ---------------------------------------------------------------------------------------
# the command line


def test_the_cli_exits_2_with_one_line_for_invalid_utf8(tmp_path: Path) -> None:
    """app/cli.py: a CatalogError is "catalog error: ..." and exit code 2, no traceback."""
    directory = _dir(tmp_path, {"tr-family.toml": b"schema = 2\n# \xff\n"})
    result = subprocess.run(
        [sys.executable, "-m", "app.cli", "--port", "1", "--catalog-dir", str(directory)],
        cwd=ROOT,
        env=dict(os.environ),
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert result.returncode == 2, result.stderr
    assert result.stderr.startswith("catalog error: tr-family.toml: entry '-': field '-'")
    assert "UTF-8" in result.stderr and "Traceback" not in result.stderr
