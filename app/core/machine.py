"""Stacked axes sized together: each axis rides on the one below (Z on X on Y).

An upper axis, with its screw, nut, motor and frame, is part of the moving mass of the
axis that carries it. So the axes are sized from the top down: the top axis as it is
given, then each lower axis with every axis above it added to its moving mass (their
weight on a vertical axis, their inertia on every axis: ``motion.nut_force_forms``). The
screw chosen on an upper axis (the user's choice, else its first-ranked screw) decides
the mass the axes below carry, so choosing another screw there changes their answer.

The rotors and screws of the upper axes translate with them: their masses count as
moving mass of the axes below; their rotary inertia matters only to their own motors.

Each axis is taken to move at right angles to the axes it carries: their own thrust (their
m a and their load) goes into its guides, not its screw. Only two vertical axes are known
to be parallel. A load that acts one way on a vertical axis above (a weight, spring or
press: ``standing_load_n``) reaches the nut of a vertical axis below it whether either
moves or not, so the lower one is sized with it (``with_standing_load``). The thrust
beyond that and the weight (the upper axis's m a, a load that opposes its motion) reaches
the lower nut whenever the two move together (``parallel_thrust``); the answer gives it,
and the sizing leaves it out (the axes moved one at a time).
"""

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Literal

from app.core import motion
from app.core.changes import Ranges, Words
from app.core.evaluate import evaluate
from app.core.formulas import geometry, stacking
from app.core.index import CatalogIndex
from app.core.model import (
    STANDARD_GRAVITY_M_S2,
    Application,
    AxisProvenance,
    Move,
    Provenance,
)
from app.core.record import Candidate
from app.core.selection import Selection, select, with_robustness

#: Where an axis's motor mass comes from: typed in (``Axis.motor_kg``), the library
#: motor's published mass (``Axis.library_motor``), or neither (0 kg).
MotorMassOrigin = Literal["typed", "library", "none"]


@dataclass(frozen=True, slots=True)
class LibraryMotorMass:
    """The published mass of the library motor an axis names: the motor's id, its mass
    [kg] (the top of its range where the library gives one: the safe side for the axis
    that carries it) and where that value comes from."""

    motor: str
    mass_kg: float
    provenance: Provenance


@dataclass(frozen=True, slots=True)
class Axis:
    """One axis of the stack: its application (its own moving mass: carriage and payload,
    the heaviest move's in a cycle of moves: ``motion.heaviest_mass``),
    the mass of its frame that moves with it when it rides on another axis (rails, base,
    bearings, brackets) [kg], its motor's mass as typed [kg] (None: not typed; 0 when
    counted in the frame), the screw chosen for it (None: the first-ranked), the
    provenance of its values the checks' capacities are (``AxisProvenance``; None: typed
    in), and the published mass of the library motor it names (None: none named, or the
    library gives none), which counts where no motor mass is typed (``motor_mass``)."""

    name: str
    app: Application
    frame_kg: float = 0.0
    motor_kg: float | None = None
    choice: str | None = None
    provenance: AxisProvenance | None = None
    library_motor: LibraryMotorMass | None = None


def motor_mass(axis: Axis) -> tuple[float, MotorMassOrigin]:
    """The motor mass [kg] ``axis`` brings to the axis below and where it comes from: the
    typed one wins, else the library motor's published mass, else 0 kg."""
    if axis.motor_kg is not None:
        return axis.motor_kg, "typed"
    if axis.library_motor is not None:
        return axis.library_motor.mass_kg, "library"
    return 0.0, "none"


