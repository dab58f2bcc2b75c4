"""The check registry (app.core.checks): one unit per check, and formula texts that agree
with the code that computes them.

Each numeric check's ``formula`` is "demand = ...; capacity = ...". Here both sides are
evaluated from the names the check binds (``symbols``) for every catalog candidate and
compared with what ``measure`` computes; a yes/no check's "passes when ..." condition is
compared with its failures. A text that drifts from its function fails here.
"""

import importlib
import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from app.catalog import Catalog
from app.core import checks
from app.core.checks import BY_NAME, REGISTRY, Check
from app.core.model import Application
from app.core.quantities import operating_point
from app.core.table import CandidateTable
from tests.core.conftest import light_app

#: Applications under which every check applies (each one switches on a group).
APPS = {
    "vertical-compression-torque": light_app(
        orientation="vertical", max_torque_nm=0.5, moving_mass_kg=3.0, load_n=120.0
    ),
    "duty-tolerance-oil": light_app(
        stroke_m=0.3,
        cycles_per_day=500.0,
        required_life_years=2.0,
        positioning_tolerance_m=2e-4,
        oil_present=True,
        vacuum=True,
        require_anti_backlash=True,
        ambient_c=100.0,
        step_angle_deg=1.8,
        microsteps=4,
        # a datasheet stepper on 12 V, below 4 x 0.64 A x 14.5 ohm = 37.1 V
        motor_supply_v=12.0,
        motor_phase_current_a=0.64,
        motor_resistance_ohm=14.5,
    ),
    "long-fast-fixed-free": light_app(length_m=3.0, speed_m_s=0.4, end_fixity="fixed-free"),
    # short, heavily loaded columns (Johnson's branch) and a brake holding a vertical load
    "short-heavy-braked": light_app(
        orientation="vertical", load_n=3000.0, length_m=0.06, brake_torque_nm=0.3
    ),
    # a vertical move with a dwell against a motor curve and its continuous rating
    "vertical-move-motor": light_app(
        orientation="vertical",
        moving_mass_kg=4.0,
        stroke_m=0.2,
        speed_m_s=0.2,
        accel_m_s2=2.0,
        decel_m_s2=4.0,
        dwell_s=0.5,
        motor_inertia_kg_m2=1e-5,
        coupling_inertia_kg_m2=3e-6,
        motor_curve=((0.0, 0.6), (1500.0, 0.4), (3000.0, 0.15)),
        motor_rms_torque_nm=0.2,
        torque_safety_factor=1.5,
        step_angle_deg=0.9,
        microsteps=16,
        max_step_rate_hz=50_000.0,
    ),
    # a stepper holding a vertical load while energised, its detent torque with power off
    "vertical-stepper-detent": light_app(
        orientation="vertical",
        brake_torque_nm=0.4,
        holding_source="energised",
        detent_torque_nm=0.02,
        brake_safety_factor=1.5,
    ),
    # a thrust bearing rated statically and dynamically, over a duty, buckling over the
    # span from the bearing to the nut
    "supported-duty": light_app(
        load_n=800.0,
        moving_mass_kg=10.0,
        stroke_m=0.4,
        cycles_per_day=1000.0,
        required_life_years=3.0,
        support_static_n=3250.0,
        support_dynamic_n=6660.0,
        bearing_to_nut_m=0.3,
    ),
}
FUNCTIONS: dict[str, Any] = {
    "pi": math.pi,
    "sqrt": math.sqrt,
    "cos": math.cos,
    "tanh": math.tanh,
    "max": max,
    "abs": abs,
    "min": min,
}


def _expression(side: str) -> Any:
    """The right-hand side of 'name = expression', '^' as power, compiled."""
    return compile(side.split("=", 1)[1].strip().replace("^", "**"), "<formula>", "eval")


def _at(symbols: Mapping[str, object], i: int) -> dict[str, object]:
    """Candidate i's value of each symbol (arrays per candidate, scalars shared)."""
    return {
        k: (v[i].item() if isinstance(v, np.ndarray) and v.ndim else v) for k, v in symbols.items()
    }


def _same(a: float, b: float) -> bool:
    """Equal to rounding, or both not a number (a limit that does not exist)."""
    return (math.isnan(a) and math.isnan(b)) or math.isclose(a, b, rel_tol=1e-9)


def formula_mismatches(check: Check, app: Application, t: CandidateTable) -> list[str]:
    """Candidates where the formula text gives another number (or verdict) than the code."""
    q = operating_point(app, t)
    m = check.measure(app, t, q)
    symbols = check.symbols(app, t, q)
    out = []
    if m.demand is None:
        condition = compile(check.formula.removeprefix("passes when "), "<formula>", "eval")
        flagged = m.flagged if m.flagged is not None else np.zeros(len(t), dtype=bool)
        for i in np.flatnonzero(m.applicable):
            passes = bool(eval(condition, {**FUNCTIONS}, _at(symbols, i)))
            if passes == bool(flagged[i]):
                out.append(t.screws[i].id)
        return out
    assert m.capacity is not None
    demand, capacity = (_expression(side) for side in check.formula.split(";"))
    for i in np.flatnonzero(m.applicable):
        scope = _at(symbols, i)
        got = (eval(demand, {**FUNCTIONS}, scope), eval(capacity, {**FUNCTIONS}, scope))
        if not (_same(got[0], m.demand[i]) and _same(got[1], m.capacity[i])):
            out.append(t.screws[i].id)
    return out


