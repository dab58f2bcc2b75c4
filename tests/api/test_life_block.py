"""The candidate's life block (table column, detail, API): the seed's rated travel where
the seed gives one, else the nut's wear life by Archard's law as a band over the wear
rate's range, in km, hours, cycles and years, naming the model."""

import math

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

#: 200 N on an ISO Tr screw, 20 mm/s, 200 mm strokes 1000 times a day, 5 years asked, the
#: nut greased (a bronze nut's wear is rated lubricated, not run dry).
DUTY = {
    "lubrication": "greased",
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
        # 200 mm each way at 20 mm/s, 0.02 s ramps at 1 m/s² (0.2 mm each): 10.02 s a move
        assert hours == pytest.approx(cycles * 2 * (0.02 + 0.1996 / 0.02 + 0.02) / 3600.0)
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
        "lubrication": "greased",
    }
    page = BeautifulSoup(client.get("/", params=params).text, "html.parser")
    marks = {tag.text for tag in page.select("td.life .life-model")}
    # the wear rates are assumed (catalog notes): the cell says so where it is read
    assert marks == {"wear, assumed rate"}
    r = client.get("/detail", params={**params, "id": "Tr12x3-bronze"})
    detail = BeautifulSoup(r.text, "html.parser").select_one("dd.life")
    assert detail is not None and "Wear life (assumed wear rates)" in detail.text
    assert "hours of operation" in detail.text and "cycles" in detail.text
    assert "km of travel (" in detail.text
    inches = client.get("/detail", params={**params, "id": "Tr12x3-bronze", "length_unit": "in"})
    # the travel in the page's unit: miles on an inch page, where it was in km
    assert " mi of travel (" in BeautifulSoup(inches.text, "html.parser").select_one("dd.life").text


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


#: 150 N and 15 kg over 1.6 m strokes at 150 mm/s, 0.5 m/s² ramps, on B14000-L20-TFE.
LONG_STROKE = {
    "load_n": 150.0,
    "speed_mm_s": 150.0,
    "length_mm": 1800.0,
    "stroke_mm": 1600.0,
    "accel_mm_s2": 500.0,
    "moving_mass_kg": 15.0,
}


def test_the_hours_are_the_cycles_times_the_time_of_one(client: TestClient) -> None:
    """The hours were the travel at the top speed: 368.9 h, the ramps and the dwells left
    out, where the years count whole cycles (8 h a day with a 5 s dwell: 552 h in the
    years, 369 h in the hours). One move: 0.3 s up to 150 mm/s over 22.5 mm, 1,555 mm at
    150 mm/s (10.367 s), 0.3 s down: 10.967 s, so 21.933 s a cycle out and back."""

    def life(**duty: float) -> dict:  # type: ignore[type-arg]
        body = {"application": {**LONG_STROKE, **duty}, "screw": {"catalog_id": "B14000-L20-TFE"}}
        return client.post("/api/v1/evaluate", json=body).json()["candidate"]["life"]  # type: ignore[no-any-return]

    cycle_s = 2 * (0.3 + 1.555 / 0.15 + 0.3)
    plain = life(cycles_per_day=1000.0)
    assert plain["hours"] == pytest.approx([c * cycle_s / 3600 for c in plain["cycles"]])
    assert plain["hours"][0] == pytest.approx(379.31, abs=0.01)
    shift = life(hours_per_day=8.0, dwell_s=5.0)
    assert shift["hours"] == pytest.approx([y * 365 * 8 for y in shift["years"]])
    assert shift["hours"] == pytest.approx([c * (cycle_s + 10) / 3600 for c in shift["cycles"]])


