"""Schema fuzzing: schemathesis generates requests from the app's own OpenAPI schema.

In-process over ASGI (no server). Valid and invalid requests (both generation modes, and
schemathesis' examples, boundary-value coverage and fuzzing phases) for every operation;
each response must not be a 5xx, must have a documented status code, the documented
content type and the documented body schema, and a request the schema forbids must get a
4xx. Deterministic (``derandomize``, no example database), so CI sees the same cases on
every run. A wrong value of one parameter that the coverage phase offers again beside
another optional parameter is sent once (``_sent_before``): about 8,400 requests in all,
where the phase offers about 14,700.

One test function per operation (``test_api_conforms_to_its_schema_get_api_v1_select``),
each parametrized over the schema filtered to that operation, so each runs schemathesis'
phases for it under a node id of its own and pytest-xdist schedules and reports each. (One
``schema.parametrize()`` over the whole schema gives every operation's item the same node
id under pytest 9, and xdist then runs one of them.) The module's ``xdist_group`` mark
keeps it on one worker (``--dist loadgroup``), where the count of generated requests is
summed.

The schema reaches the tests through a fixture (``schemathesis.pytest.from_fixture``), so
each operation's cases are built when its test runs, on the one worker that runs it.
Parametrized over the schema itself, they were built while collecting, by every xdist
worker, every run: the coverage phase's 14,000 cases took about 11 s of CPU each time.

``test_fuzz_regressions`` replays requests an earlier run found answered with a 500 or a
200 where the schema forbids them (vanishing numbers, a thread too steep to drive at its
friction, a boolean given as a number); they are refused with a 4xx now.
"""

import re
from typing import Any

import pytest
import schemathesis
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, settings
from schemathesis.checks import (
    content_type_conformance,
    negative_data_rejection,
    not_a_server_error,
    response_schema_conformance,
    status_code_conformance,
)
from schemathesis.core.parameters import ParameterLocation
from schemathesis.generation import GenerationMode
from schemathesis.generation.meta import TestPhase
from schemathesis.python import asgi

from app.main import create_app
from tests.asgi_session import InThreadASGI

#: At least this many generated requests over all operations (issue 4: 300).
MIN_TOTAL_CASES = 300
#: Examples of the fuzzing phase per operation (both modes); operations without parameters
#: stop after one. The coverage phase (boundary values and wrong types of every parameter,
#: about 2,200 requests for a GET of the application's fields) does not depend on it and
#: makes most of the requests; 100 here gave 15,372 in all, 25 gives about 14,700, and
#: takes the fuzzing phase of POST /select and GET /pairs from 16.5 to 9 s of CPU.
EXAMPLES_PER_OPERATION = 25
CHECKS = [
    not_a_server_error,
    status_code_conformance,
    content_type_conformance,
    response_schema_conformance,
    negative_data_rejection,
]

app = create_app()
schema = schemathesis.openapi.from_asgi("/openapi.json", app)
schema.config.generation.update(modes=[GenerationMode.POSITIVE, GenerationMode.NEGATIVE])
#: A query with too many parameters is refused for its size (414) before any field is read:
#: a rejection like the 422 of a bad field.
rejection = schema.config.checks.negative_data_rejection
rejection.expected_statuses = [*rejection.expected_statuses, "414"]
OPERATIONS = sorted(
    f"{method.upper()} {path}"
    for path, methods in schema.raw_schema["paths"].items()
    for method in methods
)
#: One client for every request: the transport otherwise builds a requests session per
#: request, which then reads the environment (proxies, ~/.netrc) for each; an in-process
#: app has no proxy or credentials to find (``trust_env`` off). Its requests are answered
#: in this thread (``InThreadASGI``), not on an event loop in another.
CLIENT = asgi.get_client(app)
CLIENT.trust_env = False
for _scheme in ("http://", "https://"):
    CLIENT.mount(_scheme, InThreadASGI(app))
cases_run: dict[str, int] = {}
pytestmark = pytest.mark.xdist_group("schemathesis")
FUZZ_TEST = "test_api_conforms_to_its_schema"
SCHEMA = schemathesis.pytest.from_fixture("api_schema")


@pytest.fixture(scope="module")
def api_schema() -> Any:
    """The schema (the app has no lifespan to start: ``create_app`` loads what it needs)."""
    return schema


@pytest.fixture(autouse=True)
def _node_id(request: pytest.FixtureRequest) -> None:
    """schemathesis 4.32's tests over a fixture's schema read and set ``_nodeid`` (its
    reports name the operation), which pytest 9.2's nodes no longer have."""
    request.node._nodeid = request.node.nodeid


def _fuzz_test(operation: str) -> Any:
    """The fuzz test of one documented operation ("METHOD /path"), as its own function."""
    method, path = operation.split(" ", 1)

    @settings(
        max_examples=EXAMPLES_PER_OPERATION,
        derandomize=True,
        database=None,
        deadline=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
    )
    def test(case: Any) -> None:
        if _sent_before(case):
            return
        # its cases include probes with undocumented methods: counted for the documented one
        cases_run[operation] = cases_run.get(operation, 0) + 1
        case.call_and_validate(session=CLIENT, checks=CHECKS)

    test.__name__ = test.__qualname__ = _fuzz_test_name(operation)
    return SCHEMA.include(method=method, path=path).parametrize()(test)


