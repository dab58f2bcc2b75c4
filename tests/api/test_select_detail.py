"""The select response's two forms: compact by default, everything with ``detail=full``."""

import re
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.contract.inputs import ApplicationIn
from app.contract.outputs import SelectOut
from app.contract.schemas import VIEWS
from app.report.formulas import FORMULAS
from tests.compact_form import RELATIVE, assert_compact_of

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


def _select(client: TestClient, **params: Any) -> Any:
    response = client.get("/api/v1/select", params=params)
    assert response.status_code == 200, response.text
    return response.json()


@pytest.mark.parametrize("axis", [AXIS, NOTHING_PASSES], ids=["passing", "nothing-passes"])
def test_full_form_keeps_every_field(client: TestClient, axis: dict[str, Any]) -> None:
    full = _select(client, **axis, detail="full")
    assert set(full) == set(SelectOut.model_fields) >= FULL_FIELDS
    assert full["formulas"].keys() == FORMULAS.keys()
    for candidate in full["candidates"] + full["rejected"]:
        assert {"checks", "provenance", "torque", "buckling", "fix"} <= set(candidate)


@pytest.mark.parametrize("axis", [AXIS, NOTHING_PASSES], ids=["passing", "nothing-passes"])
def test_compact_form_agrees_with_the_full_one(client: TestClient, axis: dict[str, Any]) -> None:
    compact, full = _select(client, **axis), _select(client, **axis, detail="full")
    assert compact["detail"] == "summary"
    for key in ("counts", "summary", "catalog_version", "motor_curve_origin", "share_url"):
        assert compact[key] == full[key], key
    assert [c["id"] for c in compact["candidates"]] == [c["id"] for c in full["candidates"]]
    for small, big in zip(compact["candidates"], full["candidates"], strict=True):
        # the compact form: numbers to 6 significant figures, nulls left out
        assert_compact_of(small, big, VIEWS["summary"], big["id"])
        assert small["torque"]["total_nm"] == pytest.approx(big["torque"]["total_nm"], rel=RELATIVE)
        by_check = {c["name"]: c["utilization"] for c in big["checks"]}
        assert_compact_of(small["utilization"], by_check, True, big["id"])
        assert (small.get("robust"), small["hinges_on"]) == (big["robust"], big["hinges_on"])


@pytest.mark.parametrize("axis", [AXIS, NOTHING_PASSES], ids=["passing", "nothing-passes"])
def test_compact_inputs_are_those_off_their_defaults(
    client: TestClient, axis: dict[str, Any]
) -> None:
    """The compact form echoes the inputs that differ from their defaults (the compact
    select's bytes: the full echo was 1.3 kB of 20 kB); the defaults fill in the rest, as
    the full form echoes them."""
    compact, full = _select(client, **axis), _select(client, **axis, detail="full")
    assert compact["inputs"] == {k: v for k, v in axis.items()}
    assert (
        ApplicationIn.model_validate(compact["inputs"]).model_dump(mode="json") == (full["inputs"])
    )


def test_compact_verdict_names_each_value_once_and_keeps_what_the_full_one_says(
    client: TestClient,
) -> None:
    """The compact verdict drops what the candidate already gives or the response names
    once (the compact select's bytes: the verdict was 630 of a candidate's 1,450): the
    governing check and its utilisation are the candidate's, the margin is 1 - that, the
    check's label is at /api/v1/checks, a value's label in ``labels``, whether the pass
    hinges on a value is whether ``hinges_on`` names it."""
    compact, full = _select(client, **AXIS), _select(client, **AXIS, detail="full")
    labels = {c["name"]: c["label"] for c in client.get("/api/v1/checks").json()["checks"]}
    assert compact["candidates"], "the axis has passing candidates"
    for small, big in zip(compact["candidates"], full["candidates"], strict=True):
        verdict = big["verdict"]
        assert verdict["governs"] == small["governing_check"]
        assert verdict["governs_label"] == labels[small["governing_check"]]
        governing = small["utilization"][small["governing_check"]]
        assert governing == pytest.approx(verdict["utilization"], rel=RELATIVE)
        assert verdict["margin"] == pytest.approx(1.0 - verdict["utilization"])
        assert [
            {
                "field": r["field"],
                "label": compact["labels"][r["field"]],
                "kind": r["kind"],
                "hinges": r["field"] in small["hinges_on"],
            }
            for r in small["verdict"]["rests_on"]
        ] == verdict["rests_on"]
        assert small["verdict"]["watch"] == verdict["watch"]


