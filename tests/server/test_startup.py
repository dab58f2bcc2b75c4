"""Start-up with a broken extra catalog: the app refuses to start and names file and field.

The loader's own rules are unit-tested in tests/catalog/test_catalog.py; these tests check what an
operator sees: ``create_app`` raising ``CatalogError``, and the console script and uvicorn
exiting non-zero with the file and the field on stderr.
"""

import json
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import httpx
import pytest

from app.catalog import CatalogError
from app.catalog.files import MAX_FILE_BYTES
from app.main import create_app
from app.server.settings import Settings
from deploy.local import START_CEILING_S, free_port, stop, wait_until_healthy

ROOT = Path(__file__).resolve().parents[2]

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
        timeout=START_CEILING_S,  # a ceiling: the run ends when the process does
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


# --- files the loader must refuse before reading them whole -------------------------------

EXAMPLE = ROOT / "examples" / "my-family" / "my-family.toml"


def _deep(tmp: Path) -> list[Path]:
    """Arrays nested 5,000 deep: tomllib would recurse past Python's limit."""
    return _one_dir("a = " + "[" * 5000 + "]" * 5000 + "\n", "deep.toml")(tmp)


def _nested_a_little_too_deep(tmp: Path) -> list[Path]:
    """Parsed without trouble, but nested past the loader's limit (17 levels)."""
    return _one_dir("a = " + "[" * 17 + "]" * 17 + "\n", "nested.toml")(tmp)


def _device(tmp: Path) -> list[Path]:
    """A .toml linked to /dev/zero: read whole, it would fill memory."""
    (tmp / "extra").mkdir()
    (tmp / "extra" / "zero.toml").symlink_to("/dev/zero")
    return [tmp / "extra"]


def _fifo(tmp: Path) -> list[Path]:
    """A FIFO: opening it waits for a writer, for ever."""
    (tmp / "extra").mkdir()
    os.mkfifo(tmp / "extra" / "pipe.toml")
    return [tmp / "extra"]


def _large(tmp: Path) -> list[Path]:
    """A file past the size limit (sparse: it costs no disk)."""
    (tmp / "extra").mkdir()
    with (tmp / "extra" / "large.toml").open("wb") as file:
        file.truncate(MAX_FILE_BYTES + 1)
    return [tmp / "extra"]


def _many_starts(tmp: Path) -> list[Path]:
    """A thread of 4e9 starts (the example family with its 4 starts made 4,000,000,000)."""
    text = EXAMPLE.read_text().replace(
        "starts = { value = [4] }", "starts = { value = [4000000000] }"
    )
    return _one_dir(text, "my-family.toml")(tmp)


def _deep_table(tmp: Path) -> list[Path]:
    """A table 500 levels deep in 1 kB of dotted keys: tomllib reads it, and counting its
    depth by recursion passed Python's limit (a RecursionError traceback)."""
    return _one_dir("[" + ".".join(["a"] * 500) + "]\nx = 1\n", "table.toml")(tmp)


def _example(old: str, new: str) -> Callable[[Path], list[Path]]:
    """The example family with one piece of text replaced (which must be there)."""
    assert old in EXAMPLE.read_text(), old
    return _one_dir(EXAMPLE.read_text().replace(old, new, 1), "my-family.toml")


#: the example's id pattern, and its first size (Tr8 x 2)
PATTERN = 'id_pattern = "MY-Tr{d_mm:g}'
TR8 = "outer_diameter_mm = { value = 8.0 }"
HOSTILE: list[tuple[str, Callable[[Path], list[Path]], str, str]] = [
    ("deep-table", _deep_table, "table.toml", "nested deeper than 16"),
    # {d_mm:99999999999} asked for 100 GB (MemoryError); 50,000,000 took 228 MB
    (
        "id-width",
        _example(PATTERN, 'id_pattern = "MY-Tr{d_mm:99999999999}'),
        "my-family.toml",
        "a width or precision of at most 99",
    ),
    (
        "id-width-nested",
        _example(PATTERN, 'id_pattern = "MY-Tr{d_mm:{starts}}'),
        "my-family.toml",
        "a width or precision of at most 99",
    ),
    (
        "id-too-long",
        _example(PATTERN, 'id_pattern = "MY-Tr{d_mm:99}'),
        "my-family.toml",
        "id longer than 60",
    ),
    (
        "builtin-family-id",
        _example('id = "MY"', 'id = "B"'),
        "my-family.toml",
        "family id 'B' is also declared in b-series.toml",
    ),
    # ISO 2904: d3 = d - 2 (0.5 P + a_c) = 0.8 - 2 (1 + 0.25) = -1.7 mm
    (
        "negative-root",
        _example(TR8, "outer_diameter_mm = { value = 0.8 }"),
        "my-family.toml",
        "root diameter must be above 0, got -1.7 mm",
    ),
    (
        "vanishing-diameter",
        _example(TR8, "outer_diameter_mm = { value = 1e-300 }"),
        "my-family.toml",
        "root diameter must be above 0",
    ),
    (
        "lead-not-starts-of-pitch",
        _example("starts = { value = [4] }", "leads_mm = { value = [3.0] }"),
        "my-family.toml",
        "lead 3 mm is not a whole number of starts of pitch 2 mm",
    ),
    ("deep", _deep, "deep.toml", "nested deeper than 16"),
    ("nested", _nested_a_little_too_deep, "nested.toml", "nested deeper than 16"),
    ("device", _device, "zero.toml", "not a regular file"),
    ("fifo", _fifo, "pipe.toml", "not a regular file"),
    ("large", _large, "large.toml", f"larger than {MAX_FILE_BYTES} bytes"),
    ("many-starts", _many_starts, "my-family.toml", "starts"),
]
HOSTILE_IDS = [case for case, *_ in HOSTILE]


