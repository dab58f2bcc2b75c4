"""The unit table (app/core/units.py, read through app/contract/units.py) against the exact
definitions, its round trips, and the rule that no other module of the app converts units
with a literal factor (issue 20).

Source of the definitions: NIST SP 811 (2008), Guide for the Use of the International
System of Units, appendix B.8 (factors for units listed alphabetically) and B.9 (by kind
of quantity).
"""

import ast
import math
import re
from itertools import product
from pathlib import Path
from typing import get_args

import pytest
from hypothesis import given
from hypothesis import strategies as st

import app.contract.units
import app.core.phrase
from app.contract.fields import FIELDS
from app.contract.input_field import InputField
from app.contract.units import (
    API_SYSTEM,
    API_UNITS,
    DEFAULT_UNITS,
    DISPLAY_CHOICES,
    DISPLAY_SYSTEMS,
    SI_UNITS,
    TEXT_FORMATS,
    UNITS,
    Quantity,
    api_to_si,
    display_system,
    from_api,
    from_si,
    offset,
    si_to_api,
    to_api,
    to_si,
)
from app.core.model import STANDARD_GRAVITY_M_S2

ROOT = Path(__file__).resolve().parents[2]
DIMENSIONS = get_args(Quantity)


# --- the table against the definitions --------------------------------------------------

#: unit -> its value in SI as NIST SP 811 gives it, and whether that value is exact
#: (else it is printed to 7 significant figures).
NIST = {
    "in": (0.0254, True),
    "lbf": (4.4482216152605, True),
    "lb": (0.45359237, True),
    "kgf": (9.80665, True),
    "ft/min": (5.08e-3, True),
    "oz in": (7.061552e-3, False),
    "lb in": (1.129848e-1, False),
    "psi": (6.894757e3, False),
    "mm": (1e-3, True),
    "MPa": (1e6, True),
    "GPa": (1e9, True),
    "km": (1e3, True),
    "mm³/(N m)": (1e-9, True),
}


@pytest.mark.parametrize(("unit", "value", "exact"), [(u, *v) for u, v in NIST.items()], ids=str)
def test_factor_is_the_nist_definition(unit: str, value: float, exact: bool) -> None:
    if exact:
        assert UNITS[unit].si == value
    else:
        assert float(f"{UNITS[unit].si:.7g}") == value


def test_derived_units_follow_from_their_definitions() -> None:
    """1 lbf = 1 lb x g_n; 1 ozf in = 1/16 lbf x 1 in; 1 psi = 1 lbf / in² (exact)."""
    assert UNITS["lbf"].exact == UNITS["lb"].exact * UNITS["kgf"].exact
    assert UNITS["oz in"].exact * 16 == UNITS["lbf"].exact * UNITS["in"].exact
    assert UNITS["lb in"].exact == UNITS["lbf"].exact * UNITS["in"].exact
    assert UNITS["psi"].exact * UNITS["in"].exact ** 2 == UNITS["lbf"].exact
    assert UNITS["in/s"].exact == UNITS["in"].exact
    assert UNITS["mm/300 mm"].exact * 300 == 1


def test_the_cores_standard_gravity_is_the_kilogram_forces() -> None:
    """The core weighs the moving mass with the g_n that defines the kgf and the lbf."""
    assert UNITS["kgf"].si == STANDARD_GRAVITY_M_S2


def test_both_factors_are_the_correctly_rounded_exact_ones() -> None:
    for unit in UNITS.values():
        assert unit.si == float(unit.exact), unit.symbol
        assert unit.from_si == float(1 / unit.exact), unit.symbol


def test_every_dimension_has_one_core_unit_an_api_unit_and_a_format() -> None:
    assert set(SI_UNITS) == set(API_SYSTEM) == set(API_UNITS) == set(DIMENSIONS)
    assert set(TEXT_FORMATS) == set(DIMENSIONS)
    for dimension, symbol in SI_UNITS.items():
        assert UNITS[symbol].exact == 1 and UNITS[symbol].dimension == dimension
    for dimension, symbol in API_SYSTEM.items():
        assert UNITS[symbol].dimension == dimension


