"""The cycle of moves over time and the thrust on the nut in each of its segments.

``cycle(app)`` is the cycle's moves (out and back over the stroke by default);
``move_profile(app)`` the application's trapezoid (or triangle). Every thrust comes from
the force the nut exerts on the moving mass in the axis's own frame
(``nut_force_forms``): the moving mass enters as m a (against the motion when
accelerating, with it when decelerating), and the load acts one way (a weight, spring
or press) or against the motion both ways (friction), as the user says; by default
downwards on a vertical axis and against the motion on a horizontal one. The motor's
torque in each segment, for every candidate, is ``segments``'; the cycle's energy
``cycle_energy``'s.
"""

import math
from collections.abc import Iterable
from dataclasses import dataclass
from itertools import accumulate

from app.core.formulas import life, profile, wear
from app.core.formulas.declare import formula
from app.core.model import STANDARD_GRAVITY_M_S2, Application, Move
from app.core.phrase import Amount, Phrase
from app.core.timeline import Direction, Profile, SegmentName

#: The moving segments and the sign of their acceleration along the motion.
RAMPS: tuple[tuple[SegmentName, float], ...] = (
    ("accelerate", 1.0),
    ("constant", 0.0),
    ("decelerate", -1.0),
)
#: The segments of one move, in order.
ORDER: tuple[SegmentName, ...] = ("accelerate", "constant", "decelerate", "dwell")


def decel(app: Application) -> float:
    """The deceleration [m/s^2]: as given, else the acceleration."""
    return app.accel_m_s2 if app.decel_m_s2 is None else app.decel_m_s2


def cycle(app: Application) -> tuple[Move, ...]:
    """The cycle's moves: the application's own, else out and back over the stroke (0
    without one) from the scalar inputs, each followed by the dwell.

    >>> [m.distance_m for m in cycle(Application(load_n=1.0, speed_m_s=0.1, length_m=0.5,
    ...                                          stroke_m=0.2))]
    [0.2, -0.2]
    """
    if app.moves:
        return app.moves
    stroke = app.stroke_m or 0.0
    return tuple(
        Move(
            distance_m=distance_m,
            speed_m_s=app.speed_m_s,
            accel_m_s2=app.accel_m_s2,
            decel_m_s2=decel(app),
            dwell_s=app.dwell_s,
            moving_mass_kg=app.moving_mass_kg,
            load_n=app.load_n,
            load_direction=app.load_direction,
        )
        for distance_m in (stroke, -stroke)
    )


def heaviest_mass(app: Application, moves: tuple[Move, ...] = ()) -> float:
    """The largest moving mass the nut carries over the cycle [kg] (of ``moves``, the
    cycle's when worked out): its heaviest move's (a part picked up on the way out), the
    scalar input's without moves of its own; the inertia the motor controls at its worst.

    >>> out, back = (Move(d, 0.1, 1.0, 1.0, 0.0, m) for d, m in ((0.1, 3.0), (-0.1, 2.0)))
    >>> scalar = Application(load_n=0.0, speed_m_s=0.1, length_m=0.5, moving_mass_kg=1.0)
    >>> cycle_of_moves = Application(load_n=0.0, speed_m_s=0.1, length_m=0.5, moves=(out, back))
    >>> heaviest_mass(scalar), heaviest_mass(cycle_of_moves)
    (1.0, 3.0)
    """
    return max(m.moving_mass_kg for m in moves or cycle(app))


def sense(move: Move) -> float:
    """The sign of a move's velocity along the axis: +1 up (out), -1 down (back)."""
    return math.copysign(1.0, move.distance_m)


def direction_word(app: Application, move: Move) -> Direction:
    """A move's direction in words: up or down on a vertical axis, out or back."""
    pair = directions(app)
    return pair[0][0] if sense(move) > 0.0 else pair[1][0]


def _profile(move: Move, cycle_time_s: float) -> Profile:
    """One move's trapezoid (or triangle) over its distance; a move of no distance takes
    no time."""
    stroke, a, d = abs(move.distance_m), move.accel_m_s2, move.decel_m_s2
    if stroke == 0.0:
        return Profile("trapezoid", 0.0, 0.0, 0.0, 0.0, cycle_time_s, 0.0)
    v = profile.peak_speed(stroke, move.speed_m_s, a, d)
    t_a, t_d = profile.ramp_time(v, a), profile.ramp_time(v, d)
    t_c = profile.constant_time(stroke, v, a, d)
    return Profile(
        kind="triangle" if v < move.speed_m_s else "trapezoid",
        accel_time_s=t_a,
        constant_time_s=t_c,
        decel_time_s=t_d,
        move_time_s=t_a + t_c + t_d,
        cycle_time_s=cycle_time_s,
        peak_speed_m_s=v,
    )


