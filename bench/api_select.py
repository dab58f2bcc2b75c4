"""In-process cost of a distinct compact select, step by step.

    python -m bench.api_select [REQUESTS]

Each request a different load (no cache could answer it), through what the route runs:
the query parsed, the core's selection, the candidates presented in the compact view,
the links, the JSON. Prints each step's median [ms] over the requests, the whole
request's, the Python calls per request (cProfile's count: the same on a busy machine)
and the load average, since on a shared machine the times move with it.
"""

import argparse
import cProfile
import os
import pstats
import statistics
import time
from collections.abc import Callable
from itertools import pairwise
from typing import Any

from starlette.datastructures import QueryParams

from app.api.query import parse_query
from app.catalog import load_catalog
from app.contract.outputs import SelectQuery
from app.contract.params import api_url
from app.contract.share_link import share_query
from app.core.selection import select
from app.report import service
from app.report.present import selection_summary
from app.server.responses import ModelJSON

QUERY = "load_n={load:.3f}&speed_mm_s=50&length_mm=500&lead_mm=10"
STEPS = ("parse", "select", "present", "links", "json")


def steps(load_n: float, catalog: Any) -> list[float]:
    """One distinct request's steps, each timed [s]."""
    marks = [time.perf_counter()]
    inputs = parse_query(SelectQuery, QueryParams(QUERY.format(load=load_n))).application()
    marks.append(time.perf_counter())
    app = inputs.to_core(catalog.motors, catalog.supports)
    chosen = select(app, catalog.index, service.INPUT_RANGES, service.INPUT_WORDS)
    marks.append(time.perf_counter())
    body = selection_summary(chosen)
    marks.append(time.perf_counter())
    share = share_query(inputs)
    body |= {
        "inputs": inputs.model_dump(mode="json", exclude_defaults=True),
        "share_url": "/?" + share,
        "api_url": api_url("select", inputs, share=share),
    }
    marks.append(time.perf_counter())
    ModelJSON(body)
    marks.append(time.perf_counter())
    return [b - a for a, b in pairwise(marks)]


def calls_per_request(run: Callable[[float], object], requests: int) -> float:
    """Python function calls per request, as cProfile counts them."""
    profile = cProfile.Profile()
    profile.enable()
    for i in range(requests):
        run(90.0 + i * 0.0071)
    profile.disable()
    calls: int = pstats.Stats(profile).total_calls  # type: ignore[attr-defined]
    return calls / requests


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("requests", type=int, nargs="?", default=400)
    args = parser.parse_args()
    catalog = load_catalog()
    for i in range(30):  # warm-up
        steps(40.0 + i * 0.37, catalog)
    timed = [steps(60.0 + i * 0.0113, catalog) for i in range(args.requests)]
    for k, name in enumerate(STEPS):
        print(f"{name:8s} {statistics.median(t[k] for t in timed) * 1e3:7.3f} ms")
    print(f"{'request':8s} {statistics.median(sum(t) for t in timed) * 1e3:7.3f} ms (median)")
    calls = calls_per_request(lambda load: steps(load, catalog), 20)
    print(f"calls    {calls:7.0f} per request")
    print(f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
