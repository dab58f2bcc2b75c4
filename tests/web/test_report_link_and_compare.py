"""The filed report carries its absolute link (from the host it was served from) and its
date; the compare page has the screw's size, lead, nut and speed rows and writes a life
band as its range, as the results table does."""

from datetime import UTC, datetime
from urllib.parse import parse_qsl, urlsplit

from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

AXIS = {"load": "100", "speed": "50", "length": "500"}
DUTY = {**AXIS, "stroke": "200", "cycles_per_day": "1000"}


def test_the_report_link_is_absolute_on_the_host_it_was_served_from(client: TestClient) -> None:
    for host in ("testserver", "selector.example.org:8443"):
        response = client.get("/report", params=AXIS, headers={"host": host})
        page = BeautifulSoup(response.text, "html.parser")
        cid = page.select_one("#report-heading .cid").text
        link = page.select_one(".report-date a.report-link")
        assert link["href"] == link.text
        parts = urlsplit(link["href"])
        assert (parts.scheme, parts.netloc, parts.path) == ("http", host, "/report")
        assert dict(parse_qsl(parts.query)) == {**AXIS, "id": cid}
        # the link reopens the same report
        again = BeautifulSoup(client.get(f"/report?{parts.query}").text, "html.parser")
        assert again.select_one("#report-heading .cid").text == cid


def test_the_report_is_dated(client: TestClient) -> None:
    before = datetime.now(UTC).date().isoformat()
    page = BeautifulSoup(client.get("/report", params=AXIS).text, "html.parser")
    date = page.select_one(".report-date time")["datetime"]
    assert date in {before, datetime.now(UTC).date().isoformat()}
    assert page.select_one(".report-date time").text == date


def test_compare_has_size_lead_nut_and_speed_rows_and_life_ranges(client: TestClient) -> None:
    """Each row's cells are the API's values for the candidates compared; the life (years
    of the duty) is its band 'low–high', as the results table writes it."""
    api = client.get(
        "/api/v1/select",
        params={
            "load_n": "100", "speed_mm_s": "50", "length_mm": "500", "stroke_mm": "200",
            "cycles_per_day": "1000",
        },
    ).json()["candidates"][:3]  # fmt: skip
    ids = [c["id"] for c in api]
    page = BeautifulSoup(
        client.get("/compare", params=[*DUTY.items(), *(("ids", i) for i in ids)]).text,
        "html.parser",
    )
    rows = {
        tr["data-row"]: [td.contents[0].strip() for td in tr.select("td")]
        for tr in page.select("table.compare tbody tr")
    }
    assert rows["nut_material"] == [c["nut_material"] for c in api]
    assert [float(v) for v in rows["outer_diameter_mm"]] == [c["outer_diameter_mm"] for c in api]
    assert [float(v) for v in rows["lead_mm"]] == [c["lead_mm"] for c in api]
    assert [float(v) for v in rows["rpm"]] == [round(c["rpm"]) for c in api]
    for cell, c in zip(rows["life.years"], api, strict=True):
        if c["screw_type"] == "ball":  # a ball nut's L10 is one value, not a band
            assert float(cell.replace(",", "")) == float(f"{c['life']['years'][0]:.3g}")
            continue
        low, high = (float(v.replace(",", "")) for v in cell.split("–"))
        assert low == float(f"{c['life']['years'][0]:.3g}")
        assert high == float(f"{c['life']['years'][1]:.3g}")
        assert low < high


#: Tr8x8(P2)-ptfe passes this axis at 99.76 % of its nut's allowed pressure.
CLOSE_PASS = "load=50&speed=200&length=500&stroke=300&accel=2000&moving_mass_kg=5"
#: Tr24x10(P5)-ptfe fails this axis at 100.05 % of the stepper's torque-speed curve.
CLOSE_FAIL = (
    "load=30&speed=100&length=300&stroke=200&accel=2000&moving_mass_kg=2&motor=17hs19-2004s1"
)


def test_a_utilization_near_its_limit_reads_on_its_side_of_100_percent(
    client: TestClient,
) -> None:
    """A pass at 99.76 % read "100 %" on the detail, the compare page and the report, and
    a fail at 100.05 % read "100 %" too: every page now writes them as the verdict does
    (``wording.percent``), 99.8 % and 100.05 %."""
    detail = BeautifulSoup(
        client.get(f"/detail?{CLOSE_PASS}&id=Tr8x8(P2)-ptfe").text, "html.parser"
    )
    used = [dd.text for dd in detail.select("li.check:has(.tag) dl dd") if "%" in dd.text]
    assert used == ["99.8 %"]
    compare = client.get(f"/compare?{CLOSE_PASS}&ids=Tr8x8(P2)-ptfe,R10-02.5T2-RSIT").text
    assert "99.8 %" in compare and ">100 %" not in compare
    report = client.get(f"/report?{CLOSE_FAIL}&id=Tr24x10(P5)-ptfe").text
    assert "at 100.05 % of its limit" in report


#: Tr12x3-ptfe runs this axis at 1/0.9973 of its allowed critical speed: it fails by 0.27 %.
CLOSE_WHIRL = "load=50&speed=74.805&length=900&stroke=600"


def test_a_margin_just_below_1_reads_below_1_and_its_excess_is_not_0_percent(
    client: TestClient,
) -> None:
    """A critical-speed margin of 0.9973 (a fail) read "1.00×" on the compare page, whose
    help says above 1× passes, and the verdict beside it "(0 % over)": the margin now keeps
    the decimals that put it below 1 (``wording.times``), and the excess the figure that
    says it is one (``wording.share``)."""
    api = client.get(
        "/api/v1/evaluate?load_n=50&speed_mm_s=74.805&length_mm=900&stroke_mm=600"
        "&catalog_id=Tr12x3-ptfe"
    ).json()["candidate"]
    assert 0.997 < api["critical_speed"]["margin"] < 0.998 and not api["passed"]
    page = BeautifulSoup(
        client.get(f"/compare?{CLOSE_WHIRL}&ids=Tr12x3-ptfe,Tr16x4-ptfe").text, "html.parser"
    )
    margin = page.select_one('tr[data-row="critical_speed.margin"] td').text
    assert margin == "0.997×"
    verdict = page.select_one('tr[data-row="verdict"] td').text
    assert "at 100.27 % (0.3 % over)" in verdict
    assert "(0.3 % over)" in api["verdict"]["text"]


def test_a_speed_just_over_its_limit_does_not_read_equal_to_it(client: TestClient) -> None:
    """Tr12x3-ptfe at 74.6119 mm/s turns 1492.238 rpm against 1492.045 allowed (a fail by
    0.013 %): the detail read "1492 rpm of 1492 allowed"; it keeps the decimal that tells
    them apart (``figures.apart``)."""
    query = "load=50&speed=74.6119&length=900&stroke=600"
    api = client.get(
        "/api/v1/evaluate?load_n=50&speed_mm_s=74.6119&length_mm=900&stroke_mm=600"
        "&catalog_id=Tr12x3-ptfe"
    ).json()["candidate"]
    assert api["rpm"] > api["critical_speed"]["allowed_rpm"] and not api["passed"]
    page = BeautifulSoup(client.get(f"/detail?{query}&id=Tr12x3-ptfe").text, "html.parser")
    line = next(
        dd.text
        for dt in page.select("dt")
        if dt.text == "Critical speed"
        for dd in [dt.find_next("dd")]
    )
    assert line.startswith("1492.2 rpm of 1492.0 allowed")