def test_one_dimension_list_for_the_app() -> None:
    """The units module speaks the core's dimensions; no other module declares them."""
    assert app.contract.units.Quantity is app.core.phrase.Quantity
    declarations = [
        str(path.relative_to(ROOT))
        for path in (ROOT / "app").rglob("*.py")
        if re.search(r'Literal\[\s*"force",', path.read_text())
    ]
    assert declarations == ["app/core/phrase.py"]


# --- the API's units and the page's ----------------------------------------------------

#: API unit -> how an API field name ends when it carries it.
NAME_SUFFIX = {
    "N": "_n",
    "mm": "_mm",
    "mm/s": "_mm_s",
    "mm/s²": "_mm_s2",
    "kg": "_kg",
    "N m": "_nm",
    "°C": "_c",
    "years": "_years",
    "s": "_s",
    "kg m²": "_kg_m2",
    "Hz": "_hz",
    "mH": "_mh",
}


@pytest.mark.parametrize(
    "field", [f for f in FIELDS if f.dimension is not None], ids=lambda f: f.api
)
def test_field_names_carry_their_dimensions_api_unit(field: InputField) -> None:
    assert field.dimension is not None
    assert field.unit == API_SYSTEM[field.dimension]
    assert field.api.endswith(NAME_SUFFIX[field.unit])
    assert field.si_factor == UNITS[field.unit].si


def test_a_field_takes_its_unit_from_its_dimension_only() -> None:
    with pytest.raises(ValueError, match="the dimension gives the unit"):
        InputField(
            api="x_mm", page="x", core="x_m", label="X", help="X", group="Axis",
            kind="number", bounds=(0.0, 1.0), dimension="length", unit="in",
        )  # fmt: skip


def test_the_default_display_units_are_the_apis() -> None:
    api = {d: (UNITS[u].text, 1.0) for d, u in API_SYSTEM.items()}
    assert {d: (UNITS[u].text, f) for d, (u, f) in display_system(DEFAULT_UNITS).items()} == api


def test_every_display_choice_sets_units_of_its_dimensions() -> None:
    for key, choices in DISPLAY_CHOICES.items():
        dimensions = {tuple(units) for units in choices.values()}
        assert len(dimensions) == 1, key
        for units in choices.values():
            assert all(UNITS[u].dimension == d for d, u in units.items())


def test_display_systems_are_every_combination_of_the_choices() -> None:
    assert set(DISPLAY_SYSTEMS) == set(product(*DISPLAY_CHOICES.values()))
    imperial = {"force_unit": "lbf", "length_unit": "in", "torque_unit": "oz_in"}
    assert display_system(imperial)["accel"] == ("in/s²", 25.4)
    assert display_system(imperial)["mass"] == ("lb", 0.45359237)
    assert to_api(1.0, "torque", imperial) == UNITS["oz in"].si


# --- round trips --------------------------------------------------------------------------

finite = st.floats(min_value=-1e12, max_value=1e12, allow_nan=False)


@given(value=finite, unit=st.sampled_from(sorted(UNITS)))
def test_si_round_trip(value: float, unit: str) -> None:
    # a scale with an offset (°F) rounds in its subtraction: to a few units of the offset's
    # last place
    near = 1e-13 * (1.0 + abs(value)) if UNITS[unit].offset else 1e-300
    assert from_si(to_si(value, unit), unit) == pytest.approx(value, rel=1e-15, abs=near)


@given(value=finite, dimension=st.sampled_from(DIMENSIONS))
def test_api_round_trip(value: float, dimension: Quantity) -> None:
    assert si_to_api(api_to_si(value, dimension), dimension) == pytest.approx(
        value, rel=1e-15, abs=1e-300
    )


@given(
    value=finite,
    dimension=st.sampled_from(DIMENSIONS),
    choices=st.sampled_from(sorted(DISPLAY_SYSTEMS)),
)
def test_display_round_trip(value: float, dimension: Quantity, choices: tuple[str, ...]) -> None:
    """Exact to 1e-15 relative; a scale with an offset (°F) to a few units in the last
    place of the offset too (1e-7 °C is 32.0000002 °F, whose float holds 1e-15 °F)."""
    units = dict(zip(DISPLAY_CHOICES, choices, strict=True))
    tolerance = 1e-300 if offset(dimension, units) == 0 else 1e-13
    assert to_api(from_api(value, dimension, units), dimension, units) == pytest.approx(
        value, rel=1e-15, abs=tolerance
    )


