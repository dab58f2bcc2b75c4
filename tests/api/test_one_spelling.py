"""One spelling of "utilization" in everything that leaves the app: the JSON's field
names, the OpenAPI schema, the CSV's headers and the pages' text (the page's checks table
says "Utilization", the CSV "utilization.<check>", the JSON ``utilization``)."""

import re

import pytest
from fastapi.testclient import TestClient

#: Both spellings and their forms (utilisation, Utilization, utilized ...).
EITHER = re.compile(r"utili[sz]", re.IGNORECASE)
OTHER = re.compile(r"utilis", re.IGNORECASE)
AXIS = "load=200&speed=50&length=300&accel=500&stroke=200&cycles_per_day=100"
API_AXIS = "load_n=200&speed_mm_s=50&length_mm=300&accel_mm_s2=500&stroke_mm=200"
OUTPUTS = [
    f"/report?{AXIS}",
    f"/detail?{AXIS}&id=Tr12x3-bronze",
    f"/compare?{AXIS}&ids=Tr12x3-bronze,Tr16x4-bronze",
    f"/export.csv?{AXIS}",
    "/guide",
    "/openapi.json",
    "/api/v1/formulas",
    f"/api/v1/select?{API_AXIS}&detail=full",
    f"/api/v1/select?{API_AXIS}",
    f"/api/v1/compare?{API_AXIS}&ids=Tr12x3-bronze,Tr16x4-bronze",
]


@pytest.mark.parametrize("url", OUTPUTS, ids=[u.split("?")[0] for u in OUTPUTS])
def test_one_spelling_leaves_the_app(client: TestClient, url: str) -> None:
    r = client.get(url)
    assert r.status_code == 200, r.text[:300]
    assert EITHER.search(r.text)  # the word is there to be spelled
    assert not OTHER.search(r.text), OTHER.findall(r.text)
