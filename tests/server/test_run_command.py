"""README's run command: install, serve, answer a selection, stop cleanly on SIGTERM.

The install step runs as written but into a temporary target (``--target``, ``--no-deps``:
the dependencies are already here), from another directory, so the console script and
the packaged templates, static files and catalog are what gets tested, not the checkout.
"""

import os
import re
import signal
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import httpx
import pytest

from app import cli
from app.server.protocol import BoundedHttpToolsProtocol
from deploy.local import START_CEILING_S, free_port
from tests.readme_install import ON_INSTALL, readme_run_command

ROOT = Path(__file__).resolve().parents[2]


def test_the_readme_run_command_is_install_then_serve() -> None:
    install, serve = readme_run_command()
    assert install == ["python3", "-m", "pip", "install", "-c", "constraints.txt", "."]
    assert (ROOT / "constraints.txt").is_file()
    assert serve == ["leadscrew-selector"]


def test_the_constraints_pin_every_dependency_exactly() -> None:
    """Every line of constraints.txt is name==version, and every dependency the project
    names (app and tests) is among them, so a fresh install gets what was tested."""
    lines = (ROOT / "constraints.txt").read_text().splitlines()
    pins = [line for line in lines if line and not line.startswith("#")]
    assert all(re.fullmatch(r"[A-Za-z0-9_.\-]+==[0-9][A-Za-z0-9_.+]*", pin) for pin in pins), pins
    pinned = {re.sub(r"[-_.]+", "-", pin.split("==")[0]).lower() for pin in pins}
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    named = project["dependencies"] + project["optional-dependencies"]["test"]
    for requirement in named:
        name = re.split(r"[\[<>=!~ ]", requirement, maxsplit=1)[0]
        assert re.sub(r"[-_.]+", "-", name).lower() in pinned, requirement


@pytest.mark.parametrize(
    "path",
    [
        "bin/leadscrew-selector",
        "app/cli.py",
        "app/templates/index.html",
        "app/static/css/app.css",
        "app/static/js/docs.js",
        "app/static/vendor/htmx-2.0.11.min.js",
        "app/static/vendor/swagger-ui-bundle-5.35.0.js",
        "app/static/vendor/swagger-ui-LICENSE.txt",
        "app/catalog_data/common.toml",
    ],
)
@ON_INSTALL
def test_the_install_carries(installed: Path, path: str) -> None:
    assert (installed / path).is_file()


@ON_INSTALL
def test_the_install_leaves_out_tests_and_benchmarks(installed: Path) -> None:
    assert not (installed / "tests").exists() and not (installed / "bench").exists()
    entry_points = next(installed.glob("*.dist-info")) / "entry_points.txt"
    assert "leadscrew-selector = app.cli:main" in entry_points.read_text()


def _serve_select_stop(args: list[str], cwd: Path, env: dict[str, str]) -> None:
    port = free_port()
    proc = subprocess.Popen(
        [*args, "--port", str(port)],
        cwd=cwd,
        env={**os.environ, **env},
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + START_CEILING_S  # a ceiling: the loop ends on an answer
        while True:
            assert proc.poll() is None, proc.communicate()[0]
            assert time.monotonic() < deadline, "no answer on /api/v1/health"
            try:
                if httpx.get(base + "/api/v1/health", timeout=2).status_code == 200:
                    break
            except httpx.HTTPError:
                time.sleep(0.2)
        query = {"load_n": 100, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10}
        response = httpx.get(base + "/api/v1/select", params=query, timeout=30)
        assert response.status_code == 200
        assert response.json()["candidates"]
        assert httpx.get(base + "/", timeout=30).status_code == 200
    finally:
        proc.send_signal(signal.SIGTERM)
        try:
            output, _ = proc.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            proc.kill()
            output, _ = proc.communicate()
    assert proc.returncode == 0, output


@ON_INSTALL
def test_installed_console_script_serves_and_stops_cleanly(installed: Path) -> None:
    """``leadscrew-selector`` as installed: outside the checkout, from the install only."""
    _, serve = readme_run_command()
    elsewhere = installed.parent
    script = installed / "bin" / serve[0]
    _serve_select_stop([str(script)], cwd=elsewhere, env={"PYTHONPATH": str(installed)})


def test_the_same_entry_point_from_the_checkout_stops_cleanly() -> None:
    """``app.cli:main`` without installing: the SIGTERM exit code, even offline."""
    _serve_select_stop([sys.executable, "-m", "app.cli"], cwd=ROOT, env={})


@pytest.mark.parametrize(("workers", "loop"), [(1, "asyncio"), (2, "uvloop"), (4, "uvloop")])
def test_the_command_serves_on_the_loop_that_suits_its_workers(
    monkeypatch: pytest.MonkeyPatch, workers: int, loop: str
) -> None:
    """``leadscrew-selector`` runs one worker on asyncio's event loop (it accepts every
    waiting connection at once) and several on uvloop (one connection per iteration, so
    workers sharing a socket share the connections): ``app.cli.event_loop``. The bench
    shows both effects. It keeps the bounded protocol and the app factory."""
    seen: dict[str, object] = {}
    monkeypatch.setattr(cli.uvicorn, "run", lambda target, **kw: seen.update(kw, target=target))
    monkeypatch.setattr(cli.signal, "signal", lambda *args: None)
    assert cli.main(["--port", "8123", "--workers", str(workers)]) == 0
    assert seen["loop"] == loop == cli.event_loop(workers)
    assert seen["workers"] == workers and seen["port"] == 8123
    assert seen["http"] is BoundedHttpToolsProtocol
    assert seen["target"] == "app.main:create_app" and seen["factory"] is True


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--port", "80000"], "--port: must be 1 to 65535, got 80000"),
        (["--port", "0"], "--port: must be 1 to 65535, got 0"),
        (["--port", "eighty"], "--port: not a whole number: 'eighty'"),
        (["--workers", "-3"], f"--workers: must be 1 to {cli.MAX_WORKERS}, got -3"),
        (["--workers", "0"], f"--workers: must be 1 to {cli.MAX_WORKERS}, got 0"),
        (["--workers", "1_0"], "--workers: not a whole number: '1_0'"),
        (["--port", " 8000"], "--port: not a whole number: ' 8000'"),
        (["--port", "８０００"], "--port: not a whole number: '８０００'"),
    ],
    ids=[
        "port-too-high",
        "port-zero",
        "port-text",
        "workers-negative",
        "workers-zero",
        "workers-underscore",
        "port-space",
        "port-fullwidth-digits",
    ],
)
def test_bad_options_are_a_usage_error(
    args: list[str],
    message: str,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Refused before anything starts: exit 2 and one line, no traceback, no server."""
    monkeypatch.setattr(cli.uvicorn, "run", lambda *a, **k: pytest.fail("the server started"))
    with pytest.raises(SystemExit) as stopped:
        cli.main(args)
    assert stopped.value.code == 2
    assert message in capsys.readouterr().err