@dataclass(frozen=True, slots=True)
class AxisResult:
    """One axis sized: the application it was sized with (the axes above in its moving
    mass), the mass those axes add [kg], its selection, the screw chosen (None: none
    passes and none was named), the chosen screw's mass [kg], the mass it brings to the
    axis below [kg] (its moving mass, frame, motor and screw), the
    axes above whose screw that mass leaves out (none chosen there: its mass is not
    known until one is), the vertical axes above a vertical one (parallel to it), and
    the thrust beyond their weight they pass to its nut when they move with it [N]
    (``parallel_thrust``; not in its sizing), its motor's mass in that total [kg]
    with where it comes from (``motor_mass``), and the load the parallel axes above
    stand on its nut whether they move or not, in its sizing [N] (``standing_load_n``)."""

    axis: Axis
    app: Application
    carried_kg: float
    selection: Selection
    chosen: Candidate | None
    screw_kg: float
    total_kg: float
    uncounted: tuple[str, ...] = ()
    parallel: tuple[str, ...] = ()
    parallel_thrust_n: float = 0.0
    motor_kg: float = 0.0
    standing_load_n: float = 0.0
    motor_origin: MotorMassOrigin = "none"


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
    """The chosen screw's candidate: the named one, else the first-ranked; None when none
    passes. LookupError for a name the catalog lacks. A named screw not among those
    returned is evaluated alone and, when it passes, screened at the ends of its ranged
    values as the returned ones are (``selection.with_robustness``, as the single screw's
    evaluation does): a marginal screw is said to hinge on the values that fail it."""
    choice = axis.choice
    if choice is None:
        return sel.candidates[0] if sel.candidates else None
    for c in (*sel.candidates, *sel.rejected):
        if c.screw.id == choice:
            return c
    if choice not in index.positions:
        raise LookupError(choice)
    position = index.positions[choice]
    alone = evaluate(app, index.row(position), index.table.reach, axis.provenance)
    variants, (at,) = index.variants_at([position])
    return with_robustness(app, alone, variants, at)


def carrying(app: Application, carried_kg: float) -> Application:
    """``app`` with ``carried_kg`` more moving mass: in its scalar move and in each move
    of its cycle."""
    moves = tuple(replace(m, moving_mass_kg=m.moving_mass_kg + carried_kg) for m in app.moves)
    return replace(app, moving_mass_kg=app.moving_mass_kg + carried_kg, moves=moves)


def standing_load_n(app: Application) -> float:
    """The load [N] a vertical axis stands on the nut of a vertical axis carrying it,
    whether either moves or not: the largest load of its moves that acts one way, against
    the up move (``motion.load_sense``: a weight, spring or press); 0 on a horizontal
    axis, whose loads go into the guides of the axis below."""
    if app.orientation != "vertical":
        return 0.0
    return max((m.load_n * motion.load_sense(app, m)[0] for m in motion.cycle(app)), default=0.0)


def _standing_move(app: Application, move: Move, load_n: float) -> Move:
    """``move`` with ``load_n`` [N] more acting one way (down, against its up move): the
    sum where its own acts so; where its own opposes the motion, the sum on an up move
    and the difference on a down one, which opposes the motion where its own is the
    larger."""
    own = move.load_n
    if motion.load_sense(app, move)[0] == 1.0 or move.distance_m >= 0.0:
        return replace(move, load_n=load_n + own, load_direction="fixed")
    net = load_n - own
    return replace(move, load_n=abs(net), load_direction="fixed" if net >= 0.0 else "opposes")


def with_standing_load(app: Application, load_n: float) -> Application:
    """``app`` (vertical) with ``load_n`` [N] more load acting one way, against its up
    move (``standing_load_n`` of the axes above), in its scalar load and in each move's
    (``_standing_move``). Where a load of its own opposes the motion, its cycle out and
    back over the stroke becomes its two moves, each with its own sum; without a stroke
    the scalar load is the sum, as on the up move, the larger."""
    own = app.load_n * motion.load_sense(app)[1]
    if own > 0.0 and not app.moves and app.stroke_m:
        app = replace(app, moves=motion.cycle(app))
    moves = tuple(_standing_move(app, m, load_n) for m in app.moves)
    return replace(app, load_n=app.load_n + load_n, load_direction="fixed", moves=moves)


def without_standing_load(app: Application) -> Application:
    """``app`` without its loads that act one way (``standing_load_n``): what is left of
    its thrust beyond its weight is its m a and a load that opposes its motion."""
    moves = tuple(replace(m, load_n=0.0) if motion.load_sense(app, m)[0] else m for m in app.moves)
    still = motion.load_sense(app)[0] == 1.0
    return replace(app, load_n=0.0 if still else app.load_n, moves=moves)