@pytest.mark.parametrize("axis", [AXIS, NOTHING_PASSES], ids=["passing", "nothing-passes"])
def test_compact_rejected_carry_failed_checks_utilisation_and_fix(
    client: TestClient, axis: dict[str, Any]
) -> None:
    compact, full = _select(client, **axis), _select(client, **axis, detail="full")
    assert compact["rejected"], "the axis has rejected candidates"
    # no candidate-level fix: it is the failed checks' fixes joined (each given once)
    assert set(compact["rejected"][0]) == {"id", "governing_check", "failed"}
    for small, big in zip(compact["rejected"], full["rejected"], strict=True):
        # the compact form: numbers to 6 significant figures, nulls left out
        assert_compact_of(small, big, VIEWS["rejected"], big["id"])
        assert small["id"] == big["id"]
        assert small.get("governing_check") == big["governing_check"]
        failed = [c for c in big["checks"] if not c["passed"]]
        assert_compact_of(
            small["failed"],
            [{k: c[k] for k in ("name", "kind", "utilization", "fix")} for c in failed],
            True,
            big["id"],
        )
        assert " ".join(c["fix"] for c in small["failed"] if c.get("fix")) == big["fix"]


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


def test_the_compact_select_of_the_default_request_stays_small(client: TestClient) -> None:
    """The bytes of the default request's compact select (before gzip): 20.5 kB before
    the inputs' defaults, the verdict's repeats and the rejected's joined fix were dropped,
    13.6 kB after, 11.6 kB since its numbers have 6 significant figures and its nulls are
    left out: within issue 30's 12 kB (bench/web.py prints it beside that target)."""
    response = client.get("/api/v1/select", params=AXIS, headers={"Accept-Encoding": "identity"})
    assert response.status_code == 200
    assert response.json()["candidates"] and response.json()["rejected"]
    assert len(response.content) <= 12_000


def test_a_change_admits_its_screw_at_the_limit_and_a_remedy_past_it(
    client: TestClient,
) -> None:
    """400 N at 50 mm/s on the seed's B family, lead 10 mm: nothing passes. Each of the
    summary's ``changes`` admits the screw it names with its governing check at its limit
    exactly (utilisation 1, as the description says: no margin), while the first remedy
    keeps its 5 % margin (at most 1 / 1.05)."""
    axis = {**AXIS, "load_n": 400, "family": "B", "limit": 100}
    summary = client.get("/api/v1/select", params=axis).json()["summary"]
    assert summary["changes"] and summary["remedies"]
    for change in summary["changes"]:
        changed = {**axis, **{k: repr(v) for k, v in change["inputs"].items()}}
        passing = client.get("/api/v1/select", params=changed).json()["candidates"]
        (admitted,) = [c for c in passing if c["id"] == change["admits"]]
        assert admitted["utilization"][admitted["governing_check"]] == pytest.approx(1.0)
    remedy = summary["remedies"][0]
    assert remedy["utilization"] <= 1 / 1.05 + 1e-9


def test_no_change_or_remedy_breaks_the_cycles_a_day_take(client: TestClient) -> None:
    """20 kN on a 2.5 m vertical screw, a 150 mm stroke 5,000 times a day: nothing passes.
    A slower move admits the seed's fine leads, but at 15.9 mm/s one cycle takes 18.9 s
    and 5,000 of them more than a day: the inputs refuse it (422 on cycles_per_day), so
    no change or remedy may offer it. Each one offered is an application the API accepts,
    and a remedy's passes as it says."""
    axis = {"load_n": 20000, "speed_mm_s": 1500, "length_mm": 2500, "orientation": "vertical"}
    axis |= {"stroke_mm": 150, "cycles_per_day": 5000}
    summary = client.get("/api/v1/select", params=axis).json()["summary"]
    assert summary["changes"] and summary["remedies"]
    for offered in summary["changes"] + summary["remedies"]:
        changed = {**axis, **{k: repr(v) for k, v in offered["inputs"].items()}}
        response = client.get("/api/v1/select", params={**changed, "limit": 100})
        assert response.status_code == 200, (offered, response.text)
        if "passing" in offered:
            assert response.json()["counts"]["passed"] == offered["passing"]


