"""Units at the page's edges: a field's bound is stated as a number the field accepts,
in the unit it is typed in, and the custom screw's numbers survive a unit switch and back
as typed, judging the same screw.

Factors from NIST SP 811 (2008) appendix B: 1 in = 25.4 mm, 1 lbf = 4.4482216152605 N,
g_n = 9.80665 m/s², t/°F = 1.8 t/°C + 32.
"""

import json
import re

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

AXIS = {"load": "10", "speed": "1", "length": "20"}
INCH = {"force_unit": "lbf", "length_unit": "in", "torque_unit": "oz_in"}
SCREW = {
    "outer_diameter_mm": "12",
    "root_diameter_mm": "9.5",
    "lead_mm": "3",
    "friction_dynamic": "0.15",
    "friction_static": "0.2",
    "pv_limit_mpa_m_s": "1.5",
    "drag_torque_nm": "0.02",
}
MM_AXIS = {"load": "50", "speed": "20", "length": "500", "ambient_c": "40"}
BOUND = re.compile(r"Must be (?:at least|at most|more than|less than) (\S+) ")


def _error(client: TestClient, path: str, params: dict[str, str], field: str) -> str:
    page = BeautifulSoup(client.get(path, params=params).text, "html.parser")
    found = page.select_one(f"#e-{field}")
    return "" if found is None else found.text


@pytest.mark.parametrize(
    ("typed", "field", "expected"),
    [
        # 1 mm is 0.0393700787 in: "at least 0.03937 in" refused 0.03937 itself
        ({**INCH, "length": "0.01"}, "length", "Must be at least 0.03938 in."),
        ({**INCH, "speed": "1e-6"}, "speed", "Must be at least 3.938e-05 in/s."),
        # -273.15 °C is -459.67 °F exactly: "-459.7" is below absolute zero
        ({**INCH, "ambient_c": "-500"}, "ambient_c", "Must be at least -459.67 °F."),
        ({**INCH, "max_torque": "1e-9"}, "max_torque", "Must be at least 0.0001417 oz in."),
        # 1e6 N is 224808.94 lbf, 101971.6 kgf; 1e6 mm/s² is 101.97 g
        ({**INCH, "load": "1e9"}, "load", "Must be at most 224808 lbf."),
        ({"force_unit": "kgf", "load": "1e9"}, "load", "Must be at most 101971 kgf."),
        ({"accel_unit": "g", "accel": "1e6"}, "accel", "Must be at most 101.9 g."),
        ({**INCH, "accel": "1e9"}, "accel", "Must be at most 39370 in/s²."),
    ],
    ids=["length-in", "speed-in", "ambient-f", "torque-oz-in", "lbf", "kgf", "g", "in-s2"],
)
def test_a_bound_is_stated_as_a_number_the_field_accepts(
    client: TestClient, typed: dict[str, str], field: str, expected: str
) -> None:
    """The bound is the field's in the unit typed, rounded inside the allowed range where
    4 figures cannot write it exactly: typing the number the message states is accepted."""
    message = _error(client, "/", {**AXIS, **typed}, field)
    assert message == expected
    match = BOUND.match(message + " ")
    assert match is not None
    assert _error(client, "/", {**AXIS, **typed, field: match[1]}, field) == ""


def test_a_custom_screw_bound_is_a_number_the_field_accepts(client: TestClient) -> None:
    """The custom screw's lead is at least 0.01 mm: 0.0003937008 in, stated 0.0003938 in."""
    params = {**SCREW, **MM_AXIS, **INCH, "lead_mm": "1e-6"}
    message = _error(client, "/custom", params, "lead_mm")
    assert message == "Must be at least 0.0003938 in."
    assert _error(client, "/custom", {**params, "lead_mm": "0.0003938"}, "lead_mm") == ""


def _custom(client: TestClient, params: dict[str, str]) -> BeautifulSoup:
    return BeautifulSoup(client.get("/custom", params=params).text, "html.parser")


def _sent(page: BeautifulSoup) -> dict[str, str]:
    """The custom form's fields as the browser sends them back (the hidden records too)."""
    form = page.select_one("form")
    assert form is not None
    fields = form.select("input[type=text][value], input[type=hidden][value]")
    sent = {i["name"]: i["value"] for i in fields if i["value"]}
    chosen = [(s["name"], s.select_one("option[selected]")) for s in form.select("select")]
    sent |= {name: option["value"] for name, option in chosen if option is not None}
    return {k: v for k, v in sent.items() if not k.startswith("from_")}


def test_a_custom_screw_switched_to_inches_and_back_is_the_screw_typed(
    client: TestClient,
) -> None:
    """A 12 mm x 3 mm screw switched to inches showed 0.4724 in and 0.1181 in (11.999 mm,
    2.9997 mm), judged as such, and 11.999 mm and 2.9997 mm after switching back. Each
    number now converts exactly: the screw judged is the one typed, and switching back
    restores the numbers typed."""
    metric = {**SCREW, **MM_AXIS}
    switch = {"length_unit": "in", "force_unit": "lbf", "torque_unit": "oz_in"}
    typed_in = {"from_length_unit": "mm", "from_force_unit": "N", "from_torque_unit": "N_m"}
    inches = _custom(client, {**metric, **switch, **typed_in})
    shown = {name: inches.select_one(f"#f-{name}")["value"] for name in SCREW}
    assert float(shown["outer_diameter_mm"]) * 25.4 == 12.0
    assert float(shown["lead_mm"]) * 25.4 == 3.0

    def torque(page: BeautifulSoup) -> str:
        link = next(a["href"] for a in page.select("a") if "/custom/export.json" in a["href"])
        return str(client.get(link).json()["candidate"]["torque"])

    assert torque(inches) == torque(_custom(client, metric))
    back = {**_sent(inches), "from_length_unit": "in", "from_force_unit": "lbf",
            "from_torque_unit": "oz_in", "length_unit": "mm", "force_unit": "N",
            "torque_unit": "N_m"}  # fmt: skip
    again = _custom(client, back)
    assert {name: again.select_one(f"#f-{name}")["value"] for name in SCREW} == SCREW


def test_the_governing_segments_hover_names_the_torque_unit(client: TestClient) -> None:
    """The cycle's torque chart marks the segment that governs the motor at its torque,
    in the torque unit chosen, as every other torque of the chart: '12.4 oz in', not a
    bare '12.4'."""
    axis = {"load": "11.24", "moving_mass_kg": "11", "speed": "2", "length": "20",
            "stroke": "12", "cycles_per_day": "1000", "motor": "23hs32-4004s", "limit": "3",
            **INCH}  # fmt: skip
    page = BeautifulSoup(client.get("/charts", params=axis).text, "html.parser")
    figure = json.loads(page.select_one("#fig-cycle_torque").text)
    governs = [t for t in figure["data"] if t["name"].startswith("Governs")]
    assert governs
    assert [t["hovertemplate"] for t in governs] == ["%{y:.4g} oz in<extra>governs</extra>"]