def profiles(app: Application, moves: tuple[Move, ...] = ()) -> list[Profile] | None:
    """Each move's profile, its ``cycle_time_s`` the whole cycle's (every move and every
    dwell); None without a stroke (or a stroke of 0) and no moves of the user's own.
    ``moves``: the cycle's moves when already worked out (``cycle``)."""
    if not (app.moves or app.stroke_m):
        return None
    moves = moves or cycle(app)
    times = [_profile(m, 0.0).move_time_s for m in moves]
    total = 0.0
    for move, move_s in zip(moves, times, strict=True):
        total += move_s + move.dwell_s
    return [_profile(m, total) for m in moves]


def move_profile(app: Application) -> Profile | None:
    """The cycle's fastest move (the first of the fastest) with the cycle's time: for
    out and back over the stroke, the move over the stroke (None without a stroke, or a
    stroke of 0, and no moves of the user's own)."""
    return fastest(profiles(app))


def fastest(every: list[Profile] | None) -> Profile | None:
    """The first of the fastest of the profiles ``every`` (None: none)."""
    if every is None:
        return None
    return max(every, key=lambda p: p.peak_speed_m_s)


def reached_speed(app: Application) -> float:
    """The highest speed the axis reaches [m/s]: the triangle's peak when the stroke is too
    short to reach the typed speed, else the typed speed (also without a stroke); the
    fastest move's of a cycle of moves. Every speed-based check judges this speed, not the
    one typed."""
    p = move_profile(app)
    return app.speed_m_s if p is None else p.peak_speed_m_s


def speed_note(app: Application) -> Phrase | None:
    """When the move is a triangle: the speed typed, the speed reached, and that the speed
    checks judge the one reached (None for a trapezoid, without a stroke, or for a cycle
    of moves of the user's own)."""
    p = move_profile(app)
    if p is None or p.kind != "triangle" or app.moves:
        return None
    return Phrase(
        "The stroke {s} is too short to reach the {typed} typed: the move is a triangle "
        "that peaks at {peak}, the speed every speed check judges.",
        {
            "s": Amount(app.stroke_m or 0.0, "length"),
            "typed": Amount(app.speed_m_s, "speed"),
            "peak": Amount(p.peak_speed_m_s, "speed"),
        },
    )


def has_duty(app: Application) -> bool:
    """Whether a stroke and the cycles (or hours) a day turn a travel into years."""
    return bool(equivalent_stroke(app)) and bool(cycles_per_day(app))


def life_judged(app: Application) -> bool:
    """Whether a life is required and the duty turns travel into years (``has_duty``)."""
    return app.required_life_years is not None and has_duty(app)


def life_unchecked(app: Application) -> bool:
    """Whether the duty turns life into years but no life check runs (none required)."""
    return app.required_life_years is None and has_duty(app)


def life_note(app: Application) -> Phrase | None:
    """With a duty but no required life: that life is not checked, where each screw's
    life at the duty is read, and what to give to check it (None otherwise)."""
    if not life_unchecked(app):
        return None
    return Phrase(
        "Life is not checked: no required life is given. Each screw's life at this duty "
        "is in its row and its watch list; give a required life to reject the short-lived."
    )


def directions(app: Application) -> tuple[tuple[Direction, float], tuple[Direction, float]]:
    """The two directions of motion and the sign of each one's velocity along the axis:
    up (out) along it, down (back) against it."""
    if app.orientation == "vertical":
        return (("up", 1.0), ("down", -1.0))
    return (("out", 1.0), ("back", -1.0))


def load_sense(app: Application, move: Move | None = None) -> tuple[float, float]:
    """How the user's load acts (on ``move``: its own load direction), as (s, o): (1, 0)
    one way, against the up (out) move, as a weight does; (0, 1) against the motion both
    ways, as friction does. ``auto``: a weight on a vertical axis, against the motion on a
    horizontal one."""
    direction = app.load_direction if move is None else move.load_direction
    if direction == "auto":
        direction = "fixed" if app.orientation == "vertical" else "opposes"
    return (1.0, 0.0) if direction == "fixed" else (0.0, 1.0)


def position_span(distances: Iterable[float]) -> float:
    """The range of positions a cycle of moves of ``distances`` reaches, from its start
    at 0: the highest less the lowest (in the distances' unit).

    >>> position_span([300.0, -500.0, 200.0])
    500.0
    """
    ends = list(accumulate(distances, initial=0.0))
    return max(ends) - min(ends)