def test_a_known_conversion_end_to_end() -> None:
    """1 in/s is 25.4 mm/s in the API and 0.0254 m/s in the core."""
    imperial = {**DEFAULT_UNITS, "length_unit": "in"}
    api = to_api(1.0, "speed", imperial)
    assert (api, api_to_si(api, "speed")) == (25.4, 0.0254)


# --- no unit conversion outside the units module ----------------------------------------

#: factors that convert units: powers of ten and the inch-pound definitions.
SCALES = (1e-9, 1e-6, 1e-3, 1e3, 1e4, 1e6, 1e9, 25.4, 0.0254, 1 / 0.0254, 0.3048, 0.00508)
SCALES += (4.4482216152605, 0.45359237, 9.80665, 6894.757293168, 7.0615518e-3, 0.112984829)
#: (file, value) -> why a literal equal to a scale there is not a unit conversion, or
#: where it goes.
ALLOWED = {
    ("app/core/model.py", 9.80665): "standard gravity g_n: the weight of the moving mass",
    ("app/core/model.py", 1e-9): "PASS_UTILIZATION: the rounding a pass allows",
    ("app/core/formulas/profile.py", 1e-9): "MIN_ACCEL_M_S2: an acceleration floor",
    ("app/core/formulas/trapezoidal.py", 1e-3): "ISO 2904: crest clearance 1 mm, in m",
    ("app/core/formulas/support.py", 1e6): "ISO 281: a rating is for 10^6 revolutions",
    ("app/report/thk_example.py", 1e-3): "THK's example: the motor's rotor, 1e-3 kg m^2",
    ("app/report/validation.py", 1e3): "FANUC's example: a table and work of 1000 kg",
    ("app/report/thread_examples.py", 1e4): "Adaptive Books' example: a load of 10,000 lb",
}
#: keyword arguments and calls whose numbers are input bounds and defaults, in the API
#: unit of their field (pydantic's ``ge``/``le``/``gt``/``lt`` are bounds too): values,
#: not conversions.
VALUE_KEYWORDS = ("bounds", "default", "ge", "le", "gt", "lt")
VALUE_CALLS = ("bounded_number",)


def _value_nodes(tree: ast.AST) -> set[int]:
    """ids of the nodes inside input bounds and defaults."""
    roots: list[ast.AST] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.keyword) and node.arg in VALUE_KEYWORDS:
            roots.append(node.value)
        elif isinstance(node, ast.Call) and getattr(node.func, "id", "") in VALUE_CALLS:
            roots.append(node)
    return {id(n) for root in roots for n in ast.walk(root)}


def scale_literals(source: str) -> list[tuple[int, float]]:
    """(line, value) of every number in ``source`` equal to a scale, outside bounds and
    defaults. Docstrings and doctests are text, not numbers, and are not counted."""
    tree = ast.parse(source)
    values = _value_nodes(tree)
    return sorted(
        (node.lineno, float(node.value))
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant)
        and type(node.value) in (int, float)
        and id(node) not in values
        and any(math.isclose(abs(node.value), s, rel_tol=1e-6) for s in SCALES)
    )


def _scale(value: float) -> float:
    return next(s for s in SCALES if math.isclose(abs(value), s, rel_tol=1e-6))


def test_no_scale_literal_outside_the_units_modules() -> None:
    found = {}
    for path in sorted((ROOT / "app").rglob("*.py")):
        name = str(path.relative_to(ROOT))
        if name in ("app/core/units.py", "app/contract/units.py"):
            continue
        for line, value in scale_literals(path.read_text()):
            if (name, _scale(value)) not in ALLOWED:
                found[f"{name}:{line}"] = value
    assert found == {}


def test_the_scan_finds_conversions_not_bounds_or_doctests() -> None:
    source = (
        "def f(lead_m):\n"
        '    """>>> f(0.001) * 1e3"""\n'
        "    return lead_m * 1e3\n"
        "load = 4.4482216152605 * lbf\n"
        "x = InputField(bounds=(0.0, 1e6), default=1000.0)\n"
    )
    assert scale_literals(source) == [(3, 1000.0), (4, 4.4482216152605)]


