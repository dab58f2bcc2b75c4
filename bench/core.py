"""Core figures: one full selection over the built-in catalog, and scaling to 100,000.

Times ``app.core.selection.select`` alone (no validation, no serialisation) with
``time.perf_counter``; the median of repeated runs after one warm-up run.
"""

import dataclasses
import random
import statistics
import time
from collections.abc import Callable, Sequence

from app.catalog import load_catalog
from app.core.model import Application, ScrewSpec
from app.core.selection import select
from bench.report import Report

try:  # the core may screen through a prebuilt index; time that path too when it does
    from app.core.index import CatalogIndex
except ImportError:  # pragma: no cover - an older core
    CatalogIndex = None

TYPICAL = Application(load_n=100.0, speed_m_s=0.050, length_m=0.500, lead_m=0.010)
ALL_LEADS = dataclasses.replace(TYPICAL, lead_m=None)
SIZES = (1_000, 10_000, 100_000)


def median_seconds(
    run: Callable[[], object], budget_s: float, min_runs: int = 3, warm_up: bool = True
) -> float:
    """Median wall time of ``run`` over at least ``min_runs`` runs or ``budget_s`` seconds."""
    if warm_up:
        run()  # imports, caches, allocator
    times: list[float] = []
    deadline = time.perf_counter() + budget_s
    while len(times) < min_runs or (time.perf_counter() < deadline and len(times) < 1000):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def synthetic(screws: Sequence[ScrewSpec], n: int, seed: int = 1) -> list[ScrewSpec]:
    """``n`` plausible candidates: real screws scaled in diameter and lead.

    Diameters scale by 0.7-1.5 (inertia per length by the fourth power, as for a solid
    rod), leads by 0.5-2; everything else, provenance included, is the real screw's.
    """
    rng = random.Random(seed)
    out = []
    for i in range(n):
        base = screws[i % len(screws)]
        size, pitch = rng.uniform(0.7, 1.5), rng.uniform(0.5, 2.0)
        out.append(
            dataclasses.replace(
                base,
                id=f"{base.id}-S{i}",
                outer_diameter_m=base.outer_diameter_m * size,
                root_diameter_m=base.root_diameter_m * size,
                inertia_kg_m2_per_m=base.inertia_kg_m2_per_m * size**4,
                lead_m=base.lead_m * pitch,
            )
        )
    return out


def run(report: Report) -> None:
    report.section("Core: app.core.selection.select (median wall time)")
    catalog = load_catalog()
    screws = catalog.screws
    index = getattr(catalog, "index", None)
    report.info("catalog candidates", f"{len(screws)}")
    for label, app in (("lead 10 mm", TYPICAL), ("any lead", ALL_LEADS)):
        t = median_seconds(lambda app=app: select(app, screws), budget_s=3.0)
        evaluated = select(app, screws).evaluated
        report.line(
            f"select, {label} ({evaluated} evaluated)", f"{t * 1e3:.3f} ms", "< 1 ms", t < 1e-3
        )
        if index is not None:
            t = median_seconds(lambda app=app: select(app, index), budget_s=2.0)
            report.line(
                "  over catalog.index (as the app calls it)",
                f"{t * 1e3:.3f} ms",
                "< 0.5 ms",
                t < 0.5e-3 if app is TYPICAL else None,
            )

    report.section("Core scaling: synthetic catalogs, any lead (every candidate evaluated)")
    times: dict[int, float] = {}
    for n in SIZES:
        candidates = synthetic(screws, n)
        big = n >= 100_000  # one run: it takes seconds, and warms itself up
        times[n] = median_seconds(
            lambda c=candidates: select(ALL_LEADS, c),
            0.0,
            min_runs=1 if big else 3,
            warm_up=not big,
        )
        per = times[n] / n * 1e6
        verdict = times[n] < 0.5 if n == 100_000 else None
        target = "< 0.5 s" if n == 100_000 else "-"
        report.line(f"select over {n:,} candidates", f"{times[n]:.3f} s", target, verdict)
        report.info("", f"{per:.1f} us per candidate")
        if CatalogIndex is not None:
            start = time.perf_counter()
            built = CatalogIndex.build(candidates, with_variants=False)
            build = time.perf_counter() - start
            start = time.perf_counter()
            select(ALL_LEADS, built)
            screen = time.perf_counter() - start
            report.info(
                "", f"separately: build the index {build:.3f} s, select on it {screen:.3f} s"
            )
    ratio = times[100_000] / times[10_000]
    report.line("time ratio 100k / 10k", f"{ratio:.2f}", "<= 12", ratio <= 12)