def equivalent_stroke(app: Application) -> float | None:
    """The stroke [m] of an out-and-back cycle that travels as far as the cycle: the
    stroke itself, or half the travel of the user's moves (what turns a travel into
    cycles and years)."""
    if not app.moves:
        return app.stroke_m
    return sum(abs(m.distance_m) for m in app.moves) / 2.0


def segment_labels(app: Application) -> list[str]:
    """Each segment of ``segments`` in words ("accelerate up"; "decelerate out, move 3"
    in a cycle of the user's own moves)."""
    out = []
    for k, move in enumerate(cycle(app)):
        where = f", move {k + 1}" if app.moves else ""
        out += [f"{name} {direction_word(app, move)}{where}" for name in ORDER]
    return out


def cycles_per_day(app: Application) -> float | None:
    """The cycles a day: as given, else the hours a day over the time of one cycle, both
    moves and both dwells (``life.cycles_per_day``); None without a duty, or for hours
    without a stroke to time the cycle by.

    An hour a day of 400 mm moves at 0.3 m/s, 10 m/s^2: each move 0.03 + 1.3033 + 0.03 s,
    the cycle 2.7267 s, 3600 / 2.7267 cycles:

    >>> round(cycles_per_day(Application(load_n=0.0, speed_m_s=0.3, length_m=0.5,
    ...     accel_m_s2=10.0, stroke_m=0.4, hours_per_day=1.0)), 1)
    1320.3
    """
    return _cycles_per_day(app, None if app.hours_per_day is None else move_profile(app))


def _cycles_per_day(app: Application, p: Profile | None) -> float | None:
    """``cycles_per_day`` with the move's profile ``p`` (``move_profile``)."""
    if app.cycles_per_day is not None or app.hours_per_day is None:
        return app.cycles_per_day
    return None if p is None else life.cycles_per_day(app.hours_per_day, p.cycle_time_s)


def holds_a_load(app: Application) -> bool:
    """Whether the axis must hold a load at rest: a load left on the nut after some move
    (``_rest_load``: its mass's weight on a vertical axis, a load of fixed direction). A
    vertical axis moving no mass, or a fixed load of 0 N, leaves nothing to hold."""
    return any(_rest_load(app, move) > 0.0 for move in cycle(app))


def _rest_load(app: Application, move: Move) -> float:
    """The load held at rest after ``move`` [N]: its mass's weight on a vertical axis and
    its load when it acts one way (friction holds nothing)."""
    weight = move.moving_mass_kg * STANDARD_GRAVITY_M_S2 if app.orientation == "vertical" else 0.0
    return weight + move.load_n * load_sense(app, move)[0]


def rest_loads(app: Application, moves: tuple[Move, ...] = ()) -> list[float]:
    """The load held in the dwell after each move [N], of ``moves`` when the cycle's moves
    are already worked out: the larger of what the move leaves at rest and what the next
    move (the first after the last) starts with (``_rest_load``), since a part picked or
    placed in the dwell may weigh on the nut for all of it.

    Down empty with 2 kg, then up with 5 kg, on a vertical axis: the dwell at the bottom
    holds the 5 kg (49.03 N), not 2 kg; the one at the top, after the 5 kg move, too.

    >>> from app.core.model import Move
    >>> down = Move(-0.1, 0.05, 1.0, 1.0, 0.5, 2.0)
    >>> up = Move(0.1, 0.05, 1.0, 1.0, 0.5, 5.0)
    >>> app = Application(load_n=0.0, speed_m_s=0.05, length_m=0.3,
    ...                   orientation="vertical", moves=(down, up))
    >>> [round(f, 3) for f in rest_loads(app)]
    [49.033, 49.033]
    """
    held = [_rest_load(app, m) for m in moves or cycle(app)]
    return [max(here, held[(k + 1) % len(held)]) for k, here in enumerate(held)]


def steady_load(app: Application) -> float:
    """The load the axis holds at rest [N]: the weight m g of the moving mass on a
    vertical axis and the user's load when it acts one way (friction holds nothing); the
    largest after any move of a cycle of the user's own."""
    if app.moves:
        return max(rest_loads(app))
    weight = app.moving_mass_kg * STANDARD_GRAVITY_M_S2 if app.orientation == "vertical" else 0.0
    return weight + app.load_n * load_sense(app)[0]


#: A thrust linear in the user's load: (N at load 0, N per N of load).
Form = tuple[float, float]