def test_the_tables_travel_is_in_the_pages_unit(client: TestClient) -> None:
    """Without a duty the life column gives the travel: km on a metric page, miles on an
    inch page (1 mi = 1.609344 km), the band the API gives in km."""
    metric = {"load": "200", "speed": "20", "length": "350", "family": "TR-C45"}
    inches = {"load": "45", "speed": "0.8", "length": "14", "family": "TR-C45", "length_unit": "in"}
    for params, unit in ((metric, "km"), (inches, "mi")):
        page = BeautifulSoup(client.get("/", params=params).text, "html.parser")
        cells = [td.contents[0].strip() for td in page.select("td.life")]
        assert cells and all(c.endswith(f" {unit}") for c in cells), cells
    # the inch axis in the API's units: 0.8 in/s = 20.32 mm/s, 14 in = 355.6 mm
    api = client.get(
        "/api/v1/select",
        params={"load_n": "45", "speed_mm_s": "20.32", "length_mm": "355.6", "family": "TR-C45"},
    )
    first_api = api.json()["candidates"][0]["id"]
    page = BeautifulSoup(client.get("/", params=inches).text, "html.parser")
    row = page.select("table.candidates tbody tr")[0]
    assert row.select_one(".cid").text == first_api
    cell = row.select_one("td.life").contents[0].strip()
    low, high = (float(v.replace(",", "")) for v in cell.removesuffix(" mi").split("–"))
    detail = client.post(
        "/api/v1/evaluate",
        json={
            "application": {"load_n": 45, "speed_mm_s": 20.32, "length_mm": 355.6},
            "screw": {"catalog_id": first_api},
        },
    ).json()["candidate"]["life"]["travel_km"]
    km_per_mi = 1.609344
    assert low == pytest.approx(detail[0] / km_per_mi, rel=0.005)
    assert high == pytest.approx(detail[1] / km_per_mi, rel=0.005)


def test_a_rating_the_wear_cuts_says_so(client: TestClient) -> None:
    """ZBX4000-L8-TFE: the seed rates 380-500 million cm. At 30 N the nut's wear life
    (3.25-29.6 million cm at the assumed rate) cuts both ends: the API says so and the
    table's mark no longer reads as the catalog's rating. With no thrust to wear the nut
    the seed's band stands."""
    axis = {"speed_mm_s": 50, "length_mm": 300, "stroke_mm": 200, "cycles_per_day": 2000}
    body = {"application": {**axis, "load_n": 30}, "screw": {"catalog_id": "ZBX4000-L8-TFE"}}
    life = client.post("/api/v1/evaluate", json=body).json()["candidate"]["life"]
    assert life["model"] == "rated" and life["capped_by_wear"]
    assert life["travel_million_cm"][1] < 380.0
    idle = {"application": {**axis, "load_n": 0}, "screw": {"catalog_id": "ZBX4000-L8-TFE"}}
    life = client.post("/api/v1/evaluate", json=idle).json()["candidate"]["life"]
    assert not life["capped_by_wear"]
    assert life["travel_million_cm"] == pytest.approx([380.0, 500.0])
    page = {"load": "30", "speed": "50", "length": "300", "stroke": "200",
            "cycles_per_day": "2000", "family": "ZBX", "lead": "8"}  # fmt: skip
    soup = BeautifulSoup(client.get("/", params=page).text, "html.parser")
    marks = {tag.text for tag in soup.select("td.life .life-model")}
    assert marks == {"rated, cut by wear (assumed rate)"}


