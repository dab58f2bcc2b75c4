"""Numbers past any float once converted, and an axis too hot for a polymer nut, are
answered with the field's own message or a page, never a 500 (issue 31, item 4)."""

import re

import pytest
from fastapi.testclient import TestClient

AXIS = "speed=50&length=500"
#: the largest float
MAX = "1.7976931348623157e308"


@pytest.mark.parametrize(
    ("query", "field", "message"),
    [
        # 1e308 lbf is 4.4e308 N, past the largest float (1.8e308)
        (f"load=1e308&{AXIS}&force_unit=lbf", "load", "Must be at most 224808 lbf."),
        (f"load=-1e308&{AXIS}&force_unit=lbf", "load", "Must be at least 0 lbf."),
        (f"load=1e308&{AXIS}&force_unit=kgf", "load", "Must be at most 101971 kgf."),
        ("load=50&speed=50&length=1e308&length_unit=in", "length", "Must be at most 3937 in."),
        (f"load=50&{AXIS}&accel=1e308&length_unit=in", "accel", "Must be at most 39370 in/s²."),
        # typed in N m, shown in oz in: 1.4e310 oz in is no float; kept as typed
        (
            f"load=50&{AXIS}&max_torque=1e308&from_torque_unit=N_m&torque_unit=oz_in",
            "max_torque",
            "Must be at most 14161193 oz in.",
        ),
        # the largest float typed in N, shown in kgf (1.8e307): its link's decimal in kgf
        # read back past the largest float, whose rounding raised (a 500)
        (
            f"load={MAX}&{AXIS}&from_force_unit=N&force_unit=kgf",
            "load",
            "Must be at most 101971 kgf.",
        ),
        (
            f"load=50&{AXIS}&lead={MAX}&from_length_unit=mm&length_unit=in",
            "lead",
            "Must be at most 39.37 in.",
        ),
    ],
    ids=[
        "lbf",
        "lbf-negative",
        "kgf",
        "length-in",
        "accel-in",
        "torque-switched",
        "largest-float-switched",
        "largest-float-switched-in",
    ],
)
def test_a_number_past_any_float_gets_its_bound(
    client: TestClient, query: str, field: str, message: str
) -> None:
    """The bound is the field's (1e6 N, 1e5 mm, 1e6 mm/s², 1e5 N m) in the display unit."""
    page = client.get(f"/?{query}")
    assert page.status_code == 200
    assert f'id="e-{field}">{message}<' in page.text
    for path in ("/export.csv", "/report", "/detail"):
        assert client.get(f"{path}?{query}").status_code == 422, path


HOT = "load=0.001&speed=3000&length=70&ambient_c=250&motor=17hs19-2004s1"


def test_an_axis_too_hot_for_its_nuts_draws_its_charts(client: TestClient) -> None:
    """At 250 °C a polymer nut's PV limit is zero: its share of it is infinite, which a
    log axis leaves out (the lead sweep drew its ticks from it and failed)."""
    page = client.get(f"/?{HOT}")
    assert page.status_code == 200
    charts = client.get(f"/charts?{HOT}", headers={"HX-Request": "true"})
    assert charts.status_code == 200 and 'id="fig-lead_sweep"' in charts.text
    for text in (page.text, charts.text):
        assert "Infinity" not in text and "NaN" not in text
    rejected = client.get(f"/rejected?{HOT}", headers={"HX-Request": "true"})
    top = re.search(r'/detail\?[^"]*id=([^"&]+)', page.text + rejected.text)
    assert top, "no candidate on the page"
    report = client.get(f"/report?{HOT}&id={top.group(1)}")
    assert report.status_code == 200 and "Infinity" not in report.text


#: Two moves of 5e-324 mm, the smallest float: not 0 in mm, but 0 m in SI, and the cycle
#: took no time (the nut's mean speed and the cycles a day divided by it).
TINY_MOVES = "5e-324:250:0:0:0:0:0:opposes;-5e-324:250:0:0:0:0:0:opposes"


def test_a_move_shorter_than_the_shortest_stroke_is_refused_at_its_cell(
    client: TestClient,
) -> None:
    """A move's distance is bounded as the stroke, 0.01 mm either way: said at each cell
    in the page's unit, a 422 for the links and the API, never a 500."""
    page = client.get(f"/?{AXIS}&load=100&moves={TINY_MOVES}")
    assert page.status_code == 200
    assert 'id="e-m0_dist">Must be at least 0.01 mm.<' in page.text
    assert 'id="e-m1_dist">Must be at most -0.01 mm.<' in page.text
    inch = client.get(f"/?{AXIS}&load=100&moves={TINY_MOVES}&length_unit=in")
    assert 'id="e-m0_dist">Must be at least 0.0003938 in.<' in inch.text
    for path in ("/export.csv", "/export.json", "/charts", "/versus", "/report"):
        response = client.get(f"{path}?{AXIS}&load=100&moves={TINY_MOVES}")
        assert response.status_code == 422, path
        assert "Move 1 distance</strong>: Must be at least 0.01 mm." in response.text, path
    api = client.get(f"/api/v1/select?load_n=100&speed_mm_s=50&length_mm=500&moves={TINY_MOVES}")
    assert api.status_code == 422
    fields = [d["field"] for d in api.json()["detail"]]
    assert fields == ["moves.0.distance_mm", "moves.1.distance_mm"]


#: A rotor of 5e-324 kg m², the smallest float: the load's inertia over it is no float.
TINY_ROTOR = "load=100&speed=50&length=500&motor_inertia=5e-324&id=R12-04B1-RSIT"


def test_a_rotor_too_small_for_any_ratio_is_said_without_inf(client: TestClient) -> None:
    """The inertia ratio is infinite: the detail and the report wrote its value to 4
    figures (a 500) and its message said 'inf times'; the value is a dash, as the JSON's
    null, and the message says it is over the largest float."""
    for path in ("/detail", "/report"):
        response = client.get(f"{path}?{TINY_ROTOR}")
        assert response.status_code == 200, path
        assert "is over 1.8e+308 times the rotor" in response.text, path
        assert not re.search(r"(?<![A-Za-z])-?inf(?![A-Za-z])", response.text), path
    api = client.get(
        "/api/v1/evaluate?load_n=100&speed_mm_s=50&length_mm=500"
        "&motor_inertia_kg_m2=5e-324&catalog_id=R12-04B1-RSIT"
    )
    check = next(k for k in api.json()["candidate"]["checks"] if k["name"] == "inertia_ratio")
    assert check["value"] is None and "over 1.8e+308 times" in check["message"]
