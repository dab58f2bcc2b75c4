"""Rules that keep results traceable: formulas name real functions and real fields, and
the catalog README's example is a catalog that loads."""

import importlib
import re
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.catalog import load_catalog
from app.core.checks import BY_NAME
from app.core.formulas.declare import formula_of
from app.report.formulas import FORMULAS

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("key", sorted(FORMULAS))
def test_formula_names_an_existing_core_function(key: str) -> None:
    """'app.core.formulas.pv.pv_value', or a check's 'app.core.checks.pv.NutPV.measure'."""
    parts = FORMULAS[key]["function"].split(".")
    for cut in range(len(parts) - 1, 0, -1):
        try:
            target: Any = importlib.import_module(".".join(parts[:cut]))
        except ModuleNotFoundError:
            continue
        for name in parts[cut:]:
            target = getattr(target, name)
        assert callable(target)
        return
    pytest.fail(f"no module in {FORMULAS[key]['function']}")


FORMULA_MODULES = sorted(
    path.stem
    for path in (ROOT / "app" / "core" / "formulas").glob("*.py")
    if path.stem not in ("__init__", "declare")
)


@pytest.mark.parametrize("module", FORMULA_MODULES)
def test_every_reported_formula_function_declares_its_formula(module: str) -> None:
    """A function of a formula module that the formulas table names carries its formula
    and source (``@formula``), and an entry that gives no text of its own shows them."""
    named = {
        f["function"]: f
        for f in FORMULAS.values()
        if f["function"].startswith(f"app.core.formulas.{module}.")
    }
    imported = importlib.import_module(f"app.core.formulas.{module}")
    for path in named:
        declared = formula_of(getattr(imported, path.rsplit(".", 1)[1]))
        assert declared.text and declared.source, path
    for entry in FORMULAS.values():
        if entry["function"] in named:
            assert entry["source"], entry


def _lookup(candidate: dict[str, Any], dotted: str) -> Any:
    """The field at a dotted path; through a list (e.g. ``segments``), its first item's."""
    value: Any = candidate
    for part in dotted.split("."):
        value = value[0][part] if isinstance(value, list) else value[part]
    return value


def test_every_formula_key_is_a_field_of_a_candidate(client: TestClient) -> None:
    body = client.post(
        "/api/v1/select?detail=full",
        json={
            "load_n": 100,
            "speed_mm_s": 50,
            "length_mm": 500,
            "lead_mm": 10,
            "stroke_mm": 300,
            "cycles_per_day": 100,
            "require_anti_backlash": True,
        },
    ).json()
    assert body["formulas"].keys() == FORMULAS.keys()
    candidate = body["candidates"][0]
    for key in FORMULAS:
        if key.startswith("checks."):  # a check's formula: the registry names the check
            assert key.removeprefix("checks.") in BY_NAME
            continue
        _lookup(candidate, key)  # KeyError names a formula for a field that does not exist


def test_candidate_provenance_covers_every_check_source(client: TestClient) -> None:
    body = client.get(
        "/api/v1/select",
        params={
            "detail": "full",
            "load_n": 100,
            "speed_mm_s": 50,
            "length_mm": 500,
            "orientation": "vertical",
            "require_anti_backlash": True,
            "max_torque_nm": 1,
            "stroke_mm": 200,
            "cycles_per_day": 50,
            "required_life_years": 1,
            "positioning_tolerance_mm": 0.5,
        },
    ).json()
    for candidate in body["candidates"] + body["rejected"]:
        for check in candidate["checks"]:
            for source in check["sources"]:
                assert source in candidate["provenance"], (candidate["id"], source)


def test_catalog_readme_example_loads(tmp_path: Path) -> None:
    readme = (ROOT / "catalog" / "README.md").read_text()
    blocks = re.findall(r"```toml\n(.*?)```", readme, flags=re.S)
    example = next(b for b in blocks if "[[series]]" in b)
    (tmp_path / "my-series.toml").write_text(example)
    catalog = load_catalog([tmp_path])
    assert "MY10" in catalog.series
    screw = catalog.by_id["MY10-L2"]
    assert screw.root_diameter_m == pytest.approx(0.0075)
    assert catalog.series["MY10"].fields["root_diameter"].provenance.kind == "handbook"
