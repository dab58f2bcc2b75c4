"""Start-up with a broken extra catalog: the app refuses to start and names file and field.

The loader's own rules are unit-tested in tests/test_catalog.py; these tests check what an
operator sees: ``create_app`` raising ``CatalogError``, and the console script and uvicorn
exiting non-zero with the file and the field on stderr.
"""

import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from app.catalog import CatalogError
from app.main import create_app
from app.settings import Settings

ROOT = Path(__file__).resolve().parents[1]

GOOD = """\
[family]
id = "TST"
name = "TST series, start-up test"

[defaults]
type = { value = "free-wheeling", provenance = "seed" }
backlash_mm = { min = 0.0, max = 0.1, provenance = "seed" }

[[series]]
id = "TST8000"
outer_diameter_mm = { value = 12.7, provenance = "seed" }
root_diameter_mm = { value = 10.0, provenance = "seed" }
inertia_kg_m2_per_in = { value = 3.67e-7, provenance = "seed" }
drag_torque_nm = { min = 0.0, max = 0.01, provenance = "seed" }
"""
OUTER = 'outer_diameter_mm = { value = 12.7, provenance = "seed" }\n'
ROOT_DIA = 'root_diameter_mm = { value = 10.0, provenance = "seed" }\n'


def _one_dir(text: str, name: str = "tst-series.toml") -> Callable[[Path], list[Path]]:
    def write(tmp: Path) -> list[Path]:
        (tmp / "extra").mkdir()
        (tmp / "extra" / name).write_text(text)
        return [tmp / "extra"]

    return write


def _duplicate_across_dirs(tmp: Path) -> list[Path]:
    for name in ("one", "two"):
        (tmp / name).mkdir()
    (tmp / "one" / "tst-series.toml").write_text(GOOD)
    (tmp / "two" / "tst-copy.toml").write_text(GOOD)
    return [tmp / "one", tmp / "two"]


def _duplicate_of_builtin(tmp: Path) -> list[Path]:
    (tmp / "extra").mkdir()
    text = GOOD.replace('id = "TST8000"', 'id = "ZBX8000"')
    (tmp / "extra" / "zbx-again.toml").write_text(text)
    return [tmp / "extra"]


# (case, directories to pass, file expected in the message, field expected in the message)
BROKEN: list[tuple[str, Callable[[Path], list[Path]], str, str]] = [
    ("bad-toml", _one_dir("[[series]\nid = 'X'\n", "broken.toml"), "broken.toml", "TOML"),
    ("missing-field", _one_dir(GOOD.replace(OUTER, "")), "tst-series.toml", "outer_diameter_mm"),
    (
        "negative-diameter",
        _one_dir(GOOD.replace("value = 12.7", "value = -12.7")),
        "tst-series.toml",
        "outer_diameter_mm",
    ),
    (
        "root-equals-outer",
        _one_dir(GOOD.replace(ROOT_DIA, ROOT_DIA.replace("10.0", "12.7"))),
        "tst-series.toml",
        "root_diameter_mm",
    ),
    (
        "root-above-outer",
        _one_dir(GOOD.replace(ROOT_DIA, ROOT_DIA.replace("10.0", "13.0"))),
        "tst-series.toml",
        "root_diameter_mm",
    ),
    ("duplicate-id-across-dirs", _duplicate_across_dirs, "tst-copy.toml", "id"),
    ("duplicate-of-builtin-id", _duplicate_of_builtin, "zbx-again.toml", "id"),
]
IDS = [case for case, *_ in BROKEN]


def test_the_good_extra_catalog_loads(tmp_path: Path) -> None:
    """The fixture the broken cases start from is itself valid."""
    app = create_app(Settings(catalog_dirs=_one_dir(GOOD)(tmp_path)))
    assert "TST8000" in app.state.catalog.series


@pytest.mark.parametrize(("case", "make", "file", "field"), BROKEN, ids=IDS)
def test_create_app_refuses_a_broken_catalog(
    tmp_path: Path, case: str, make: Callable[[Path], list[Path]], file: str, field: str
) -> None:
    with pytest.raises(CatalogError) as info:
        create_app(Settings(catalog_dirs=make(tmp_path)))
    message = str(info.value)
    assert file in message, message
    assert field in message, message


def test_create_app_names_a_missing_directory(tmp_path: Path) -> None:
    with pytest.raises(CatalogError, match="not-there"):
        create_app(Settings(catalog_dirs=[tmp_path / "not-there"]))


def test_settings_from_the_environment_reach_the_loader(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    dirs = _one_dir(GOOD.replace(OUTER, ""))(tmp_path)
    monkeypatch.setenv("LEADSCREW_CATALOG_DIRS", f'["{dirs[0]}"]')
    with pytest.raises(CatalogError, match="outer_diameter_mm"):
        create_app(Settings())


def _run(args: list[str], env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        args,
        cwd=ROOT,
        env={**os.environ, **(env or {})},
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )


@pytest.mark.parametrize(
    ("case", "make", "file", "field"),
    [BROKEN[1], BROKEN[3], BROKEN[5]],
    ids=[IDS[1], IDS[3], IDS[5]],
)
def test_console_script_exits_non_zero_naming_the_file(
    tmp_path: Path, case: str, make: Callable[[Path], list[Path]], file: str, field: str
) -> None:
    """``leadscrew-selector --catalog-dir BAD`` (the script runs ``app.cli:main``)."""
    args = [sys.executable, "-m", "app.cli", "--port", "1"]
    for directory in make(tmp_path):
        args += ["--catalog-dir", str(directory)]
    result = _run(args)
    assert result.returncode != 0
    assert file in result.stderr and field in result.stderr, result.stderr
    assert "Traceback" not in result.stderr  # one clear line, not a stack


def test_uvicorn_with_a_bad_catalog_in_the_environment_exits_non_zero(tmp_path: Path) -> None:
    """The path workers take: settings from LEADSCREW_CATALOG_DIRS, the app factory raises."""
    dirs = _one_dir(GOOD.replace(OUTER, ""))(tmp_path)
    result = _run(
        [sys.executable, "-m", "uvicorn", "app.main:create_app", "--factory", "--port", "1"],
        env={"LEADSCREW_CATALOG_DIRS": f'["{dirs[0]}"]'},
    )
    assert result.returncode != 0
    assert "tst-series.toml" in result.stderr and "outer_diameter_mm" in result.stderr