def size_axis(
    axis: Axis,
    carried_kg: float,
    index: CatalogIndex,
    ranges: Ranges,
    words: Words,
    uncounted: tuple[str, ...] = (),
    standing_n: float = 0.0,
) -> AxisResult:
    """One axis with ``carried_kg`` of upper axes added to its moving mass, which leaves
    out the screws of the axes ``uncounted`` (none chosen there), and, when it is
    vertical, the load ``standing_n`` [N] the vertical axes above stand on its nut added
    to its own (``with_standing_load``)."""
    app = carrying(axis.app, carried_kg)
    standing = standing_n if app.orientation == "vertical" else 0.0
    if standing > 0.0:
        app = with_standing_load(app, standing)
    sel = select(app, index, ranges, words, axis.provenance)
    chosen = _chosen(app, index, sel, axis)
    screw_kg = 0.0 if chosen is None else screw_mass(app, chosen)
    motor_kg, origin = motor_mass(axis)
    total = motion.heaviest_mass(app) + axis.frame_kg + motor_kg + screw_kg
    return AxisResult(
        axis,
        app,
        carried_kg,
        sel,
        chosen,
        screw_kg,
        total,
        uncounted,
        motor_kg=motor_kg,
        motor_origin=origin,
        standing_load_n=standing,
    )


def own_thrust(app: Application) -> float:
    """The thrust [N] a vertical axis's nut exerts beyond the weight of the mass it moves,
    the largest over its cycle's moving segments (``stacking.parallel_reaction`` of
    ``motion.moving_forms`` at its load): what it passes to a vertical axis carrying it."""
    moves = motion.cycle(app)
    thrusts = motion.at_load(motion.moving_forms(app, moves), app.load_n)
    weights = [m.moving_mass_kg * STANDARD_GRAVITY_M_S2 for m in moves for _ in motion.RAMPS]
    return stacking.parallel_reaction(thrusts, weights)


def parallel_thrust(
    results: Sequence[AxisResult], lower: AxisResult
) -> tuple[tuple[str, ...], float]:
    """The vertical axes among ``results`` (the axes above) when ``lower`` is vertical
    too, and the sum of their ``own_thrust`` [N]: each one's thrust beyond its weight
    reaches the nut below when they move together, beyond their standing loads where
    ``lower`` is sized with them (``without_standing_load``) (none: ``((), 0.0)``)."""
    if lower.app.orientation != "vertical":
        return (), 0.0
    above = [r for r in results if r.app.orientation == "vertical"]
    carried = lower.standing_load_n > 0.0
    thrust = sum(own_thrust(without_standing_load(r.app) if carried else r.app) for r in above)
    return tuple(r.axis.name for r in above), thrust


def size_machine(
    axes: Sequence[Axis], index: CatalogIndex, ranges: Ranges, words: Words
) -> Machine:
    """Size ``axes`` (top first): each with the total mass of the axis above it and the
    standing loads of the vertical axes above (``standing_load_n``), and the thrust the
    parallel axes above pass to it when they move together (``parallel_thrust``)."""
    results: list[AxisResult] = []
    carried = 0.0
    uncounted: tuple[str, ...] = ()
    for axis in axes:
        standing = sum(standing_load_n(r.axis.app) for r in results)
        result = size_axis(axis, carried, index, ranges, words, uncounted, standing)
        parallel, thrust = parallel_thrust(results, result)
        result = replace(result, parallel=parallel, parallel_thrust_n=thrust)
        results.append(result)
        carried = result.total_kg
        if result.chosen is None:
            uncounted = (*uncounted, axis.name)
    return Machine(tuple(results), _governing(results), motion.heaviest_mass(results[-1].app))


def _governing(results: Sequence[AxisResult]) -> str | None:
    """The axis nearest its limit, or furthest past it: the first with no screw chosen;
    else of the chosen screws that fail, the one with the highest governing utilisation
    (not the first from the top: the axis to change first is the one furthest over);
    else the highest governing utilisation of all. A failure with no utilisation (a
    yes/no check) counts as furthest over."""
    for r in results:
        if r.chosen is None:
            return r.axis.name
    chosen = [(r.axis.name, r.chosen) for r in results if r.chosen is not None]
    failing = [(name, c) for name, c in chosen if not c.passed]
    pool = failing or chosen
    use = {name: float(c.max_utilization) for name, c in pool}
    over = {name: math.inf if math.isnan(u) else u for name, u in use.items()}
    return max(over, key=over.__getitem__, default=None)