# --- temperatures and temperature differences (issue 29, item 6) ------------------------

INCH = {**DEFAULT_UNITS, "length_unit": "in"}


def test_a_temperature_difference_converts_without_the_offset() -> None:
    """NIST SP 811 B.9: a difference of 1 °F is 5/9 K, while t/°F = 1.8 t/°C + 32. A nut
    rise of 211.7 K is 211.7 x 1.8 = 381.06 °F of difference, not 211.7 x 1.8 + 32 =
    413.06 °F; on the page in millimetres it stays 211.7 K."""
    from app.contract.units import Display, amount_text
    from app.core.phrase import Amount

    assert from_api(211.7, "temperature_rise", INCH) == pytest.approx(381.06, rel=1e-12)
    assert from_api(211.7, "temperature", INCH) == pytest.approx(413.06, rel=1e-12)
    assert amount_text(Amount(211.7, "temperature_rise"), INCH) == "381 Δ°F"
    assert Display(INCH).check(211.7, "K") == "381.1 Δ°F"
    assert Display(dict(DEFAULT_UNITS)).check(211.7, "K") == "211.7 K"
    assert API_SYSTEM["temperature_rise"] == "K" and offset("temperature_rise", INCH) == 0.0


#: Each ``Amount`` of a temperature in the core's sentences, by its expression: a
#: difference (a subtraction of temperatures, a rise, a delta, a room to a limit) must
#: carry ``temperature_rise``; an absolute temperature (a reading, a rating, or a
#: temperature plus a difference) ``temperature``.
_AMOUNT = re.compile(r'Amount\(\s*(?P<expr>[^"]*?),\s*"(?P<dim>temperature(?:_rise)?)"\s*\)')


def _is_difference(expression: str) -> bool:
    if re.search(r"\s-\s", expression):
        return True
    if "+" in expression:
        return False
    return re.search(r"rise|delta|room", expression) is not None


def test_every_temperature_in_a_sentence_is_classified() -> None:
    """Every temperature amount in app/ is found by the pattern (none slips past it), and
    each difference carries the difference dimension, each temperature the absolute one."""
    found = []
    for path in sorted((ROOT / "app").rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        written = len(re.findall(r'"temperature(?:_rise)?"\s*\)', text))
        matches = list(_AMOUNT.finditer(text))
        assert len(matches) == written, path
        for m in matches:
            want = "temperature_rise" if _is_difference(m["expr"]) else "temperature"
            assert m["dim"] == want, (path.name, m["expr"])
            found.append(m["dim"])
    assert {"temperature", "temperature_rise"} <= set(found)


def test_every_temperature_check_field_and_output_is_classified() -> None:
    """A check whose value is a temperature names its dimension here (the nut heat check
    judges a rise against the room to the rated maximum: both differences); an input or
    output whose name ends in _rise, _delta or _k carries the difference dimension, one
    ending in _c the absolute one."""
    from typing import Annotated, get_origin, get_type_hints

    from pydantic import BaseModel

    import app.contract.schemas as schemas
    from app.contract.source import From
    from app.core.checks import REGISTRY

    temperature_checks = {
        c.name: c.quantity for c in REGISTRY if c.quantity and "temperature" in c.quantity
    }
    assert temperature_checks == {"nut_heat": "temperature_rise"}

    named: list[tuple[str, str]] = [
        (f.api, f.dimension) for f in FIELDS if f.dimension and "temperature" in f.dimension
    ]
    for model in vars(schemas).values():
        if not (isinstance(model, type) and issubclass(model, BaseModel)):
            continue
        for name, hint in get_type_hints(model, include_extras=True).items():
            if get_origin(hint) is not Annotated:
                continue
            for source in hint.__metadata__:
                if (
                    isinstance(source, From)
                    and source.quantity
                    and "temperature" in source.quantity
                ):
                    named.append((name, source.quantity))
    assert ("ambient_c", "temperature") in named
    for name, dimension in named:
        if name.endswith(("_rise", "_delta", "_k")) or "_rise_" in name:
            assert dimension == "temperature_rise", name
        elif name.endswith("_c"):
            assert dimension == "temperature", name
