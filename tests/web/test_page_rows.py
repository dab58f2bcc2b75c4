"""The results page's rows (the ``row`` view of ``CandidateOut``) against the full form
of the same candidates: every field of the row is the full form's, the utilisations are
the full checks' and the warned checks are the full form's warnings."""

import pytest

from app.catalog import Catalog
from app.contract.schemas import VIEWS, ApplicationIn
from app.contract.units import DEFAULT_UNITS
from app.report.service import run_page_selection, run_selection
from tests.leadscrews import leadscrew_families

ROW = set(VIEWS["row"])


@pytest.mark.parametrize(
    "inputs",
    [
        {"load_n": 100, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10},
        # traverse-speed advice fails for many of these (warnings on passing rows, ranked
        # after the clean ones)
        {"load_n": 10, "speed_mm_s": 300, "length_mm": 300, "lead_mm": 10, "limit": 30},
        # a move and a motor: profile and segments on every row
        {
            "load_n": 50,
            "speed_mm_s": 200,
            "length_mm": 500,
            "lead_mm": 10,
            "stroke_mm": 300,
            "accel_mm_s2": 2000,
            "moving_mass_kg": 5,
            "brake_torque_nm": 0.2,
        },
    ],
)
def test_rows_equal_the_full_form(catalog: Catalog, inputs: dict[str, float]) -> None:
    application = ApplicationIn.model_validate(inputs)
    page, _ = run_page_selection(application, catalog, DEFAULT_UNITS)
    full = run_selection(application, catalog)
    assert [r.id for r in page.candidates] == [c.id for c in full.candidates]
    assert page.candidates and page.counts == full.counts
    for row, c in zip(page.candidates, full.candidates, strict=True):
        assert set(row.model_fields_set) == ROW, c.id
        # the view's fields, and of the verdict its sentence and governing label alone
        assert row.model_dump(include=VIEWS["row"]) == c.model_dump(include=VIEWS["row"]), c.id
        assert row.utilization == {k.name: k.utilization for k in c.checks}
        assert row.warned == [w.name for w in c.warnings]
    if inputs.get("speed_mm_s") == 300:
        assert any(row.warned for row in page.candidates)
    if "stroke_mm" in inputs:
        assert all(row.segments for row in page.candidates)


def test_the_rejected_are_in_full_only_when_nothing_passes(catalog: Catalog) -> None:
    passing = ApplicationIn.model_validate({"load_n": 100, "speed_mm_s": 50, "length_mm": 500})
    page, compact = run_page_selection(passing, catalog, DEFAULT_UNITS)
    assert page.candidates and not page.rejected and compact
    # 5 kN at 500 mm/s over 2 m: no leadscrew passes (ball screws do, so they are left out)
    none = ApplicationIn.model_validate(
        {"load_n": 5000, "speed_mm_s": 500, "length_mm": 2000,
         "family": list(leadscrew_families(catalog))}
    )  # fmt: skip
    page, compact = run_page_selection(none, catalog, DEFAULT_UNITS)
    assert not page.candidates and page.rejected
    assert [c.id for c in page.rejected] == [r.id for r in compact]
    assert all(c.checks and c.fix for c in page.rejected)