def test_the_example_family_loads_as_the_many_starts_case_starts(tmp_path: Path) -> None:
    assert "starts = { value = [4] }" in EXAMPLE.read_text()
    assert "MY-Tr8-P2" in create_app(Settings(catalog_dirs=[EXAMPLE.parent])).state.catalog.series


@pytest.mark.parametrize(("case", "make", "file", "reason"), HOSTILE, ids=HOSTILE_IDS)
def test_the_loader_refuses_a_hostile_file(
    tmp_path: Path, case: str, make: Callable[[Path], list[Path]], file: str, reason: str
) -> None:
    with pytest.raises(CatalogError) as info:
        create_app(Settings(catalog_dirs=make(tmp_path)))
    assert file in str(info.value) and reason in str(info.value), str(info.value)


@pytest.mark.parametrize(
    ("case", "make", "file", "reason"),
    [h for h in HOSTILE if h[0] in ("deep", "fifo", "deep-table", "builtin-family-id")],
    ids=["deep-table", "builtin-family-id", "deep", "fifo"],
)
def test_catalog_dirs_from_the_environment_are_checked_before_workers_start(
    tmp_path: Path, case: str, make: Callable[[Path], list[Path]], file: str, reason: str
) -> None:
    """LEADSCREW_CATALOG_DIRS gets the command line's checks: two workers would each fail
    and be started again, for ever; the script exits 2 first, naming the file."""
    dirs = make(tmp_path)
    result = _run(
        [sys.executable, "-m", "app.cli", "--port", "1", "--workers", "2"],
        env={"LEADSCREW_CATALOG_DIRS": json.dumps([str(d) for d in dirs])},
    )
    assert result.returncode == 2, result.stderr
    assert file in result.stderr and reason in result.stderr, result.stderr
    assert "Traceback" not in result.stderr


@pytest.mark.parametrize(
    ("variable", "value"),
    [("LEADSCREW_CATALOG_DIRS", "not json"), ("LEADSCREW_MAX_CONNECTIONS", "many")],
    ids=["not-json", "not-a-number"],
)
def test_a_bad_setting_stops_the_script_naming_it(variable: str, value: str) -> None:
    result = _run([sys.executable, "-m", "app.cli", "--port", "1"], env={variable: value})
    assert result.returncode == 2, result.stderr
    assert result.stderr.startswith("settings error:") and "Traceback" not in result.stderr
    assert variable.removeprefix("LEADSCREW_").lower() in result.stderr.lower()


# --- the command line's catalog directories reach every worker ------------------------------


def _console_script() -> Path:
    """The ``leadscrew-selector`` script of this interpreter's environment."""
    script = Path(sys.executable).parent / "leadscrew-selector"
    assert script.is_file(), f"{script}: install the project (pip install -e .)"
    return script


@pytest.mark.parametrize("workers", [1, 2])
def test_catalog_dir_on_the_command_line_is_served(workers: int) -> None:
    """``leadscrew-selector --catalog-dir examples/my-family`` serves the family MY with one
    worker (the app factory runs in the script's own process, whose settings were read
    before the command line was applied) as with two (each worker a process of its own)."""
    port = free_port()
    args = [str(_console_script()), "--catalog-dir", str(EXAMPLE.parent), "--port", str(port)]
    # the script imports the package first on PYTHONPATH: this checkout's
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    env.pop("LEADSCREW_CATALOG_DIRS", None)
    proc = subprocess.Popen([*args, "--workers", str(workers), "--log-level", "warning"], env=env)
    try:
        wait_until_healthy(port, proc, "leadscrew-selector")
        with httpx.Client(base_url=f"http://127.0.0.1:{port}", timeout=30) as client:
            ids = {s["id"] for s in client.get("/api/v1/series").json()["series"]}
            assert "MY-Tr8-P2" in ids, sorted(ids)
            for _ in range(2 * workers):  # whichever worker answers
                answer = client.get("/api/v1/series/MY-Tr8-P2", headers={"Connection": "close"})
                assert answer.status_code == 200
    finally:
        stop(proc)
