"""README's install step, made once per run for the tests that read what it installs: the
run command's tests (tests/server/test_run_command.py) and the wheel's contents
(tests/test_quality.py). Those tests are marked ``ON_INSTALL``: one xdist worker runs them
all (``--dist loadgroup``), so the install (a wheel built by pip from the checkout) is made
once, by the session fixture ``installed`` of tests/conftest.py."""

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

#: the tests of the install run on one xdist worker (``--dist loadgroup``): it is made once
ON_INSTALL = pytest.mark.xdist_group("run-command-install")


def readme_run_command() -> tuple[list[str], list[str]]:
    """(install, serve) argument lists from the ``## Run`` block of README.md."""
    readme = (ROOT / "README.md").read_text()
    block = re.search(r"^## Run\s*\n+```(?:sh|bash|console)?\n(.+?)\n```", readme, re.M | re.S)
    assert block, "README.md has no ## Run code block"
    install, serve = (shlex.split(part) for part in block[1].strip().split("&&"))
    return install, serve


def install_into(target: Path) -> Path:
    """The README's install step, into ``target`` (``--target``, ``--no-deps``: the
    dependencies are already here), run from there, outside the checkout."""
    install, _ = readme_run_command()
    install = [str(ROOT / arg) if arg.endswith(".txt") else arg for arg in install]
    args = [sys.executable, *install[1:-1], "--no-deps", "--target", str(target), str(ROOT)]
    done = subprocess.run(
        args, cwd=target, capture_output=True, text=True, timeout=600, check=False
    )
    if done.returncode != 0:
        reason = f"pip install failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}"
        if os.environ.get("CI") == "true" or "hatchling" not in done.stderr:
            pytest.fail(reason)
        pytest.skip("cannot fetch the build backend (offline?): " + reason[-300:])
    return target
