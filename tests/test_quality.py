"""Repository rules: lint, format, types, and the core's independence from the web."""

import ast
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

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


#: Each folder of app/ and the folders it must not import: a layer imports only those
#: below it (core < catalog < contract < report < api, web < main), and the server's
#: plumbing imports no results or pages.
NOT_IMPORTED_BY = {
    "catalog": ("report", "api", "web"),
    "contract": ("report", "api", "web", "server"),
    "report": ("api", "web", "server"),
    "server": ("contract", "report", "api", "web"),
    "api": ("web",),
    "web": ("api",),
}


@pytest.mark.parametrize("folder", sorted(NOT_IMPORTED_BY))
def test_no_layer_imports_one_above_it(folder: str) -> None:
    """No upward import: e.g. the service reads share links from the contract, not from
    the pages; the error type lives with the server, its page rendering with the web."""
    above = tuple(f"app.{name}" for name in NOT_IMPORTED_BY[folder])
    found = {
        f"{path.relative_to(ROOT)} imports {name}"
        for path in sorted((ROOT / "app" / folder).rglob("*.py"))
        for name in _app_imports(path)
        if name.startswith(above)
    }
    assert found == set()


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
def test_wheel_carries_templates_static_and_catalog(tmp_path: Path) -> None:
    result = _run(
        "pip", "wheel", "--no-deps", "--no-build-isolation", "-w", str(tmp_path), str(ROOT)
    )
    if result.returncode != 0 and "hatchling" in (result.stdout + result.stderr):
        result = _run("pip", "wheel", "--no-deps", "-w", str(tmp_path), str(ROOT))
    assert result.returncode == 0, result.stdout + result.stderr
    import zipfile

    wheel = next(tmp_path.glob("*.whl"))
    names = set(zipfile.ZipFile(wheel).namelist())
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