def test_the_nearest_screws_change_is_offered_only_where_the_inputs_accept_it(
    client: TestClient,
) -> None:
    """TR-C45 at 200 N and 300 mm/s, a 300 mm stroke 30,000 times a day (a 2.6 s cycle:
    at most 33,231): the nearest nut slides too fast at any speed that still fits 30,000
    cycles in a day. Its change (55.3 mm/s, an 11.0 s cycle) is not offered: the summary
    says no speed within the accepted inputs admits it."""
    axis = {"load_n": 200, "speed_mm_s": 300, "length_mm": 500, "stroke_mm": 300}
    axis |= {"accel_mm_s2": 1000, "cycles_per_day": 30000, "family": "TR-C45"}
    summary = client.get("/api/v1/select", params=axis).json()["summary"]
    assert summary["input_change"] == {}
    assert "No linear speed within the accepted inputs admits it." in summary["message"]
    refused = client.get("/api/v1/select", params={**axis, "speed_mm_s": 55.27})
    assert refused.status_code == 422
    assert refused.json()["detail"][0]["field"] == "cycles_per_day"


#: A speed a fix names as a most (the nut's sliding speed, PV, the traverse table).
FIX_SPEED = re.compile(r"(?:Move|Run|speed may be) at most ([\d.,]+) mm/s")


@pytest.mark.parametrize("speed_mm_s", [270, 300])
def test_a_fix_says_where_the_speed_it_names_is_one_the_inputs_refuse(
    client: TestClient, speed_mm_s: int
) -> None:
    """80 N (270 mm/s: the B and ZBX leadscrews) or 200 N (300 mm/s: TR-C45) over a 300 mm
    stroke 30,000 times a day: a cycle may take at most 2.88 s. The nearest screws' fixes
    name slower speeds (PV's 235.2 mm/s for B12000-L30, a 3.02 s cycle); a fix that names
    one the API then refuses says so, and one that does not say so names a speed the API
    accepts."""
    axis: dict[str, Any] = {"speed_mm_s": speed_mm_s, "length_mm": 500, "stroke_mm": 300}
    axis |= {"cycles_per_day": 30000, "limit": 10}
    if speed_mm_s == 270:
        axis |= {"load_n": 80, "family": ["B", "ZBX"]}
    else:
        axis |= {"load_n": 200, "accel_mm_s2": 1000, "family": "TR-C45"}
    rejected = client.get("/api/v1/select", params=axis).json()["rejected"]
    seen = {True: 0, False: 0}
    for failed in (f for r in rejected for f in r["failed"]):
        for named in FIX_SPEED.findall(failed["fix"]):
            said = "The inputs refuse a move that slow" in failed["fix"]
            answer = client.get("/api/v1/select", params={**axis, "speed_mm_s": named})
            assert answer.status_code == (422 if said else 200), failed["fix"]
            seen[said] += 1
    assert seen[True] > 0
    if speed_mm_s == 270:
        assert "a cycle would take 3.022 s, and 30,000 cycles a day leave 2.88 s for each" in next(
            f["fix"] for r in rejected if r["id"] == "B12000-L30" for f in r["failed"]
        )


def test_the_summary_counts_the_limits_and_the_advice_that_ran_apart(client: TestClient) -> None:
    """R12-04B1-RSIT driven by the 17HS19-2004S1 stepper runs 10 limits (the stroke with its
    nut on the screw and the stepper's supply among them) and two pieces of advice (the
    inertia ratio, the ball nut's mean load), and its pass read "Passes the 8 checks that
    ran" over 9 checks."""
    axis = {"load_n": 30, "speed_mm_s": 100, "length_mm": 300, "stroke_mm": 200}
    axis |= {"accel_mm_s2": 2000, "moving_mass_kg": 2, "motor": "17hs19-2004s1"}
    body = {"application": axis, "screw": {"catalog_id": "R12-04B1-RSIT"}}
    c = client.post("/api/v1/evaluate", json=body).json()["candidate"]
    kinds = [k["kind"] for k in c["checks"]]
    assert c["passed"] and kinds.count("limit") == 10 and kinds.count("advice") == 2
    assert c["verdict"]["summary"].startswith("Passes the 10 limits that ran, besides 2 pieces")
