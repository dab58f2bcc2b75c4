"""Stacked axes sized together: each axis rides on the one below (Z on X on Y).

An upper axis, with its screw, nut, motor and frame, is part of the moving mass of the
axis that carries it. So the axes are sized from the top down: the top axis as it is
given, then each lower axis with every axis above it added to its moving mass (their
weight on a vertical axis, their inertia on every axis: ``motion.nut_force_forms``). The
screw chosen on an upper axis (the user's choice, else its first-ranked screw) decides
the mass the axes below carry, so choosing another screw there changes their answer.

The rotors and screws of the upper axes translate with them: their masses count as
moving mass of the axes below; their rotary inertia matters only to their own motors.
"""

from collections.abc import Sequence
from dataclasses import dataclass, replace

from app.core import motion
from app.core.changes import Ranges, Words
from app.core.evaluate import evaluate
from app.core.formulas import geometry
from app.core.index import CatalogIndex
from app.core.model import Application, AxisProvenance
from app.core.record import Candidate
from app.core.selection import Selection, select


@dataclass(frozen=True, slots=True)
class Axis:
    """One axis of the stack: its application (its own moving mass: carriage and payload,
    the heaviest move's in a cycle of moves: ``motion.heaviest_mass``),
    the mass of its frame that moves with it when it rides on another axis (rails, base,
    bearings, brackets) [kg], its motor's mass [kg] (0 when counted in the frame), the
    screw chosen for it (None: the first-ranked), and the provenance of its values the
    checks' capacities are (``AxisProvenance``; None: typed in)."""

    name: str
    app: Application
    frame_kg: float = 0.0
    motor_kg: float = 0.0
    choice: str | None = None
    provenance: AxisProvenance | None = None


@dataclass(frozen=True, slots=True)
class AxisResult:
    """One axis sized: the application it was sized with (the axes above in its moving
    mass), the mass those axes add [kg], its selection, the screw chosen (None: none
    passes and none was named), the mass it brings to the axis below [kg], and the
    axes above whose screw that mass leaves out (none chosen there: its mass is not
    known until one is)."""

    axis: Axis
    app: Application
    carried_kg: float
    selection: Selection
    chosen: Candidate | None
    screw_kg: float
    total_kg: float
    uncounted: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class Machine:
    """The stack sized: each axis top first, the axis that governs (the chosen screw with
    the highest governing utilisation, or the first axis with nothing chosen), and the
    mass the bottom axis moves [kg]."""

    axes: tuple[AxisResult, ...]
    governing: str | None
    moved_kg: float


def screw_mass(app: Application, chosen: Candidate) -> float:
    """The chosen screw's mass over the axis's length [kg]: a solid cylinder at the
    thread's pitch diameter (``geometry.screw_mass``)."""
    s = chosen.screw
    return geometry.screw_mass(s.density_kg_m3, float(chosen.pitch_diameter_m), app.length_m)


def _chosen(app: Application, index: CatalogIndex, sel: Selection, axis: Axis) -> Candidate | None:
    """The chosen screw's candidate: the named one (evaluated alone when it is not among
    those returned), else the first-ranked; None when none passes. LookupError for a
    name the catalog lacks."""
    choice = axis.choice
    if choice is None:
        return sel.candidates[0] if sel.candidates else None
    for c in (*sel.candidates, *sel.rejected):
        if c.screw.id == choice:
            return c
    if choice not in index.positions:
        raise LookupError(choice)
    return evaluate(app, index.row(index.positions[choice]), index.table.reach, axis.provenance)


def carrying(app: Application, carried_kg: float) -> Application:
    """``app`` with ``carried_kg`` more moving mass: in its scalar move and in each move
    of its cycle."""
    moves = tuple(replace(m, moving_mass_kg=m.moving_mass_kg + carried_kg) for m in app.moves)
    return replace(app, moving_mass_kg=app.moving_mass_kg + carried_kg, moves=moves)


def size_axis(
    axis: Axis,
    carried_kg: float,
    index: CatalogIndex,
    ranges: Ranges,
    words: Words,
    uncounted: tuple[str, ...] = (),
) -> AxisResult:
    """One axis with ``carried_kg`` of upper axes added to its moving mass, which leaves
    out the screws of the axes ``uncounted`` (none chosen there)."""
    app = carrying(axis.app, carried_kg)
    sel = select(app, index, ranges, words, axis.provenance)
    chosen = _chosen(app, index, sel, axis)
    screw_kg = 0.0 if chosen is None else screw_mass(app, chosen)
    total = motion.heaviest_mass(app) + axis.frame_kg + axis.motor_kg + screw_kg
    return AxisResult(axis, app, carried_kg, sel, chosen, screw_kg, total, uncounted)


def size_machine(
    axes: Sequence[Axis], index: CatalogIndex, ranges: Ranges, words: Words
) -> Machine:
    """Size ``axes`` (top first): each with the total mass of the axis above it."""
    results: list[AxisResult] = []
    carried = 0.0
    uncounted: tuple[str, ...] = ()
    for axis in axes:
        result = size_axis(axis, carried, index, ranges, words, uncounted)
        results.append(result)
        carried = result.total_kg
        if result.chosen is None:
            uncounted = (*uncounted, axis.name)
    return Machine(tuple(results), _governing(results), motion.heaviest_mass(results[-1].app))


def _governing(results: Sequence[AxisResult]) -> str | None:
    """The axis nearest its limit: one with no screw chosen, or a chosen screw that
    fails, first; else the highest governing utilisation."""
    for r in results:
        if r.chosen is None or not r.chosen.passed:
            return r.axis.name
    utilization = {r.axis.name: r.chosen.max_utilization for r in results if r.chosen}
    return max(utilization, key=utilization.__getitem__, default=None)
