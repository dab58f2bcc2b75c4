"""Nut ratings through the API (issue 21, item 4): a polymer nut's dynamic axial load.

No maker's dynamic load for a polymer trapezoidal nut could be cited, so the catalog
derives one: the material's maximum pressure (Neale, Tribology Handbook A5: thermoplastic
10 MPa, filled PTFE 7 MPa) times 0.25, the low end of the 0.25-0.75 share of the flank
area that makers count for a flexing plastic nut (linearmotiontips.com), over the engaged
flank area (L / P) pi d2 H1 (Shigley's power-screw bearing area; ISO 2904: d2 = d - P / 2,
H1 = P / 2). Each figure is worked out here by hand."""

import math

import pytest
from fastapi.testclient import TestClient

from tests.api.calls import check, evaluate, names

API = "/api/v1"
#: Tr20x4: d2 = 18 mm, H1 = 2 mm; the catalog's nut is 2 d = 40 mm long, 10 turns.
TR20_TURN_M2 = math.pi * 18e-3 * 2e-3
#: A slow axis (0.5 mm/s: 7.5 rpm, flanks sliding at 7.1 mm/s), so that the PV limit
#: leaves the maximum pressure in charge of the contact-pressure check.
SLOW = {"load_n": 5000, "speed_mm_s": 0.5, "length_mm": 500}


def test_a_tr20x4_acetal_nut_fails_at_5_kn_with_its_rating_and_source(
    client: TestClient,
) -> None:
    """Tr20x4 acetal at 5 kN: p_dyn = 0.25 x 10 MPa = 2.5 MPa over 10 x pi x 18 x 2 mm^2 =
    1131 mm^2 carries 2827 N, so 5 kN fails (1.77 x). The contact-pressure check alone
    passed it: 10 MPa x 1131 mm^2 = 11.3 kN, and PV 0.07 MPa m/s at 7.1 mm/s allows
    9.9 MPa, 11.2 kN."""
    c = evaluate(client, "Tr20x4-acetal", **SLOW)
    rated = check(c, "design_load")
    assert rated is not None and not rated["passed"]
    hand = 0.25 * 10e6 * 10 * TR20_TURN_M2
    assert hand == pytest.approx(2827.4, abs=0.1)
    assert rated["limit"] == pytest.approx(hand) and rated["value"] == pytest.approx(5000)
    assert "2827 N" in rated["message"] and "2.5 MPa" in rated["message"]
    assert "Neale, Tribology Handbook A5" in rated["message"]
    assert "derived" in rated["message"] and "linearmotiontips.com" in rated["message"]
    # the fix proposes 5 % inside the rating: 0.95 x 2827 N
    assert "at most 2686 N" in rated["fix"] and "5 % margin" in rated["fix"]
    pressure = check(c, "bearing_pressure")
    assert pressure is not None and pressure["passed"]
    v = 7.5 / 60 * math.hypot(4e-3, math.pi * 18e-3)
    assert pressure["limit"] == pytest.approx(min(10e6, 0.07e6 / v) * 10 * TR20_TURN_M2)
    prov = c["provenance"]["dynamic_pressure"]
    assert prov["kind"] == "derived" and "Neale" in prov["source"]


def test_a_ptfe_nut_is_rated_by_its_own_material(client: TestClient) -> None:
    """Filled PTFE: 0.25 x 7 MPa = 1.75 MPa over the same 1131 mm^2, 1979 N."""
    rated = check(evaluate(client, "Tr20x4-ptfe", **SLOW), "design_load")
    assert rated is not None and not rated["passed"]
    assert rated["limit"] == pytest.approx(0.25 * 7e6 * 10 * TR20_TURN_M2)
    assert "1979 N" in rated["message"] and "PTFE" in rated["message"]


def test_the_rating_grows_with_the_size_and_the_nut_length(client: TestClient) -> None:
    """Tr24x5 acetal (d2 21.5 mm, H1 2.5 mm, a 48 mm nut: 9.6 turns): 2.5 MPa x 9.6 x pi x
    21.5 x 2.5 mm^2 = 4053 N; a 60 mm Tr20x4 nut (15 turns) carries 4241 N. Both below
    5 kN: a polymer nut of this size does not carry it."""
    tr24 = check(evaluate(client, "Tr24x5-acetal", **SLOW), "design_load")
    assert tr24 is not None
    assert tr24["limit"] == pytest.approx(2.5e6 * 9.6 * math.pi * 21.5e-3 * 2.5e-3)
    longer = check(evaluate(client, "Tr20x4-acetal", **SLOW, nut_length_mm=60), "design_load")
    assert longer is not None
    assert longer["limit"] == pytest.approx(2.5e6 * 15 * TR20_TURN_M2)
    assert (tr24["limit"], longer["limit"]) == pytest.approx((4053, 4241), abs=1)
    assert not tr24["passed"] and not longer["passed"]


def test_a_bronze_nut_is_not_held_to_a_polymer_rating(client: TestClient) -> None:
    """Tr20x4 bronze carries 5 kN slowly: 11 MPa x 1131 mm^2 = 12.4 kN by Shigley's table,
    and it has no polymer dynamic rating."""
    c = evaluate(client, "Tr20x4-bronze", **SLOW)
    assert "design_load" not in names(c)
    pressure = check(c, "bearing_pressure")
    assert pressure is not None and pressure["passed"]
    assert pressure["limit"] == pytest.approx(11e6 * 10 * TR20_TURN_M2)


def test_select_drops_polymer_tr20x4_nuts_at_5_kn(client: TestClient) -> None:
    """Across the catalog at 5 kN, no polymer Tr20x4 nut passes, and the bronze one does."""
    body = client.get(f"{API}/select", params={**SLOW, "limit": 100}).json()
    ids = [x["id"] for x in body["candidates"]]
    assert "Tr20x4-bronze" in ids
    assert not [i for i in ids if i.startswith("Tr20x4") and ("acetal" in i or "ptfe" in i)]
