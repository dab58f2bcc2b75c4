"""Run every benchmark and print each figure beside its target (PASS / MISS).

    python3 bench/run.py            # core, HTTP, page weight, memory, keystroke to
                                    # results in Chromium, hostile load
    python3 bench/run.py --soak     # plus a 60 s no-error load test per endpoint
    python3 bench/run.py --only floods --seconds 30
                                    # health p99 under issue 31's floods of one worker,
                                    # 64 connections each, and the probes set from them

Figures are printed, never asserted: timing depends on the machine. The exit code is 0
whenever the benchmarks ran, whatever they measured.
"""

import argparse
import os
import platform
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def setting() -> dict[str, str]:
    """What the figures depend on: the code measured and how busy the machine was."""
    git = ["git", "-C", str(ROOT)]
    head = subprocess.run([*git, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    dirty = subprocess.run([*git, "status", "--porcelain"], capture_output=True, text=True)
    changed = len(dirty.stdout.splitlines())
    return {
        "commit": (head.stdout.strip() or "unknown")
        + (f" + {changed} uncommitted paths" if changed else ""),
        "python": platform.python_version(),
        "CPUs": str(os.cpu_count()),
        "load average (1, 5, 15 min)": " ".join(f"{x:.2f}" for x in os.getloadavg()),
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--soak", action="store_true", help="add the 60 s load test per endpoint")
    parser.add_argument("--soak-seconds", type=int, default=60)
    parser.add_argument("--seconds", type=int, default=10, help="wrk duration per endpoint")
    parser.add_argument(
        "--only",
        choices=("core", "http", "keystroke", "hostile", "attacks", "floods"),
        help="run one part",
    )
    args = parser.parse_args(argv)
    # `python3 bench/run.py` puts bench/ first on the path; the repository root belongs there
    sys.path[:] = [str(ROOT), *(p for p in sys.path if Path(p or ".").resolve() != ROOT / "bench")]
    from bench import attacks, core, hostile, keystroke, web
    from bench.report import Report

    report = Report()
    report.section("Setting")
    for name, value in setting().items():
        report.info(name, value)
    if args.only in (None, "core"):
        core.run(report)
    if args.only in (None, "http"):
        web.run(
            report,
            seconds=args.seconds,
            memory_requests=(5_000, 50_000),
            # the default run stays near three minutes; a soak waits for all 50,000
            memory_seconds=600 if args.soak else 60,
            soak_seconds=args.soak_seconds if args.soak else None,
        )
    if args.only in (None, "keystroke"):
        keystroke.run(report)
    if args.only in (None, "hostile"):
        with tempfile.TemporaryDirectory(prefix="leadscrew-bench-") as tmp:
            hostile.run(report, seconds=args.seconds, tmp=Path(tmp))
    if args.only in (None, "hostile", "attacks"):
        with tempfile.TemporaryDirectory(prefix="leadscrew-attacks-") as tmp:
            attacks.run(report, seconds=min(args.seconds, 5), tmp=Path(tmp))
    if args.only == "floods":
        attacks.kubernetes(report, attacks.costly_queries(report, args.seconds))
    report.info("load average at the end", " ".join(f"{x:.2f}" for x in os.getloadavg()))
    report.summary()
    return 0


if __name__ == "__main__":
    sys.exit(main())