@formula(
    "F_guide = mu_g m g on a horizontal axis, 0 on a vertical one",
    "Coulomb friction of the guides; Thomson, profile rail carriages: mu 0.002-0.003 (ball)",
)
def guide_friction_n(app: Application, mass_kg: float) -> float:
    """The friction of the guides on a moving mass of ``mass_kg`` [N]: mu_g m g, with mu_g
    the guides' friction coefficient (``Application.guide_friction``), on a horizontal
    axis, whose guides carry the weight; 0 on a vertical one, whose guides carry none of
    it. It opposes the motion: the nut pushes it along with the load. Thomson gives
    0.002-0.003 for ball profile rail carriages and 0.001-0.002 for roller ones, their
    seals' drag besides (thomsonlinear.com, "What is the coefficient of friction for
    profile rail carriages?").

    80 kg on ball carriages at 0.003: 0.003 x 80 x 9.80665 = 2.354 N.

    >>> round(guide_friction_n(Application(load_n=0.0, speed_m_s=0.1, length_m=1.0,
    ...     guide_friction=0.003), 80.0), 3)
    2.354
    """
    if app.orientation == "vertical":
        return 0.0
    return app.guide_friction * mass_kg * STANDARD_GRAVITY_M_S2


def _move_forms(app: Application, move: Move) -> list[Form]:
    """The nut force of the accelerate, constant and decelerate segments of ``move`` as
    forms in the load (``nut_force_forms``); a move of the user's own carries its own
    load, so its forms do not scale with the application's load (h = 0)."""
    weight = move.moving_mass_kg * STANDARD_GRAVITY_M_S2 if app.orientation == "vertical" else 0.0
    fixed, opposing = load_sense(app, move)
    v = sense(move)
    guides = v * guide_friction_n(app, move.moving_mass_kg)
    forms: list[Form] = []
    for _, sign in RAMPS:
        rate = move.accel_m_s2 if sign > 0 else move.decel_m_s2
        g = move.moving_mass_kg * v * sign * rate + weight + guides
        h = fixed + v * opposing
        forms.append((g + h * move.load_n, 0.0) if app.moves else (g, h))
    return forms


@formula(
    "F_nut = m x'' + W + v F_guide + F (s_fixed + v o_opposing)",
    "Newton's second law on the moving mass; the load's direction",
)
def nut_force_forms(app: Application) -> list[Form]:
    """The force the nut exerts on the moving mass along the axis (up or out positive) in
    each moving segment of every move of the cycle (``cycle``), and at rest, as a linear
    form in the load F: F_nut = m x'' + W + v F_guide + F (s + v o), with x'' the
    segment's acceleration along the axis (+a, 0, -d moving up or out; -a, 0, +d moving
    down or back), W = m g on a vertical axis, F_guide the guides' friction on a
    horizontal one (``guide_friction_n``), v = +1 up or out and -1 down or back, and
    (s, o) = (1, 0) for a load of fixed direction (a weight, spring or press: against the
    up or out move) or (0, 1) for one that opposes the motion both ways (friction,
    cutting) (``load_sense``). At rest F_nut = W + F s: once for out and back, after each
    move of a cycle of the user's own (whose forms hold their own loads, h = 0).

    >>> app = Application(load_n=10.0, speed_m_s=0.1, length_m=0.5, moving_mass_kg=2.0,
    ...                   accel_m_s2=3.0, decel_m_s2=5.0)
    >>> [g + h * app.load_n for g, h in nut_force_forms(app)]
    [16.0, 10.0, 0.0, -16.0, -10.0, 0.0, 0.0]
    """
    return _with_rest(app, moving_forms(app))


def _with_rest(app: Application, moving: list[Form]) -> list[Form]:
    """``nut_force_forms`` from the forms of the moving segments (``moving_forms``)."""
    if app.moves:
        return [*moving, *((f, 0.0) for f in rest_loads(app))]
    weight = app.moving_mass_kg * STANDARD_GRAVITY_M_S2 if app.orientation == "vertical" else 0.0
    return [*moving, (weight, load_sense(app)[0])]


def moving_forms(app: Application, moves: tuple[Move, ...] = ()) -> list[Form]:
    """``nut_force_forms`` of the moving segments alone, move after move (of ``moves``
    when the cycle's moves are already worked out)."""
    return [f for move in moves or cycle(app) for f in _move_forms(app, move)]


def at_load(forms: list[Form], load_n: float) -> list[float]:
    """Thrusts linear in the load, ``forms`` (g, h), at the load ``load_n``: g + h F [N].

    >>> at_load([(5.0, 1.0), (-2.0, 0.5)], 10.0)
    [15.0, 3.0]
    """
    return [g + h * load_n for g, h in forms]


