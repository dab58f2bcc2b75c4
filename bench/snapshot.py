"""Byte-exact responses of varied queries, recorded once and compared after a change.

    python -m bench.snapshot record DIR     # write each response to DIR
    python -m bench.snapshot compare DIR    # exit 1 when any response differs

A speed change must not move a number: record before it, compare after each step. The
queries cover lead and ball screws, a vertical axis, moves of the user's own, a stepper
and a servo from the motor library, every check's inputs, the page in imperial units,
the compact select beside the full one, an evaluate and the results fragment.
"""

import argparse
import hashlib
import sys
from pathlib import Path
from urllib.parse import urlsplit

import numpy as np
from fastapi.testclient import TestClient
from starlette.datastructures import QueryParams

from app.api.query import parse_query
from app.catalog import load_catalog
from app.contract.outputs import SelectQuery
from app.core.quantities import NAMES, quantity
from app.core.screening import screen_table
from app.main import create_app

SELECT = "/api/v1/select?detail=full&"
#: name -> path: each a different path through the core and the edges.
QUERIES = {
    "default": SELECT + "load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10",
    "any-lead-summary": "/api/v1/select?load_n=100&speed_mm_s=50&length_mm=500",
    "vertical-stroke": SELECT + "load_n=40&moving_mass_kg=12&orientation=vertical"
    "&speed_mm_s=80&length_mm=600&accel_mm_s2=2000&stroke_mm=450&cycles_per_day=2000"
    "&hold_power_off=true&brake_torque_nm=0.3&lead_mm=5",
    "ball-screws": SELECT + "load_n=3000&speed_mm_s=400&length_mm=800&family=HIWIN-ROLLED"
    "&family=HIWIN-GROUND&stroke_mm=600&hours_per_day=8&required_life_years=3",
    "moves": SELECT + "load_n=10&speed_mm_s=250&length_mm=500&moves="
    "300:250:2500:2500:0.2:2.5:10:opposes;-300:250:2500:2500:0.2:0.5:10:opposes",
    "stepper": SELECT + "load_n=30&moving_mass_kg=3&speed_mm_s=150&length_mm=400"
    "&accel_mm_s2=3000&stroke_mm=300&dwell_s=0.3&motor=17hs19-2004s1&lead_mm=8"
    "&hours_per_day=4&microsteps=16",
    "servo": SELECT + "load_n=200&moving_mass_kg=20&speed_mm_s=300&length_mm=900"
    "&accel_mm_s2=5000&stroke_mm=700&motor=yaskawa-sgm7j-01a&end_fixity=fixed-simple"
    "&bearing_to_nut_mm=750&support_static_n=9000&support_dynamic_n=6000"
    "&ambient_c=40&lubrication=dry&positioning_tolerance_mm=0.2",
    "nut-and-limit": SELECT + "load_n=150&speed_mm_s=30&length_mm=300&nut_material=acetal"
    "&nut_length_mm=20&coating=none&rank_by=life&advice=reject&limit=5",
    "page-imperial": "/?load=25&speed=2&length=20&lead=0.5&stroke=15&force_unit=lbf"
    "&length_unit=in&torque_unit=oz_in&orientation=vertical&moving_mass_kg=4",
    "compact-default": "/api/v1/select?load_n=137&speed_mm_s=50&length_mm=500&lead_mm=10",
    "compact-vertical": "/api/v1/select?load_n=40&moving_mass_kg=12&orientation=vertical"
    "&speed_mm_s=80&length_mm=600&accel_mm_s2=2000&stroke_mm=450&hold_power_off=true&lead_mm=5",
    "compact-ball": "/api/v1/select?load_n=3000&speed_mm_s=400&length_mm=800"
    "&family=HIWIN-ROLLED&stroke_mm=600&hours_per_day=8&required_life_years=3",
    "compact-stepper": "/api/v1/select?load_n=30&moving_mass_kg=3&speed_mm_s=150"
    "&length_mm=400&accel_mm_s2=3000&motor=17hs19-2004s1&lead_mm=8&microsteps=16",
    "compact-none-pass": "/api/v1/select?load_n=20000&speed_mm_s=900&length_mm=2000",
    "compact-reject": "/api/v1/select?load_n=150&speed_mm_s=30&length_mm=300"
    "&nut_material=acetal&advice=reject&limit=5&rank_by=life",
    "evaluate": "/api/v1/evaluate?catalog_id=Tr12x3-bronze&load_n=100&speed_mm_s=50&length_mm=500",
    "fragment": "/?load=100&speed=50&length=500&lead=10",
}
#: name -> headers of a query asked as htmx asks (the results fragment).
HEADERS = {"fragment": {"HX-Request": "true"}}


def responses() -> dict[str, bytes]:
    """Each query's status line and body."""
    out = {}
    with TestClient(create_app()) as client:
        for name, path in QUERIES.items():
            r = client.get(path, headers=HEADERS.get(name))
            out[name] = f"{r.status_code}\n".encode() + r.content
    return out


def _bytes(values: np.ndarray) -> bytes:
    """The array's bytes as float64, every NaN spelled the same (its sign and payload
    carry no number)."""
    values = np.asarray(values, dtype=np.float64)
    return np.where(np.isnan(values), np.nan, values).tobytes()


def core_arrays() -> dict[str, bytes]:
    """Each API query's every number and utilisation over the whole catalog, as a digest
    of the arrays' bytes (the responses show the returned candidates alone)."""
    catalog = load_catalog()
    out = {}
    for name, path in QUERIES.items():
        if not path.startswith("/api/v1/select"):
            continue
        pairs = QueryParams(urlsplit(path).query)
        query = parse_query(SelectQuery, pairs).application()
        app = query.to_core(catalog.motors, catalog.supports)
        s = screen_table(app, catalog.index.table)
        digest = hashlib.sha256()
        for field in sorted(NAMES):  # by name: the parts may reorder
            digest.update(_bytes(quantity(s.quantities, field)))
        for check, use in sorted(s.utilization.items()):
            digest.update(check.encode() + (b"" if use is None else _bytes(use)))
        for check, mask in sorted(s.failed.items()):
            digest.update(check.encode() + mask.tobytes())
        digest.update(_bytes(s.max_utilization))
        out[f"core-{name}"] = b"core\n" + digest.hexdigest().encode()
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=("record", "compare"))
    parser.add_argument("directory", type=Path)
    args = parser.parse_args(argv)
    args.directory.mkdir(parents=True, exist_ok=True)
    changed = []
    for name, body in {**responses(), **core_arrays()}.items():
        path = args.directory / f"{name}.txt"
        if args.mode == "record":
            path.write_bytes(body)
        elif not path.exists() or path.read_bytes() != body:
            changed.append(name)
        print(name, body[: body.index(b"\n")].decode(), len(body), "bytes")
    if changed:
        print("changed:", ", ".join(changed))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
