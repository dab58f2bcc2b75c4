"""The operating point's numbers as the screening reads them: every one a float array of
the table's length, whatever the application switches on, and the screening of the first
rows of a table (``Screening.head``) the same numbers as the whole table's first rows."""

import dataclasses

import numpy as np
import pytest

from app.catalog import Catalog
from app.core.model import Application, Move
from app.core.quantities import NAMES, PART_OF, PARTS, operating_point, quantity
from app.core.screening import screen_table
from app.core.selection import select

PLAIN = Application(load_n=100.0, speed_m_s=0.05, length_m=0.5)
APPS = {
    "plain": PLAIN,
    "stroke": dataclasses.replace(
        PLAIN, moving_mass_kg=3.0, accel_m_s2=2.0, stroke_m=0.3, cycles_per_day=500.0
    ),
    "vertical-hold": dataclasses.replace(
        PLAIN,
        orientation="vertical",
        moving_mass_kg=12.0,
        accel_m_s2=2.0,
        stroke_m=0.4,
        hold_power_off=True,
        brake_torque_nm=0.3,
    ),
    "stepper": dataclasses.replace(
        PLAIN,
        moving_mass_kg=3.0,
        accel_m_s2=3.0,
        stroke_m=0.3,
        motor_curve=((0.0, 0.5), (600.0, 0.3), (1500.0, 0.1)),
        step_angle_deg=1.8,
        microsteps=16,
        motor_inertia_kg_m2=5.4e-6,
    ),
    "moves-support": dataclasses.replace(
        PLAIN,
        moves=(
            Move(0.3, 0.25, 2.5, 2.5, 0.2, 2.5, 10.0, "opposes"),
            Move(-0.3, 0.25, 2.5, 2.5, 0.2, 0.5, 10.0, "opposes"),
        ),
        support_static_n=9000.0,
        support_dynamic_n=6000.0,
        bearing_to_nut_m=0.4,
        nut_length_m=0.02,
    ),
}


@pytest.mark.parametrize("name", list(APPS))
def test_every_number_is_a_float_array_of_the_tables_length(catalog: Catalog, name: str) -> None:
    t = catalog.index.table
    q = operating_point(APPS[name], t)
    odd = {
        field: (type(v).__name__, getattr(v, "dtype", None), getattr(v, "shape", None))
        for field in NAMES
        if not (
            isinstance(v := quantity(q, field), np.ndarray)
            and v.dtype == np.float64
            and v.shape == (len(t),)
        )
    }
    assert odd == {}


@pytest.mark.parametrize("name", ["plain", "vertical-hold"])
def test_the_head_of_a_screening_is_the_whole_screenings_first_rows(
    catalog: Catalog, name: str
) -> None:
    """The head's verdicts are the whole screening's first rows; its numbers and
    measures, read at its candidates' positions, are those of the rows screened alone."""
    app, t = APPS[name], catalog.index.table
    whole = screen_table(app, t)
    n = 40
    index = np.arange(n, dtype=np.intp)
    head = whole.head(n, index, t.take(index))
    alone = screen_table(app, t.take(index))
    for field in NAMES:
        part, own = quantity(head.quantities, field), quantity(alone.quantities, field)
        assert np.array_equal(part[:n], own, equal_nan=True), field
    for check, m in alone.measures.items():
        read = head.measures[check]
        assert np.array_equal(read.applicable[:n], m.applicable), check
        for got, want in ((read.demand, m.demand), (read.capacity, m.capacity)):
            assert (got is None) == (want is None), check
            if got is not None:
                assert np.array_equal(got[:n], want, equal_nan=True), check
    assert np.array_equal(head.passed, whole.passed[:n])
    assert np.array_equal(head.passed, alone.passed)
    assert np.array_equal(head.max_utilization, whole.max_utilization[:n], equal_nan=True)
    assert head.failed.keys() == whole.failed.keys()


def test_each_number_lives_in_one_part_and_reads_the_same_every_way(catalog: Catalog) -> None:
    """The parts of ``Quantities`` share no name, so a name alone finds its number
    (``quantity``); one candidate's numbers read through ``at`` and through a returned
    record's ``quantities`` are that candidate's entries of the arrays; a number asked of
    a part that does not hold it is an error, not another part's number."""
    names = [n for _, names in PARTS.values() for n in names]
    assert len(names) == len(set(names)) == len(NAMES) > 80
    assert set(PARTS) == {
        "axis", "torque", "column", "nut", "life", "heat", "accuracy", "holding", "motor",
        "support", "energy",
    }  # fmt: skip
    app = APPS["vertical-hold"]
    s = select(app, catalog.index)
    record = s.candidates[0]
    q, i = s.screening.quantities, s.ranked[0]
    for name in NAMES:
        part = PART_OF[name]
        expected = float(quantity(q, name)[i])
        for read in (getattr(q.at(i), part), getattr(record.quantities, part)):
            assert np.array_equal(getattr(read, name), expected, equal_nan=True), name
    with pytest.raises(AttributeError):
        record.quantities.torque.critical_rpm  # type: ignore[attr-defined]  # noqa: B018
    with pytest.raises(AttributeError):
        record.quantities.total_nm  # type: ignore[attr-defined]  # noqa: B018
