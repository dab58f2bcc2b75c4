"""The catalog index (app.core.index): built once at load, read-only, passed to every
query; and the core keeps no state of its own beside it."""

import ast
import math
from dataclasses import fields
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.catalog import Catalog
from app.core.index import CatalogIndex, size_of
from app.core.model import Application
from app.core.quantities import operating_point
from app.core.table import COLUMNS, CandidateTable
from app.main import create_app

CORE = Path(__file__).resolve().parents[2] / "app" / "core"
#: Method names that change a dict, list or set in place.
MUTATORS = frozenset(
    {"append", "extend", "insert", "add", "update", "setdefault", "pop", "popitem", "clear"}
)
#: Decorators that keep results between calls. (``functools.cached_property`` keeps a
#: number on its own record, built for one query and dropped with it: not between queries.)
MEMOIZERS = frozenset({"cache", "lru_cache"})


def _module_names(tree: ast.Module) -> set[str]:
    """The names a module assigns at its top level."""
    names = set()
    for node in tree.body:
        targets = node.targets if isinstance(node, ast.Assign) else []
        if isinstance(node, ast.AnnAssign):
            targets = [node.target]
        names |= {t.id for t in targets if isinstance(t, ast.Name)}
    return names


def _state_writes(source: str) -> set[str]:
    """Where a function of the module ``source`` calls
    ``id()``, changes a module-level name in place (``NAME[k] = v``, ``NAME.append(v)``,
    ...), rebinds one (``global``) or keeps its results (``functools.lru_cache``)."""
    tree = ast.parse(source)
    module = _module_names(tree)
    found = []
    for func in ast.walk(tree):
        if not isinstance(func, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda):
            continue
        for deco in getattr(func, "decorator_list", []):
            called = deco.func if isinstance(deco, ast.Call) else deco
            label = called.attr if isinstance(called, ast.Attribute) else getattr(called, "id", "")
            if label in MEMOIZERS:
                found.append(f"{label} on {func.name} at line {deco.lineno}")
        for node in ast.walk(func):
            name = None
            call = node.func if isinstance(node, ast.Call) else None
            if isinstance(call, ast.Name) and call.id == "id":
                found.append(f"id() at line {node.lineno}")
            if isinstance(call, ast.Attribute) and isinstance(call.value, ast.Name):
                name = call.value.id if call.attr in MUTATORS else None
            stored = isinstance(node, ast.Subscript) and isinstance(node.ctx, ast.Store | ast.Del)
            if stored and isinstance(node.value, ast.Name):
                name = node.value.id
            if isinstance(node, ast.Global):
                found += [f"global {n} at line {node.lineno}" for n in node.names]
            if name in module:
                found.append(f"{name} changed at line {node.lineno}")
    return set(found)


def test_the_core_keeps_no_state_between_queries() -> None:
    """No function of app/core changes a module-level dict, list or set, keys anything
    by ``id()`` or keeps its results: what a query reads is passed in (the catalog
    index), not remembered."""
    modules = sorted(CORE.rglob("*.py"))
    assert len(modules) > 20
    found = {
        where: _state_writes(p.read_text())
        for p in modules
        if (where := p.relative_to(CORE).as_posix())
    }
    assert {where: lines for where, lines in found.items() if lines} == {}
    # nor does a table carry a place to keep work in: its fields are its columns
    others = {f.name for f in fields(CandidateTable)} - set(COLUMNS)
    assert others == {"screws", "reach", "pressure_tables", "deviation_tables"}


def test_the_state_scan_finds_a_module_level_cache() -> None:
    """The scan above fails on the patterns it exists to keep out."""
    source = (
        "_SEEN: dict[int, object] = {}\n"
        "def of(x):\n"
        "    _SEEN[id(x)] = x\n"
        "    _SEEN.clear()\n"
        "    return x\n"
    )
    assert _state_writes(source) == {
        "_SEEN changed at line 3",
        "id() at line 3",
        "_SEEN changed at line 4",
    }
    registered = "_found = []\ndef register(c):\n    _found.append(c)\n"
    assert _state_writes(registered) == {"_found changed at line 3"}


def test_the_index_is_built_once_at_load(monkeypatch: pytest.MonkeyPatch) -> None:
    """Selections (API and page), a candidate's detail, evaluations of a catalog and of a
    custom screw and the lead sweep all read the index the app built when it loaded the
    catalog; none builds another."""
    built: list[CatalogIndex] = []
    build = CatalogIndex.build.__func__  # type: ignore[attr-defined]

    def counted(cls: type[CatalogIndex], *args: Any, **kwargs: Any) -> CatalogIndex:
        built.append(build(cls, *args, **kwargs))
        return built[-1]

    monkeypatch.setattr(CatalogIndex, "build", classmethod(counted))
    app = create_app()
    query = {"load_n": 120.0, "speed_mm_s": 40.0, "length_mm": 400.0}
    custom = {"outer_diameter_mm": 12.7, "root_diameter_mm": 9.906, "lead_mm": 10.0}
    custom |= {"friction_dynamic": 0.15, "friction_static": 0.2}
    with TestClient(app) as client:
        assert len(built) == 1 and app.state.catalog.index is built[0]
        for params in (query, {**query, "lead_mm": 10.0}):
            assert client.get("/api/v1/select", params=params).status_code == 200
        page = {"load": "120", "speed": "40", "length": "400", "lead": "10"}
        assert "lead_sweep" in client.get("/charts", params=page).text
        assert client.get("/detail", params={**page, "id": "ZBX8000-L10"}).status_code == 200
        for screw in ({"catalog_id": "ZBX8000-L10"}, custom):
            body = {"application": query, "screw": screw}
            assert client.post("/api/v1/evaluate", json=body).status_code == 200
    assert len(built) == 1


