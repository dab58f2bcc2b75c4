"""HEAD on every GET route, the CSV formula guard's edge cases, redirects without Host.

A health check or link checker sends HEAD and must get the GET's status and headers with
no body; a spreadsheet runs `` =...`` and fullwidth ``＝...`` cells as formulas; and a
redirect built from the Host header would send a client wherever that header says.
"""

import pytest
from fastapi.testclient import TestClient

from app.contract.outputs import SelectOut
from app.web.export import results_csv, safe_cell
from tests.web.test_pages import csv_candidates

AXIS = "load=100&speed=50&length=500&lead=10"
SELECT = "/api/v1/select?load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10"
GET_PATHS = [
    "/api/v1/health",
    "/api/v1/series",
    SELECT,
    "/export.csv?" + AXIS,
    "/export.json?" + AXIS,
    "/?" + AXIS,
    "/catalog",
    "/catalog/ZBX8000",
    "/docs",
    "/openapi.json",
    "/static/css/app.css",
]


def _series_and_detail(client: TestClient) -> list[str]:
    candidate = client.get(SELECT).json()["candidates"][0]
    return [f"/api/v1/series/{candidate['series']}", f"/detail?{AXIS}&id={candidate['id']}"]


@pytest.mark.parametrize("encoding", ["identity", "gzip"])
def test_head_answers_every_get_route_with_its_headers_and_no_body(
    client: TestClient, encoding: str
) -> None:
    for path in GET_PATHS + _series_and_detail(client):
        headers = {"Accept-Encoding": encoding}
        got = client.get(path, headers=headers)
        head = client.head(path, headers=headers)
        assert (head.status_code, got.status_code) == (200, 200), path
        assert head.content == b"", path
        for name in ("content-length", "content-type", "content-encoding", "vary"):
            assert head.headers.get(name) == got.headers.get(name), (path, name)
        assert head.headers["x-content-type-options"] == "nosniff"


def test_head_keeps_the_error_of_a_route_without_get(client: TestClient) -> None:
    response = client.head("/api/v1/machine")  # POST only (evaluate has a GET now)
    assert response.status_code == 405 and response.content == b""
    assert response.headers["allow"] == "POST"


@pytest.mark.parametrize(
    ("path", "allow"),
    [
        ("/api/v1/select", "GET, HEAD, POST"),
        ("/api/v1/pairs", "GET, HEAD, POST"),
        ("/api/v1/evaluate", "GET, HEAD, POST"),
        ("/api/v1/machine", "POST"),
        ("/api/v1/health", "GET, HEAD"),
    ],
)
def test_a_405_allows_every_method_of_the_path(client: TestClient, path: str, allow: str) -> None:
    """RFC 9110, 15.5.6: a 405 lists the methods the resource supports; GET and POST on
    /api/v1/select are two routes, and a PUT must name both."""
    response = client.put(path)
    assert response.status_code == 405
    assert response.headers["allow"] == allow


def test_head_of_a_refused_query_has_no_body(client: TestClient) -> None:
    response = client.head("/?" + "&".join(["a=1"] * 5000))
    assert response.status_code == 414 and response.content == b""


@pytest.mark.parametrize(
    "text",
    [
        "=1+1",
        " =1+1",
        "  +1",
        "\u00a0-1",
        "\n@SUM(A1)",
        "\tx",
        "\rx",
        "＝HYPERLINK(1)",
        "＋1",
        "－1",
        "＠SUM(A1)",
        "\u3000＝1",
    ],
)
def test_formula_starts_are_quoted(text: str) -> None:
    assert safe_cell(text) == "'" + text


@pytest.mark.parametrize("value", ["B6000", " 12 mm", "TFE", "", 1.5, -1.5, None])
def test_plain_cells_pass_unchanged(value: object) -> None:
    assert safe_cell(value) == value


def test_a_csv_export_quotes_spaced_and_fullwidth_formulas(client: TestClient) -> None:
    result = client.get(SELECT + "&detail=full").json()
    hostile = {**result["candidates"][0], "id": " =HYPERLINK(1)", "series": "＝SUM(A1)"}
    units = {"force_unit": "N", "length_unit": "mm", "torque_unit": "N_m"}
    typed = SelectOut.model_validate({**result, "candidates": [hostile], "rejected": []})
    text = results_csv(typed, units)
    row = csv_candidates(text)[0]
    assert (row["id"], row["series"]) == ("' =HYPERLINK(1)", "'＝SUM(A1)")


@pytest.mark.parametrize(
    ("path", "location"),
    [
        ("/static", "/static/"),
        ("/docs/", "/docs"),
        ("/api/v1/health/", "/api/v1/health"),
        ("/api/v1/select/?load_n=1", "/api/v1/select?load_n=1"),
    ],
)
def test_redirects_are_path_only_whatever_the_host(
    client: TestClient, path: str, location: str
) -> None:
    for host in ("evil.example", "testserver", "evil.example:8443"):
        response = client.get(path, headers={"Host": host}, follow_redirects=False)
        assert response.status_code in (301, 302, 307, 308), path
        assert response.headers["location"] == location
        assert "evil" not in response.headers["location"]