#: what each negative coverage case already sent tested: (method, path, the scenario's
#: description, the parameter's place and name, its wrong value)
SENT: set[tuple[str, ...]] = set()


def _sent_before(case: Any) -> bool:
    """Whether ``case`` is a negative coverage case whose one wrong parameter value was
    already sent, the same way, to the same operation.

    The coverage phase sends each wrong value of a parameter (too small, too large, of the
    wrong type) beside the required parameters alone, then again beside each optional one:
    ``length_mm=AAA`` reached GET /api/v1/select 57 times, about half its 2,200 requests.
    The app refuses a field's wrong value on that field whatever else is sent, so each is
    sent once. Cases that name no parameter, positive cases and the other phases are all
    sent."""
    meta = case.meta
    if meta is None or meta.phase.name != TestPhase.COVERAGE:
        return False
    data = meta.phase.data
    if meta.generation.mode != GenerationMode.NEGATIVE or data.parameter is None:
        return False
    place = data.parameter_location
    container = {
        ParameterLocation.QUERY: case.query,
        ParameterLocation.PATH: case.path_parameters,
        ParameterLocation.HEADER: case.headers,
        ParameterLocation.COOKIE: case.cookies,
    }.get(place, case.body)
    value = container.get(data.parameter) if isinstance(container, dict) else container
    key = (case.method, case.path, data.description, str(place), data.parameter, repr(value))
    if key in SENT:
        return True
    SENT.add(key)
    return False


def _fuzz_test_name(operation: str) -> str:
    return f"{FUZZ_TEST}_{re.sub(r'[^a-z0-9]+', '_', operation.lower()).strip('_')}"


for _operation in OPERATIONS:
    globals()[_fuzz_test_name(_operation)] = _fuzz_test(_operation)


def test_enough_cases_were_generated(request: pytest.FixtureRequest) -> None:
    """Runs after the fuzz test in this module, in the same process (its ``xdist_group``).

    Skipped when the fuzz test was not selected for every operation; fails when it was but
    ran elsewhere (another xdist worker), since the count would then prove nothing."""
    names = {_fuzz_test_name(operation): operation for operation in OPERATIONS}
    collected = (getattr(item, "originalname", None) for item in request.session.items)
    selected = {names[name] for name in collected if name in names}
    if selected != set(OPERATIONS):
        pytest.skip("the fuzz test was not selected for every operation")
    assert set(cases_run) == set(OPERATIONS), (
        "the fuzz test ran for these operations in another process; run this module on one"
        f" worker (its xdist_group mark): {sorted(set(OPERATIONS) - set(cases_run))}"
    )
    total = sum(cases_run.values())
    print(f"\nschemathesis requests per operation: {cases_run}, total {total}")
    assert total >= MIN_TOTAL_CASES, cases_run


TINY = 5e-324
TINY_APPLICATION = {
    "load_n": TINY,
    "speed_mm_s": TINY,
    "length_mm": TINY,
    "lead_mm": TINY,
    "stroke_mm": TINY,
    "cycles_per_day": TINY,
    "max_torque_nm": TINY,
    "required_life_years": TINY,
    "positioning_tolerance_mm": TINY,
}
TINY_SCREW = {
    "outer_diameter_mm": 999.0,
    "root_diameter_mm": TINY,
    "lead_mm": TINY,
    "friction_dynamic": TINY,
    "friction_static": TINY,
    "inertia_kg_m2_per_m": TINY,
    "pv_limit_mpa_m_s": TINY,
}
EVALUATE = "/api/v1/evaluate"


@pytest.mark.parametrize(
    ("method", "path", "kwargs"),
    [
        pytest.param(
            "POST", "/api/v1/select", {"json": TINY_APPLICATION},
            id="tiny-post-select",
        ),
        pytest.param(
            "GET", "/api/v1/select", {"params": TINY_APPLICATION},
            id="tiny-get-select",
        ),
        pytest.param(
            "POST", EVALUATE, {"json": {"application": TINY_APPLICATION, "screw": TINY_SCREW}},
            id="tiny-evaluate-custom",
        ),
        pytest.param(
            "POST", EVALUATE,
            {"json": {
                "application": {"length_mm": 1.0, "load_n": 1.0, "speed_mm_s": 1.0,
                                "ambient_c": 0.0},
                "screw": {"friction_dynamic": 1.0, "friction_static": 1.0, "lead_mm": 5.0,
                          "outer_diameter_mm": 2.0, "root_diameter_mm": 1.0},
            }},
            id="steep-lead-evaluate",
        ),
        pytest.param(
            "POST", "/api/v1/select",
            {"json": {"coating": "none", "load_n": 315963.171200751, "lead_mm": None,
                      "required_life_years": None, "speed_mm_s": 29550.73781430684,
                      "limit": 100, "vacuum": True, "length_mm": 2.5, "stroke_mm": True,
                      "critical_speed_safety_factor": 1.0}},
            id="bool-as-number-select",
        ),
    ],
)  # fmt: skip
def test_fuzz_regressions(method: str, path: str, kwargs: dict[str, Any]) -> None:
    """Requests schemathesis reported (the vanishing ones minus fields at their defaults;
    the other two from a 600-examples-per-operation run): each is refused with a 422."""
    with TestClient(app, raise_server_exceptions=False) as client:
        response = client.request(method, path, **kwargs)
    assert response.status_code == 422, response.text
