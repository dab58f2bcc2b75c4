"""The candidate's life block (table column, detail, API): the seed's rated travel where
the seed gives one, else the nut's wear life by Archard's law as a band over the wear
rate's range, in km, hours, cycles and years, naming the model."""

import math

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

#: 200 N on an ISO Tr screw, 20 mm/s, 200 mm strokes 1000 times a day, 5 years asked.
DUTY = {
    "load_n": 200.0,
    "speed_mm_s": 20.0,
    "length_mm": 350.0,
    "stroke_mm": 200.0,
    "cycles_per_day": 1000.0,
    "required_life_years": 5.0,
}


def _candidate(client: TestClient, screw: str, **extra: object) -> dict:  # type: ignore[type-arg]
    r = client.post(
        "/api/v1/evaluate", json={"application": {**DUTY, **extra}, "screw": {"catalog_id": screw}}
    )
    assert r.status_code == 200, r.text
    return r.json()["candidate"]  # type: ignore[no-any-return]


def test_an_iso_bronze_nut_shows_its_wear_life_band(client: TestClient) -> None:
    """Tr12x3 with a bronze nut: the seed rates no life, so the block is the wear life.
    The oiled bronze's wear rate is 1e-8 mm3/(N m), range 3.3e-9 to 3e-8
    (catalog/iso-trapezoidal/common.toml): the band's ends are the wear-life check's
    nominal years times 1e-8 / 3e-8 and 1e-8 / 3.3e-9. Hours = travel / 0.02 m/s /
    3600; cycles = travel / (2 x 0.2 m); years = cycles / (1000 x 365); 1 km = 0.1
    million cm."""
    c = _candidate(client, "Tr12x3-bronze")
    life = c["life"]
    assert life["model"] == "wear" and "Archard" in life["note"]
    nominal = next(k for k in c["checks"] if k["name"] == "wear_life")["limit"]
    assert life["years"] == pytest.approx([nominal / 3.0, nominal * 1e-8 / 3.3e-9])
    for km, hours, cycles, years in zip(
        life["travel_km"], life["hours"], life["cycles"], life["years"], strict=True
    ):
        assert hours == pytest.approx(km * 1000.0 / 0.02 / 3600.0)
        assert cycles == pytest.approx(km * 1000.0 / (2 * 0.2))
        assert years == pytest.approx(cycles / (1000.0 * 365.0), rel=1e-3)
    assert life["travel_million_cm"] == pytest.approx([km / 10.0 for km in life["travel_km"]])


def test_a_seed_nut_keeps_its_rated_life(client: TestClient) -> None:
    """A seed series with a rated travel shows that, named "rated", in the seed's unit."""
    c = _candidate(client, "KHD6000-L2")
    life = c["life"]
    assert life["model"] == "rated" and "seed" in life["note"]
    assert life["travel_km"] == pytest.approx([10.0 * m for m in life["travel_million_cm"]])


def test_without_a_stroke_the_life_has_no_cycles(client: TestClient) -> None:
    app = {
        k: v
        for k, v in DUTY.items()
        if k not in ("stroke_mm", "cycles_per_day", "required_life_years")
    }
    r = client.post(
        "/api/v1/evaluate", json={"application": app, "screw": {"catalog_id": "Tr12x3-bronze"}}
    )
    life = r.json()["candidate"]["life"]
    assert life["cycles"] is None and life["years"] is None
    assert all(math.isfinite(h) and h > 0 for h in life["hours"])


def test_the_page_names_the_life_model(client: TestClient) -> None:
    """The table's life column and the detail say which model each number is from."""
    params = {
        "load": "200",
        "speed": "20",
        "length": "350",
        "stroke": "200",
        "cycles_per_day": "1000",
        "family": "TR-C45",
    }
    page = BeautifulSoup(client.get("/", params=params).text, "html.parser")
    marks = {tag.text for tag in page.select("td.life .life-model")}
    # the wear rates are assumed (catalog notes): the cell says so where it is read
    assert marks == {"wear, assumed rate"}
    r = client.get("/detail", params={**params, "id": "Tr12x3-bronze"})
    detail = BeautifulSoup(r.text, "html.parser").select_one("dd.life")
    assert detail is not None and "Wear life (assumed wear rates)" in detail.text
    assert "hours at the top speed" in detail.text and "cycles" in detail.text


def test_a_ball_nut_life_is_named_l10_not_wear(client: TestClient) -> None:
    """A ball nut's life is its L10 fatigue life (ISO 3408-5), in the cell and the detail:
    never the leadscrew's assumed wear rate."""
    params = {"load": "500", "speed": "100", "length": "500", "stroke": "400"}
    params |= {"cycles_per_day": "1000", "family": "HIWIN-GROUND"}
    page = BeautifulSoup(client.get("/", params=params).text, "html.parser")
    marks = {tag.text for tag in page.select("td.life .life-model")}
    assert marks == {"L10"}
    first = page.select_one("tbody.candidate[data-id]")
    assert first is not None
    r = client.get("/detail", params={**params, "id": first["data-id"]})
    detail = BeautifulSoup(r.text, "html.parser").select_one("dd.life")
    assert detail is not None and "L10 fatigue life (ISO 3408-5)" in detail.text
    assert "assumed wear" not in detail.text