def nut_forces(app: Application) -> list[float]:
    """``nut_force_forms`` at the application's load [N]."""
    return at_load(nut_force_forms(app), app.load_n)


def segment_travels(p: Profile | None) -> tuple[float, float, float]:
    """The nut travel [m] of the accelerate, constant and decelerate segments of one move:
    v t / 2 on a ramp, v t at the peak speed v (the triangle's where the stroke is too
    short to reach the top speed). Without a stroke, the constant-speed run alone."""
    if p is None:
        return (0.0, 1.0, 0.0)
    v = p.peak_speed_m_s
    return (v * p.accel_time_s / 2.0, v * p.constant_time_s, v * p.decel_time_s / 2.0)


def wear_forms(app: Application) -> tuple[list[Form], list[float]]:
    """Each moving segment of every move: the nut's thrust as a form in the load
    (``nut_force_forms``) and the segment's travel [m] (``segment_travels``)."""
    moves = cycle(app)
    return moving_forms(app, moves), _travels(moves, profiles(app, moves))


def _travels(moves: tuple[Move, ...], every: list[Profile] | None) -> list[float]:
    """Each moving segment's travel of ``moves`` with their profiles ``every``
    (``segment_travels``)."""
    parts = [None] * len(moves) if every is None else every
    return [x for p in parts for x in segment_travels(p)]


def wear_thrust(app: Application) -> float:
    """The thrust [N] that wears the nut as the whole cycle does (``wear.cycle_wear_thrust``
    over ``wear_forms``): the load with its direction, the weight and m a on the ramps."""
    forms, travels = wear_forms(app)
    return wear.cycle_wear_thrust(at_load(forms, app.load_n), travels)


def lead_move(app: Application) -> Move:
    """The move whose start needs the most thrust (its accelerate segment's thrust against
    the motion; the first move out and back over the stroke): the move the torque
    breakdown and break-away describe."""
    moves = cycle(app)
    return _lead(app, moves, at_load(moving_forms(app, moves), app.load_n) if app.moves else [])


def _lead(app: Application, moves: tuple[Move, ...], moving_n: list[float]) -> Move:
    """``lead_move`` of ``moves``, whose moving segments' thrusts are ``moving_n`` [N]
    (read for the user's own moves alone)."""
    if not app.moves:
        return moves[0]
    starts = [sense(m) * f for m, f in zip(moves, moving_n[::3], strict=True)]
    return moves[starts.index(max(starts))]


def running_thrust(app: Application, move: Move) -> float:
    """The thrust against the motion at the top speed of ``move`` [N] (its constant
    segment)."""
    g, h = _move_forms(app, move)[1]
    return sense(move) * (g + h * app.load_n)


@dataclass(frozen=True, slots=True)
class Cycle:
    """The cycle's numbers that are the same for every candidate, worked out once per
    query (``cycle_of``) and handed to each part of the operating point that reads them.

    ``moves``: ``cycle``; ``profiles``: ``profiles``; ``fastest``: ``move_profile``;
    ``moving_n``: ``moving_forms`` at the load [N]; ``forces``: ``nut_forces`` [N] (the
    moving segments' first, then the rests'); ``steady_n``:
    ``steady_load`` [N]; ``travels``: each moving segment's travel [m] (``wear_forms``);
    ``wear_n``: ``wear_thrust`` [N]; ``lead``: ``lead_move``; ``reached_m_s``:
    ``reached_speed`` [m/s]; ``cycles_per_day``: ``cycles_per_day``."""

    moves: tuple[Move, ...]
    profiles: list[Profile] | None
    fastest: Profile | None
    moving_n: list[float]
    forces: list[float]
    steady_n: float
    travels: list[float]
    wear_n: float
    lead: Move
    reached_m_s: float
    cycles_per_day: float | None


def cycle_of(app: Application) -> Cycle:
    """The ``Cycle`` of ``app``: each number the function it names gives, the moves and
    their forms built once."""
    moves = cycle(app)
    every = profiles(app, moves)
    moving = moving_forms(app, moves)
    forces = at_load(_with_rest(app, moving), app.load_n)
    moving_n = forces[: len(moving)]
    travels = _travels(moves, every)
    top = fastest(every)
    return Cycle(
        moves=moves,
        profiles=every,
        fastest=top,
        moving_n=moving_n,
        forces=forces,
        steady_n=steady_load(app),
        travels=travels,
        wear_n=wear.cycle_wear_thrust(moving_n, travels),
        lead=_lead(app, moves, moving_n),
        reached_m_s=app.speed_m_s if top is None else top.peak_speed_m_s,
        cycles_per_day=_cycles_per_day(app, top),
    )
