"""Repository rules: lint, format, types, and the core's independence from the web."""

import ast
import csv
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.readme_install import ON_INSTALL

ROOT = Path(__file__).resolve().parents[1]
WEB_PACKAGES = {"fastapi", "starlette", "jinja2", "pydantic", "pydantic_settings", "plotly"}


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", *args], cwd=ROOT, capture_output=True, text=True, check=False
    )


def test_ruff_lint() -> None:
    result = _run("ruff", "check", "app", "tests", "bench", "deploy")
    assert result.returncode == 0, result.stdout + result.stderr


def test_ruff_format() -> None:
    result = _run("ruff", "format", "--check", "app", "tests", "bench", "deploy")
    assert result.returncode == 0, result.stdout + result.stderr


def test_mypy_app() -> None:
    result = _run("mypy", "app")
    assert result.returncode == 0, result.stdout + result.stderr


def _imports(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(), filename=str(path))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name.split(".")[0] for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names.add(node.module.split(".")[0])
    return names


CORE = ROOT / "app" / "core"


def _app_imports(path: Path) -> set[str]:
    """The app modules a file imports by absolute name (e.g. 'app.contract.units')."""
    tree = ast.parse(path.read_text())
    found = {
        alias.name
        for node in ast.walk(tree)
        if isinstance(node, ast.Import)
        for alias in node.names
    }
    found |= {
        node.module
        for node in ast.walk(tree)
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0
    }
    return {name for name in found if name == "app" or name.startswith("app.")}


@pytest.mark.parametrize("path", sorted(CORE.rglob("*.py")), ids=lambda p: str(p.relative_to(CORE)))
def test_core_has_no_web_imports(path: Path) -> None:
    """Every module of the core, at any depth: no web stack, nothing of the app outside
    the core (the core is pure; the edges import it, never the other way)."""
    assert not _imports(path) & WEB_PACKAGES
    assert {m for m in _app_imports(path) if not m.startswith("app.core")} == set()


#: The layers of app/, lowest first: a module imports only from its own folder and from
#: the tiers below its own (core < catalog < contract < report < api, web < main, cli).
#: The server's plumbing sits beside the contract: it wraps the layers above and imports
#: no inputs, results or pages; the package's face (its version) and ``paths`` (where the
#: bundled files live) are the floor.
LAYERS: tuple[frozenset[str], ...] = tuple(
    frozenset(tier.split())
    for tier in (
        "__init__ paths",
        "core",
        "catalog",
        "contract server",
        "report",
        "api web",
        "main cli",
    )
)
TIER = {name: rank for rank, tier in enumerate(LAYERS) for name in tier}


def _layer(module: str) -> str:
    """The layer of a module by dotted name: its folder (or file) under ``app``."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def _modules() -> list[Path]:
    return sorted((ROOT / "app").rglob("*.py"))


def test_every_module_has_a_layer() -> None:
    layers = {_layer(".".join(p.relative_to(ROOT).with_suffix("").parts)) for p in _modules()}
    assert layers == set(TIER)


def _upward_imports(path: Path, root: Path = ROOT) -> set[str]:
    own = _layer(".".join(path.relative_to(root).with_suffix("").parts))
    return {
        f"{path.relative_to(root)} imports {name}"
        for name in _app_imports(path)
        if _layer(name) != own and TIER[_layer(name)] >= TIER[own]
    }


@pytest.mark.parametrize("layer", sorted(TIER))
def test_no_layer_imports_its_own_tier_or_above(layer: str) -> None:
    """No import sideways or upward, no exception: e.g. the catalog reads units from the
    core's table, not the contract; the service reads share links from the contract, not
    from the pages; the error type lives with the server, its page rendering with the web."""
    paths = [
        p for p in _modules() if p.relative_to(ROOT / "app").parts[0].removesuffix(".py") == layer
    ]
    assert paths
    assert set().union(*map(_upward_imports, paths)) == set()


def test_layer_scan_catches_an_upward_import(tmp_path: Path) -> None:
    bad = tmp_path / "app" / "catalog" / "probe.py"
    bad.parent.mkdir(parents=True)
    bad.write_text("from app.contract.units import to_si\nfrom app.core.units import from_si\n")
    assert _upward_imports(bad, tmp_path) == {"app/catalog/probe.py imports app.contract.units"}


def test_import_scan_catches_a_web_import(tmp_path: Path) -> None:
    bad = tmp_path / "bad.py"
    bad.write_text("from fastapi import FastAPI\nimport pydantic.fields\n")
    assert _imports(bad) & WEB_PACKAGES == {"fastapi", "pydantic"}


def test_dockerfile_copies_existing_paths() -> None:
    lines = (ROOT / "Dockerfile").read_text().splitlines()
    copied = [part for line in lines if line.startswith("COPY ") for part in line.split()[1:-1]]
    assert copied, "Dockerfile copies nothing"
    for path in copied:
        assert (ROOT / path).exists(), f"Dockerfile copies missing {path}"
    text = "\n".join(lines)
    assert "USER " in text and "EXPOSE 8000" in text and "/api/v1/health" in text


def test_ci_runs_the_readme_test_command() -> None:
    readme = (ROOT / "README.md").read_text()
    command = "python3 -m pip install -c constraints.txt -e '.[test]' && python3 -m pytest"
    assert command in readme
    assert "README.md" in (ROOT / ".ci" / "run").read_text()


@pytest.mark.skipif(shutil.which("git") is None, reason="needs git")
@ON_INSTALL
def test_wheel_carries_templates_static_and_catalog(installed: Path) -> None:
    """The wheel pip builds from the checkout: the one README's install step built and
    installed (the ``installed`` fixture, shared with the run command's tests), whose
    RECORD lists every file of the wheel."""
    record = next(installed.glob("*.dist-info")) / "RECORD"
    names = {row[0] for row in csv.reader(record.read_text().splitlines()) if row}
    for required in (
        "app/templates/index.html",
        "app/static/css/app.css",
        "app/catalog_data/common.toml",
        "app/catalog_data/zbx-series.toml",
        "app/core/selection.py",
    ):
        assert required in names
    assert any(n.startswith("app/static/vendor/htmx-2") for n in names)


def test_app_runs_no_generated_code() -> None:
    """No ``exec``, ``eval`` or ``compile`` in the app: plain code (the design guide)."""
    found = []
    for path in (ROOT / "app").rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            named = getattr(node, "func", None)
            if isinstance(node, ast.Call) and getattr(named, "id", "") in (
                "exec",
                "eval",
                "compile",
            ):
                found.append(f"{path.relative_to(ROOT)}:{node.lineno}")
    assert found == []