def test_the_index_is_read_only(catalog: Catalog) -> None:
    """Every column of the table and of the variant rows refuses writes, and so do the
    eligible rows kept for a set of filters and their joint table; the rows by id and by
    size are read-only mappings of read-only arrays."""
    index = catalog.index
    assert index.variants is not None
    kept = index.eligible(Application(load_n=50.0, speed_m_s=0.05, length_m=0.5, lead_m=0.01))
    assert kept.joint is not None
    for table in (index.table, index.variants.table, kept.table, kept.joint.table):
        for name in COLUMNS:
            with pytest.raises(ValueError, match="read-only"):
                getattr(table, name)[:1] = 0
    with pytest.raises(TypeError):
        index.positions["new"] = 0  # type: ignore[index]
    with pytest.raises(ValueError, match="read-only"):
        next(iter(index.sizes.values()))[0] = 0


def test_rows_by_id_and_by_size(catalog: Catalog) -> None:
    """Each id names its own row; each size and nut holds every lead of that series'
    screws with that coating and nut, shortest first (B8000 uncoated: 18 leads)."""
    index = catalog.index
    assert len(index.positions) == len(index.table) == len(catalog.screws)
    for sid, row in index.positions.items():
        assert index.table.screws[row].id == sid
    rows = index.sizes[("B8000", "polyacetal", False, False)]
    leads_mm = [round(float(index.table.lead_m[r]) * 1e3, 6) for r in rows]
    assert leads_mm == [1, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 12.7, 15, 20, 25, 25.4, 30, 40, 50]
    assert sum(map(len, index.sizes.values())) == len(index.table)
    for size, at in index.sizes.items():
        assert all(size_of(index.table.screws[r]) == size for r in at)


def test_each_screw_owns_its_variant_rows(catalog: Catalog) -> None:
    """Screw ``i``'s variant rows are ``start[i]:start[i + 1]``: two per ranged value
    (its low and its high end), named by that value."""
    index = catalog.index
    variants = index.variants
    assert variants is not None
    assert len(variants.start) == len(index.table) + 1
    row = index.positions["B4000-L2"]
    span = range(variants.start[row], variants.start[row + 1])
    screw = index.table.screws[row]
    ends = [name for name, pair in screw.assumption_ends.items() for end in pair if end]
    assert [variants.names[r] for r in span] == ends
    assert "pv_limit_mpa_m_s" in ends
    low = variants.table.screws[span[ends.index("pv_limit_mpa_m_s")]]
    assert low.pv_limit_pa_m_s == pytest.approx(0.07e6)


def test_a_bronze_nut_carries_its_table_pressure_over_the_flank_area(catalog: Catalog) -> None:
    """Tr12x3 bronze nut, 24 mm long: A = (24 / 3) pi 10.5 x 1.5 mm2 = 395.84 mm2 (ISO
    2904 d2 = 10.5 mm, H1 = 0.5 P). At 10 mm/s, n = 200 rpm and the flanks slide at
    200 / 60 x sqrt(3^2 + (pi 10.5)^2) mm = 0.11041 m/s: Shigley Table 8-4 gives 5.5 MPa
    (0.1 to 0.2 m/s), so 2177 N. At 20 mm/s, 0.22082 m/s: 5.5 - 4.5 x 0.02082 / 0.05 =
    3.626 MPa between 0.2 and 0.25 m/s, so 1435 N.

    The same numbers come from the catalog's own table, from a table of that screw alone
    and from a table joined with other screws after it (the pressure tables renumbered).
    """
    screw = catalog.by_id["Tr12x3-bronze"]
    polymer = [catalog.by_id["B4000-L2"], catalog.by_id["ZBX8000-L10"]]
    alone = CandidateTable.build([screw])
    joined = CandidateTable.build(polymer).join(alone)
    row = catalog.index.positions[screw.id]
    area_m2 = 24 / 3 * math.pi * 10.5 * 1.5 * 1e-6
    assert area_m2 == pytest.approx(395.84e-6, rel=1e-5)
    expected = ((0.01, 0.11041, 5.5e6, 2177.0), (0.02, 0.22082, 3.626e6, 1435.0))
    for speed_m_s, sliding_m_s, pressure_pa, load_n in expected:
        app = Application(load_n=100.0, speed_m_s=speed_m_s, length_m=0.5)
        for table, k in ((catalog.index.table, row), (alone, 0), (joined, 2)):
            q = operating_point(app, table)
            assert q.nut.sliding_speed_m_s[k] == pytest.approx(sliding_m_s, rel=1e-4)
            assert q.nut.nut_allowed_pressure_pa[k] == pytest.approx(pressure_pa, rel=1e-3)
            assert q.nut.nut_allowed_load_n[k] == pytest.approx(load_n, rel=1e-3)
    assert joined.pressure_tables == alone.pressure_tables
    assert np.array_equal(joined.pressure_table, [-1, -1, 0])
