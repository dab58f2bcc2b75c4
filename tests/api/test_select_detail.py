"""The select response's two forms: compact by default, everything with ``detail=full``."""

from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.contract.schemas import VIEWS
from app.report.formulas import FORMULAS

AXIS = {"load_n": 100, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10}
NOTHING_PASSES = {"load_n": 5000, "speed_mm_s": 800, "length_mm": 2000}
#: The fields of the select response before the compact form existed.
FULL_FIELDS = {
    "inputs",
    "candidates",
    "rejected",
    "counts",
    "summary",
    "catalog_version",
    "share_url",
    "api_url",
    "formulas",
}


def _cut(full: Any, view: Any) -> Any:
    """A full candidate's JSON cut to a view (field -> True, or a nested model's view)."""
    if full is None:
        return None
    return {k: full[k] if part is True else _cut(full[k], part) for k, part in view.items()}


def _select(client: TestClient, **params: Any) -> Any:
    response = client.get("/api/v1/select", params=params)
    assert response.status_code == 200, response.text
    return response.json()


@pytest.mark.parametrize("axis", [AXIS, NOTHING_PASSES], ids=["passing", "nothing-passes"])
def test_full_form_keeps_every_field(client: TestClient, axis: dict[str, Any]) -> None:
    full = _select(client, **axis, detail="full")
    assert set(full) == FULL_FIELDS
    assert full["formulas"].keys() == FORMULAS.keys()
    for candidate in full["candidates"] + full["rejected"]:
        assert {"checks", "provenance", "torque", "buckling", "fix"} <= set(candidate)


@pytest.mark.parametrize("axis", [AXIS, NOTHING_PASSES], ids=["passing", "nothing-passes"])
def test_compact_form_agrees_with_the_full_one(client: TestClient, axis: dict[str, Any]) -> None:
    compact, full = _select(client, **axis), _select(client, **axis, detail="full")
    assert compact["detail"] == "summary"
    for key in ("inputs", "counts", "summary", "catalog_version", "share_url"):
        assert compact[key] == full[key], key
    assert [c["id"] for c in compact["candidates"]] == [c["id"] for c in full["candidates"]]
    for small, big in zip(compact["candidates"], full["candidates"], strict=True):
        assert small == _cut(big, VIEWS["summary"])
        assert small["torque"]["total_nm"] == big["torque"]["total_nm"]
        assert small["utilization"] == {c["name"]: c["utilization"] for c in big["checks"]}
        assert (small["robust"], small["hinges_on"]) == (big["robust"], big["hinges_on"])


@pytest.mark.parametrize("axis", [AXIS, NOTHING_PASSES], ids=["passing", "nothing-passes"])
def test_compact_rejected_carry_failed_checks_utilisation_and_fix(
    client: TestClient, axis: dict[str, Any]
) -> None:
    compact, full = _select(client, **axis), _select(client, **axis, detail="full")
    assert compact["rejected"], "the axis has rejected candidates"
    assert set(compact["rejected"][0]) == {"id", "governing_check", "failed", "fix"}
    for small, big in zip(compact["rejected"], full["rejected"], strict=True):
        assert small == _cut(big, VIEWS["rejected"])
        assert small["id"] == big["id"]
        assert small["governing_check"] == big["governing_check"]
        failed = [c for c in big["checks"] if not c["passed"]]
        assert small["failed"] == [
            {k: c[k] for k in ("name", "kind", "utilization", "fix")} for c in failed
        ]
        assert small["fix"] == big["fix"]


def test_post_takes_detail_as_a_query_parameter(client: TestClient) -> None:
    compact = client.post("/api/v1/select", json=AXIS).json()
    full = client.post("/api/v1/select", params={"detail": "full"}, json=AXIS).json()
    assert compact["detail"] == "summary" and "formulas" not in compact
    assert full["formulas"].keys() == FORMULAS.keys()


def test_formulas_have_an_endpoint_of_their_own(client: TestClient) -> None:
    compact = _select(client, **AXIS)
    formulas = client.get(compact["formulas_url"]).json()["formulas"]
    assert formulas == _select(client, **AXIS, detail="full")["formulas"]


def test_openapi_documents_both_forms(client: TestClient) -> None:
    schema = client.get("/openapi.json").json()
    ok = schema["paths"]["/api/v1/select"]["get"]["responses"]["200"]
    refs = {
        s["$ref"].rsplit("/", 1)[1] for s in ok["content"]["application/json"]["schema"]["anyOf"]
    }
    assert refs == {"SelectOut", "SelectSummaryOut"}
    detail = [
        p for p in schema["paths"]["/api/v1/select"]["get"]["parameters"] if p["name"] == "detail"
    ]
    assert detail and "full" in str(detail[0]["schema"])


def test_an_unknown_detail_is_refused(client: TestClient) -> None:
    response = client.get("/api/v1/select", params={**AXIS, "detail": "everything"})
    assert response.status_code == 422
    assert response.json()["detail"][0]["field"] == "detail"
