"""``app.report.reader``: a view of a candidate read from the core's record, as the model
or as plain JSON values, the two alike and valid for their own models."""

import pytest
from fastapi.testclient import TestClient

from app.catalog import Catalog
from app.contract.outputs import SelectOut
from app.contract.schemas import COMPACT_VIEWS, VIEWS, ApplicationIn, CandidateOut, view_model
from app.contract.source import Writer
from app.contract.units import DEFAULT_UNITS
from app.core.selection import select
from app.report.reader import reader
from app.report.service import INPUT_RANGES
from tests.compact_form import assert_compact_of

#: a move, a duty and a vacuum: profile, segments, life and outgassing on every candidate
AXIS = {"load_n": 20, "speed_mm_s": 100, "length_mm": 500, "stroke_mm": 300, "lead_mm": 10}
AXIS |= {"accel_mm_s2": 1000, "cycles_per_day": 100}


def test_a_full_selection_through_the_api_validates_against_its_own_model(
    client: TestClient,
) -> None:
    """The select response (built without validation at every level) is valid JSON for
    ``SelectOut``: every required field of every nested model is there."""
    query = "load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10&stroke_mm=300&detail=full"
    body = client.get(f"/api/v1/select?{query}&accel_mm_s2=1000&vacuum=true").json()
    out = SelectOut.model_validate(body)
    assert out.candidates and out.candidates[0].segments
    assert isinstance(out.candidates[0], CandidateOut)


@pytest.mark.parametrize("view", sorted(VIEWS))
def test_each_view_reads_alike_as_json_and_as_the_model(catalog: Catalog, view: str) -> None:
    """The dict reader writes what the model reader's model serialises, and that is valid
    for the view's own model (``view_model``): no field missing, none extra. A compact
    view (``COMPACT_VIEWS``) as JSON is the model's in the compact form: numbers to 6
    significant figures, null values left out, and its model says so (a field that can
    be null optional)."""
    app = ApplicationIn.model_validate(AXIS).to_core(catalog.motors, catalog.supports)
    selection = select(app, catalog.index, INPUT_RANGES)
    compact = view in COMPACT_VIEWS
    checked = view_model(CandidateOut, VIEWS[view], view.title(), compact=compact)
    full_precision = view_model(CandidateOut, VIEWS[view], view.title())
    assert selection.candidates
    for c in [*selection.candidates[:5], *selection.rejected[:5]]:
        as_json = reader(CandidateOut, view, as_dict=True)(c, c, Writer(DEFAULT_UNITS))
        model = reader(CandidateOut, view)(c, c, Writer(DEFAULT_UNITS))
        assert set(model.model_fields_set) == set(VIEWS[view]), c.screw.id
        valid = checked.model_validate(as_json).model_dump(mode="json", exclude_unset=compact)
        assert valid == as_json, c.screw.id
        of_model = full_precision.model_validate(model, from_attributes=True)
        dumped = of_model.model_dump(mode="json")
        if compact:
            assert_compact_of(as_json, dumped, VIEWS[view], c.screw.id)
        else:
            assert dumped == as_json, c.screw.id


#: Ball screws beside leadscrews, with a duty: ball nuts' checks do not apply to
#: leadscrews' ratings, and some leadscrews lack a value a check reads.
MIXED = {**AXIS, "family": ["HIWIN-ROLLED", "B"]}


def test_the_compact_view_leaves_the_verdicts_summary_unread_and_it_reads_the_same_later(
    catalog: Catalog,
) -> None:
    """The compact select reads a verdict's parts alone: its summary line and the checks
    that could not run are worked out only when a full view reads them, and then say
    what a record read in full from the start says."""
    app = ApplicationIn.model_validate(MIXED).to_core(catalog.motors, catalog.supports)
    compact_first = select(app, catalog.index, INPUT_RANGES).candidates
    full_first = select(app, catalog.index, INPUT_RANGES).candidates
    assert {c.screw.screw_type for c in compact_first} == {"ball", "lead"}
    for c in compact_first:
        reader(CandidateOut, "summary", as_dict=True)(c, c, Writer(DEFAULT_UNITS))
        assert {"summary", "skipped", "not_applicable"}.isdisjoint(vars(c.verdict))
    read = [
        [reader(CandidateOut, "full", as_dict=True)(c, c, Writer(DEFAULT_UNITS))["verdict"]]
        for c in (*compact_first, *full_first)
    ]
    half = len(compact_first)
    assert read[:half] == read[half:]
    pairs = zip(compact_first, read[:half], strict=True)
    ball = [v for c, [v] in pairs if c.screw.screw_type == "ball"]
    assert all(v["not_applicable"] for v in ball)
