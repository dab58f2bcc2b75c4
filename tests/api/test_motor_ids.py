"""A library motor's id in any case and with spaces around it: read once, in the input
model, as the library writes it (lowercase), so the API, the page and the share link
carry one id; a library file writing an id in capitals is refused at load."""

from pathlib import Path
from urllib.parse import parse_qs, urlsplit

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.catalog.errors import CatalogError
from app.catalog.motors import load_motors
from tests.api.test_motor_library import LIBRARY

#: A light horizontal axis; the motor as its datasheet writes it.
AXIS = {"load_n": 20.0, "speed_mm_s": 50.0, "length_mm": 350.0, "limit": 3}
PAGE_AXIS = {"load": "20", "speed": "50", "length": "350"}
TYPED = ["17HS19-2004S1", " 17hs19-2004S1  ", "17Hs19-2004s1"]


@pytest.mark.parametrize("typed", TYPED, ids=["datasheet", "spaces", "mixed"])
def test_the_api_reads_any_case(client: TestClient, typed: str) -> None:
    r = client.get("/api/v1/select", params={**AXIS, "motor": typed})
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["inputs"]["motor"] == "17hs19-2004s1"
    assert parse_qs(urlsplit(body["share_url"]).query)["motor"] == ["17hs19-2004s1"]
    posted = client.post("/api/v1/select", json={**AXIS, "motor": typed})
    assert posted.status_code == 200
    assert posted.json()["inputs"]["motor"] == "17hs19-2004s1"
    # the same screws as with the library's own spelling
    own = client.get("/api/v1/select", params={**AXIS, "motor": "17hs19-2004s1"}).json()
    assert [c["id"] for c in body["candidates"]] == [c["id"] for c in own["candidates"]]


def test_none_and_any_read_in_any_case(client: TestClient) -> None:
    for typed, held in (("NONE", None), (" Any ", "any")):
        r = client.post("/api/v1/select", json={**AXIS, "motor": typed})
        assert r.status_code == 200, r.text
        # the compact select echoes the inputs that differ from their defaults (none: absent)
        assert r.json()["inputs"].get("motor") == held


def test_an_unknown_motor_is_still_refused(client: TestClient) -> None:
    r = client.get("/api/v1/select", params={**AXIS, "motor": "17HS19-9999"})
    assert r.status_code == 422
    assert r.json()["detail"][0]["field"] == "motor"


def test_the_page_reads_any_case_and_shares_the_library_id(client: TestClient) -> None:
    r = client.get("/", params={**PAGE_AXIS, "motor": " 17HS19-2004S1 "})
    assert r.status_code == 200
    soup = BeautifulSoup(r.text, "html.parser")
    assert soup.select_one("#results") is not None
    links = [a["href"] for a in soup.select("a.share-link")]
    assert links
    for link in links:
        assert parse_qs(urlsplit(str(link)).query)["motor"] == ["17hs19-2004s1"]


def test_a_library_id_in_capitals_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "motors.toml"
    assert "[motors.m1]" in LIBRARY
    path.write_text(LIBRARY.replace("[motors.m1]", "[motors.M1]"))
    with pytest.raises(CatalogError) as caught:
        load_motors(path)
    assert "motors.M1" in str(caught.value) and "lowercase" in str(caught.value)