def test_registry_lists_each_check_module_once() -> None:
    """Every module of app/core/checks (but the base) defines one Check, listed once."""
    names = [c.name for c in REGISTRY]
    assert len(set(names)) == len(names)
    folder = Path(checks.__file__).parent
    modules = {p.stem for p in folder.glob("*.py")} - {"__init__", "base"}
    listed = [type(c).__module__.rsplit(".", 1)[1] for c in REGISTRY]
    assert sorted(listed) == sorted(modules)
    for name in modules:
        module = importlib.import_module(f"app.core.checks.{name}")
        defined = [
            v
            for v in vars(module).values()
            if isinstance(v, type) and issubclass(v, Check) and v.__module__ == module.__name__
        ]
        assert len(defined) == 1, name
    for c in REGISTRY:
        assert c.label and c.description and c.formula and c.source, c.name
        assert c.kind in ("limit", "advice")


@pytest.mark.parametrize(
    ("name", "app_id"),
    [
        pytest.param(c.name, app_id, id=f"{c.name}-{app_id}")
        for c in REGISTRY
        for app_id, app in APPS.items()
        if c.applies(app)
    ],
)
def test_formula_text_agrees_with_the_code(catalog: Catalog, name: str, app_id: str) -> None:
    assert formula_mismatches(BY_NAME[name], APPS[app_id], catalog.index.table) == []


def test_every_check_applies_under_some_application(catalog: Catalog) -> None:
    """The formula test above is not vacuous: each check runs on some candidates."""
    for check in REGISTRY:
        counts = [
            int(
                check.measure(
                    app, catalog.index.table, operating_point(app, catalog.index.table)
                ).applicable.sum()
            )
            for app in APPS.values()
            if check.applies(app)
        ]
        assert counts and max(counts) > 0, check.name


def test_a_numeric_check_judges_numbers_wherever_it_applies(catalog: Catalog) -> None:
    """Where a numeric check applies, its demand and its limit are numbers: a NaN demand
    against a limit compares false with it, and the check would pass unjudged (a screw
    of one's own with an impossible pitch once passed its root stress on "nan MPa")."""
    table = catalog.index.table
    unjudged = []
    for app_id, app in APPS.items():
        q = operating_point(app, table)
        for check in (c for c in REGISTRY if c.applies(app)):
            m = check.measure(app, table, q)
            if m.demand is None or m.capacity is None:
                continue
            missing = m.applicable & (np.isnan(m.demand) | np.isnan(m.capacity))
            unjudged += [(app_id, check.name, table.screws[i].id) for i in np.flatnonzero(missing)]
    assert unjudged == []


@pytest.mark.parametrize(
    ("name", "wrong"),
    [
        pytest.param(
            "buckling",
            "F = F_c; F_allowed = SF * (pi^2 * E * A / s^2 if s >= sqrt(2 * pi^2 * E / "
            "S_y) else A * S_y)",
            id="buckling-short-column-as-squash-load",
        ),
        pytest.param(
            "critical_speed",
            "n = 60 * v / lead; "
            "n_allowed = SF * 60 / (2 * pi) * (beta / L)^2 * sqrt(E / rho) * d_r / 2",
            id="critical-speed-radius-of-gyration",
        ),
        pytest.param("oil", "passes when oil_compatible", id="oil-ignores-presence"),
    ],
)
def test_a_wrong_formula_text_is_caught(
    catalog: Catalog, name: str, wrong: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    check = BY_NAME["coating_environment" if name == "oil" else name]
    # without oil the correct rule passes every variant; the wrong one fails the coated
    app = light_app(oil_present=False) if name == "oil" else APPS["vertical-compression-torque"]
    monkeypatch.setattr(type(check), "formula", wrong)
    assert formula_mismatches(check, app, catalog.index.table) != []


def test_a_limit_from_the_catalog_names_where_it_comes_from() -> None:
    """The governing limit's provenance is read from ``capacity_sources``: every check
    whose capacity is a catalog value names it (among the fields it reads); only the
    checks whose capacity is the user's own input leave it empty."""
    user_limits = {c.name for c in REGISTRY if not c.capacity_sources}
    motor = {"motor_curve", "motor_rms", "motor_speed", "inertia_ratio", "motor_supply"}
    controller = {"step_rate", "step_resolution"}
    holding = {"holding", "holding_power_off"}
    # the thrust bearing's ratings are inputs, typed or a library unit's (as a motor's)
    support = {"support_static", "support_life"}
    # the stroke and the nut against the user's own screw length
    assert user_limits == {
        "torque", "accuracy", "stroke_travel", *holding, *motor, *controller, *support
    }  # fmt: skip
    for c in REGISTRY:
        assert set(c.capacity_sources) <= set(c.sources), c.name
