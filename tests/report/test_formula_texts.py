"""The formulas table's texts, evaluated: each text, read with its own symbols and units
(n in rpm, as the ``rpm`` row reports it), gives the number its function computes.

The check registry's formulas are evaluated in ``tests/core/test_check_registry.py``; these
are the output table's rows, whose texts are written for reading (``x`` and a space for a
product), so the reading below turns them into Python first.
"""

import math
import re
from collections.abc import Callable

import pytest

from app.core.formulas import geometry, pv, torque
from app.report.formulas import FORMULAS

#: an operand's end and the next operand's start: a product written as a space
_PRODUCT = re.compile(r"(?<=[\w.)])\s+(?=[\w(])")


def _value(text: str, scope: dict[str, float]) -> float:
    """The right-hand side of a formula text (up to its first comma), in ``scope``."""
    side = text.split("=", 1)[1].split(",", 1)[0]
    side = side.replace("H.T.", "HT").replace(" x ", " * ").replace("^", "**")
    result: float = eval(_PRODUCT.sub(" * ", side.strip()), {"pi": math.pi}, scope)
    return result


RPM, LEAD, D_P, DEPTH, LOAD, PV_LIM = 600.0, 0.01, 0.0115, 0.0012, 250.0, 1.0e5
HELIX = geometry.helix_travel(LEAD, D_P)
SCOPE = {"n": RPM, "HT": HELIX, "h": DEPTH, "F": LOAD, "PV_lim": PV_LIM, "lead": LEAD}

CASES: dict[str, Callable[[], float]] = {
    "pv.surface_speed_m_s": lambda: pv.surface_speed(RPM, HELIX),
    "pv.pressure_mpa": lambda: pv.contact_pressure(LOAD, pv.contact_area(HELIX, DEPTH)),
    "pv.value_mpa_m_s": lambda: pv.pv_value(LOAD, RPM, HELIX, DEPTH),
    "pv.max_load_n": lambda: pv.max_load_for_pv(PV_LIM, RPM, DEPTH),
    "pv.max_speed_mm_s": lambda: geometry.linear_speed(
        pv.max_rpm_for_pv(PV_LIM, LOAD, DEPTH), LEAD
    ),
    "rpm": lambda: geometry.screw_speed_rpm(RPM * LEAD / 60.0, LEAD),
    "torque.load_nm": lambda: torque.load_torque(LOAD, LEAD, 0.4),
}


@pytest.mark.parametrize("key", CASES)
def test_the_text_gives_the_functions_number(key: str) -> None:
    scope = {**SCOPE, "v": RPM * LEAD / 60.0, "eta": 0.4}
    got = _value(FORMULAS[key]["formula"], scope)
    assert got == pytest.approx(CASES[key](), rel=1e-12), FORMULAS[key]["formula"]


def test_the_reading_catches_a_wrong_text() -> None:
    """The old surface-speed text, n H.T. with n in rpm, is 60 times the function's."""
    assert _value("V = n H.T.", SCOPE) == pytest.approx(60 * pv.surface_speed(RPM, HELIX))


def test_the_life_in_years_names_every_travel_it_divides() -> None:
    """``life.years`` divides the travel band of ``sections.Life``: the seed's rating cut
    to the nut's wear life, else the wear life, else a ball nut's L10 as travel."""
    text = FORMULAS["life.years"]["formula"]
    for term in ("rated travel", "wear life", "L10"):
        assert term in text, term