def test_a_preloaded_ball_nuts_life_counts_its_preload(client: TestClient) -> None:
    """R15-10K3-FSC (ground, Ca 9,600 N) is taken at the 5 % preload HIWIN allows a single
    nut (480 N, F_lim = 2^1.5 x 480 = 1,357.6 N). 50 N pushed 250 mm at 300 mm/s, 8 kg at
    2 m/s², 6,000 cycles a day: every segment presses side 1, at 66 N (45 mm a cycle), 50 N
    (410 mm) and 34 N (45 mm); the axis's cubic mean thrust is 50.91 N. Side 1 carries
    (1 + F / 1357.6)^1.5 x 480 = 515.4, 506.8 and 498.1 N (HIWIN F 3.7), a cubic mean of
    506.8 N; side 2 what is left of its preload, 449.4, 456.8 and 464.1 N, a mean of
    456.8 N. L1 = (9600 / (1.2 x 506.8))^3 x 10^6 = 3933e6 rev, L2 = (9600 / (1.2 x
    456.8))^3 x 10^6 = 5371e6, L = (L1^(-10/9) + L2^(-10/9))^(-9/10) = 0.6179 L1 = 2430e6
    (HIWIN sec. 3.7.2 d)); 2 x 0.25 m / 0.01 m = 50 rev a cycle, 300,000 a day: 22.2
    years. One-sided (L1 alone) it read 35.9 years, and 35,446 on the axis's thrust
    alone."""
    app = {"load_n": 50, "load_direction": "fixed", "speed_mm_s": 300, "length_mm": 500,
           "accel_mm_s2": 2000, "stroke_mm": 250, "cycles_per_day": 6000,
           "moving_mass_kg": 8, "required_life_years": 5}  # fmt: skip
    c = _candidate_of(client, app, "R15-10K3-FSC")
    ball = next(k for k in c["checks"] if k["name"] == "ball_life")
    l1, l2 = (9600 / (1.2 * 506.8)) ** 3 * 1e6, (9600 / (1.2 * 456.8)) ** 3 * 1e6
    by_hand = (l1 ** (-10 / 9) + l2 ** (-10 / 9)) ** (-9 / 10) / (50 * 6000 * 365)
    assert ball["limit"] == pytest.approx(by_hand, rel=0.002)
    assert ball["limit"] == pytest.approx(22.2, abs=0.05)
    assert (
        "preload 480 N loads both its sides (the axis's thrust alone: 50.91 N)" in (ball["message"])
    )
    assert "cubic mean loads 506.8 N and 456.8 N" in ball["message"]
    assert c["life"]["years"][0] == pytest.approx(ball["limit"], rel=1e-9)
    # a nut with play (rolled, no preload) is rated on the axis's thrust
    rolled = _candidate_of(client, app, "R16-10K3-FSCDIN")
    assert "preload" not in next(k for k in rolled["checks"] if k["name"] == "ball_life")["message"]


def _candidate_of(client: TestClient, app: dict[str, object], screw: str) -> dict:  # type: ignore[type-arg]
    body = {"application": app, "screw": {"catalog_id": screw}}
    response = client.post("/api/v1/evaluate", json=body)
    assert response.status_code == 200, response.text
    return response.json()["candidate"]  # type: ignore[no-any-return]


def test_the_ball_nut_load_factor_is_an_input_the_life_falls_with_as_its_cube(
    client: TestClient,
) -> None:
    """HIWIN sec. 3.7.2: f_w 1.1 to 1.2 without impact, 1.3 to 1.8 in normal operation.
    The default 1.2 gives R16-10K3-FSCDIN a life L; f_w 1.5 gives L (1.2 / 1.5)^3 = 0.512 L,
    and the check's message names the factor used. Outside 1 to 5 it is refused by field."""
    app = {"load_n": 300, "speed_mm_s": 300, "length_mm": 500, "accel_mm_s2": 2000,
           "stroke_mm": 300, "cycles_per_day": 5000, "moving_mass_kg": 10,
           "required_life_years": 1}  # fmt: skip
    default = _candidate_of(client, app, "R16-10K3-FSCDIN")
    normal = _candidate_of(client, {**app, "ball_load_factor": 1.5}, "R16-10K3-FSCDIN")
    base = next(k for k in default["checks"] if k["name"] == "ball_life")["limit"]
    check = next(k for k in normal["checks"] if k["name"] == "ball_life")
    assert check["limit"] == pytest.approx(base * (1.2 / 1.5) ** 3, rel=1e-9)
    assert "load factor 1.5" in check["message"]
    assert normal["life"]["years"][0] == pytest.approx(check["limit"], rel=1e-9)
    body = {
        "application": {**app, "ball_load_factor": 0.5},
        "screw": {"catalog_id": "R16-10K3-FSCDIN"},
    }
    refused = client.post("/api/v1/evaluate", json=body)
    assert refused.status_code == 422
    assert refused.json()["detail"][0]["field"].endswith("ball_load_factor")
