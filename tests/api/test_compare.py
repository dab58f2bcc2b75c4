"""Side-by-side compare: GET /api/v1/compare and the /compare page, with the verdicts."""

from urllib.parse import parse_qsl

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

AXIS = {"load_n": 100, "speed_mm_s": 50, "length_mm": 300}
PAGE_AXIS = "load=100&speed=50&length=300"


def _passing_ids(client: TestClient, n: int) -> list[str]:
    found = client.get("/api/v1/select", params=AXIS).json()["candidates"]
    return [c["id"] for c in found[:n]]


def test_compare_returns_each_candidate_as_evaluate_gives_it(client: TestClient) -> None:
    ids = _passing_ids(client, 3)
    body = client.get("/api/v1/compare", params={**AXIS, "ids": ",".join(ids)}).json()
    assert [c["id"] for c in body["candidates"]] == ids
    for c in body["candidates"]:
        one = client.post(
            "/api/v1/evaluate",
            json={"application": AXIS, "screw": {"catalog_id": c["id"]}},
        ).json()["candidate"]
        assert c == one  # the same full record, verdict included
        assert c["verdict"]["governs"] == c["governing_check"]
        assert c["verdict"]["margin"] == pytest.approx(1 - c["verdict"]["utilization"])
    assert body["share_url"].startswith("/compare?")


def test_repeated_ids_work_like_a_comma_list(client: TestClient) -> None:
    ids = _passing_ids(client, 2)
    a = client.get("/api/v1/compare", params={**AXIS, "ids": ",".join(ids)}).json()
    b = client.get("/api/v1/compare", params=[*AXIS.items(), *(("ids", i) for i in ids)]).json()
    assert a == b


@pytest.mark.parametrize(
    ("ids", "words"),
    [
        ("", "at least 2"),
        ("ONE", "at least 2"),
        ("a,b,c,d,e", "at most 4"),
        ("Tr12x3-bronze,no-such-screw", "no catalog screw 'no-such-screw'"),
    ],
)
def test_bad_ids_are_a_field_error(client: TestClient, ids: str, words: str) -> None:
    if ids == "ONE":
        ids = _passing_ids(client, 1)[0]
    r = client.get("/api/v1/compare", params={**AXIS, "ids": ids})
    assert r.status_code == 422
    (error,) = r.json()["detail"]
    assert error["field"] == "ids" and words in error["message"]
    page = client.get(f"/compare?{PAGE_AXIS}&ids={ids}")
    assert page.status_code == 422
    assert words in BeautifulSoup(page.text, "html.parser").select_one("#e-ids").text


def test_bad_inputs_are_still_a_field_error(client: TestClient) -> None:
    r = client.get("/api/v1/compare", params={**AXIS, "load_n": -1, "ids": "a,b"})
    assert r.status_code == 422
    assert any("load_n" in e["field"] for e in r.json()["detail"])


def test_the_compare_page_marks_the_best_of_each_row(client: TestClient) -> None:
    ids = _passing_ids(client, 3)
    api = client.get("/api/v1/compare", params={**AXIS, "ids": ",".join(ids)}).json()
    share = api["share_url"]
    page = BeautifulSoup(client.get(share).text, "html.parser")
    table = page.select_one("table.compare")
    assert [th.text for th in table.select("thead th.cid")] == ids
    cs = api["candidates"]
    rows = {tr["data-row"]: tr.select("td") for tr in table.select("tbody tr")}
    # verdict row: each candidate's verdict text
    assert [td.text.strip() for td in rows["verdict"]] == [c["verdict"]["text"] for c in cs]
    # lowest running torque is marked best (ties all marked)
    torques = [c["torque"]["total_nm"] for c in cs]
    best = {i for i, t in enumerate(torques) if t == min(torques)}
    if len(best) < len(cs):
        assert {
            i for i, td in enumerate(rows["torque.total_nm"]) if "best" in td.get("class", [])
        } == best
    # highest efficiency marked best
    eff = [c["efficiency"] for c in cs]
    top = {i for i, e in enumerate(eff) if e == max(eff)}
    if len(top) < len(cs):
        assert {
            i for i, td in enumerate(rows["efficiency"]) if "best" in td.get("class", [])
        } == top
    # each check's utilisation has a row
    for name in cs[0]["utilization"]:
        if cs[0]["utilization"][name] is not None:
            assert name in rows


def test_the_results_table_offers_a_compare_form_with_the_same_inputs(client: TestClient) -> None:
    page = BeautifulSoup(client.get(f"/?{PAGE_AXIS}").text, "html.parser")
    form = page.select_one("form#compare-form")
    assert form["action"] == "/compare" and form["method"] == "get"
    hidden = {i["name"]: i["value"] for i in form.select("input[type=hidden]")}
    share = page.select_one("a.share-link")["href"]
    assert hidden == dict(parse_qsl(share.split("?", 1)[1]))
    boxes = page.select("input[type=checkbox][name=ids][form=compare-form]")
    rows = page.select("table.candidates tbody.candidate")
    assert [b["value"] for b in boxes] == [r["data-id"] for r in rows]
    # each row shows its verdict line, as the API's verdict says it (the sentence is in
    # the full form; the compact one gives its parts)
    api = client.get("/api/v1/select", params={**AXIS, "detail": "full"}).json()["candidates"]
    lines = [p.text for p in page.select("table.candidates p.verdict-line")]
    assert lines == [c["verdict"]["text"] for c in api]
