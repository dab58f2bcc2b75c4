"""The duty for many candidates at once: the rated life in years, lead error and thermal
growth over the stroke, the nut's heat balance, and the thrust bearing's load and life.
"""

import math
from typing import Any

import numpy as np

from app.core import motion
from app.core.formulas import (
    accuracy,
    ballscrew,
    heat,
    life,
    support,
)
from app.core.model import Application
from app.core.nut import nut_length
from app.core.table import Array, CandidateTable, filled, finite
from app.core.timeline import Profile

#: Ambient temperature at which the screw's length is nominal [C].
REFERENCE_TEMPERATURE_C = 20.0


def most_cycles_per_day(p: Profile | None) -> float | None:
    """The most cycles a day holds [1/day]: its 24 hours over the time of the cycle
    ``p`` (every move and dwell, ``motion.move_profile``); None without a move. 0.2 m at
    0.1 m/s with 1 m/s^2 ramps takes 2.1 s, with its 0.4 s dwell 2.5 s each way:
    86,400 s / 5 s.

    >>> most_cycles_per_day(motion.move_profile(Application(load_n=0.0, speed_m_s=0.1,
    ...     length_m=0.5, stroke_m=0.2, accel_m_s2=1.0, dwell_s=0.4)))
    17280.0
    """
    return None if p is None else life.cycles_per_day(life.HOURS_PER_DAY, p.cycle_time_s)


def cycles_fit_a_day(cycles_per_day: float | None, p: Profile | None) -> bool:
    """The cycles per day given fit in a day of the cycle ``p`` (``most_cycles_per_day``;
    a day exactly filled fits, its product rounded a hair above)."""
    most = most_cycles_per_day(p)
    return cycles_per_day is None or most is None or cycles_per_day <= most * (1.0 + 1e-12)


def stroke_span_m(app: Application) -> float:
    """The length of screw the nut travels over [m]: the stroke, else the cycle's
    equivalent stroke (``motion.equivalent_stroke``: half a cycle of moves' travel), 0
    without either."""
    if app.stroke_m is not None:
        return app.stroke_m
    return motion.equivalent_stroke(app) or 0.0


def screw_fins(app: Application, t: CandidateTable, nut_m: Array) -> Array:
    """The screw's conductance both ways from the nut [W/K]: two fins of its root (the
    endless fin's conductance and the fin parameter in still air, catalog columns,
    ``heat.fin_conductance``, ``heat.fin_parameter``),
    each as long as the screw each side of the nut at the end of its stroke, centred on
    the screw (``heat.nut_sides_m``; the stroke, else the cycle's equivalent stroke), its
    far end taken as insulated (``heat.fin_share``)."""
    sides = heat.nut_sides_m(app.length_m, stroke_span_m(app), nut_m)
    shares = heat.fin_share(sides[0], t.fin_m_per_m) + heat.fin_share(sides[1], t.fin_m_per_m)
    return np.asarray(t.fin_conductance_w_k * shares, dtype=np.float64)


def heat_balance(app: Application, t: CandidateTable, c: motion.Cycle) -> dict[str, Any]:
    """The power the nut's thread friction and drag turn into heat, averaged over the
    cycle ``c`` (``motion.cycle_of``), and the nut's steady temperature rise: the screw
    conducts the heat away both ways as a fin, the nut's surface convects it.

    The thread heats at the travel-weighted mean of the thrust it carries in every moving
    segment of every move (``c.wear_n``, ``motion.wear_thrust``: the load with its
    direction, the weight on a vertical axis, m a on the ramps), the same cycle whether
    given as the scalar inputs or as moves, at the cycle's mean speed (its travel over
    its time, dwells included), every segment through the forward efficiency (a segment
    the load drives loses less: the safe side). The nut's drag (``heat.drag_power``, the
    top of its range, as the torque breakdown and the cycle's energy take it) heats at
    the same mean speed. Without a stroke: the constant-speed run at the top speed."""
    stroke = motion.equivalent_stroke(app) or 0.0
    p = c.fastest
    mean_speed = app.speed_m_s if p is None else 2.0 * stroke / p.cycle_time_s
    friction = finite(heat.friction_power(c.wear_n, mean_speed, t.efficiency, t.friction_loss))
    drag = heat.drag_power(t.drag_max_nm, mean_speed, t.lead_m, t.drag_work_per_turn_j)
    nut_m = nut_length(app, t)
    rise = heat.temperature_rise(
        friction + drag,
        screw_fins(app, t, nut_m),
        nut_m,
        t.nut_outer_diameter_m,
        heat.FREE_CONVECTION_W_M2_K,
    )
    return {
        "heat_speed_m_s": filled(len(t), mean_speed),
        "friction_power_w": friction,
        "drag_power_w": drag,
        "nut_temperature_rise_k": rise,
        "heat_growth_m": heat_growth(app, t, rise, nut_m),
    }


def heat_growth(app: Application, t: CandidateTable, rise_k: Array, nut_m: Array) -> Array:
    """Each screw's growth from its nut's friction heat [m] (``heat.heated_growth``),
    between the thrust bearing and the nut at the far end of its stroke, for the
    positioning error; the nut's steady rise ``rise_k`` [K] (``heat_balance``), the nut
    length ``nut_m`` [m].

    The span is the heat balance's own (``screw_fins``): the nut at the end of a stroke
    centred on the screw, where its heat balance is taken, the thrust bearing at the
    screw's end beyond the stroke from it. The screw's temperature falls along it as the
    long fin's profile, theta_b cosh(m (L_f - x)) / cosh(m L_f), L_f the screw's length
    from the nut to that end (``heat.nut_sides_m``); the growth counts it to the nut's
    middle. A bearing nearer the nut, or one drawing heat off, grows less: the safe side.

    NaN where the heat balance does not judge the nut: without a stroke or moves (no
    duty), a ball nut (it rolls: no sliding-friction model), or a screw without its
    conductivity, nut length or expansion.
    """
    if not (app.stroke_m or app.moves):
        return filled(len(t), np.nan)
    far_m = heat.nut_sides_m(app.length_m, stroke_span_m(app), nut_m)[1]
    growth = heat.heated_growth(t.screw_expansion_per_k, rise_k, t.fin_m_per_m, far_m, nut_m)
    return np.where(t.ball, np.nan, growth).astype(np.float64)


def duty(
    app: Application, t: CandidateTable, wear_travel_m: Array, cycles: float | None
) -> dict[str, Any]:
    """Rated life in years for the duty, lead error and thermal growth over the stroke.

    The seed rates its nuts' travel without the load it holds at, and warns that life
    varies with load: the rated travel is taken as at most the wear life of the same nut
    material at this cycle's wear thrust (``wear_travel_m``, NaN where the nut has no
    wear rate), so a rating never promises more at a high load than the wear law.
    ``cycles``: the cycles a day (``motion.cycles_per_day``)."""
    nan = filled(len(t), np.nan)
    stroke = motion.equivalent_stroke(app)
    rated = bool(stroke and cycles)
    travel = app.stroke_m if app.stroke_m is not None else app.length_m
    low_m = np.where(t.life_min_given, np.fmin(t.life_min_m, wear_travel_m), np.nan)
    high_m = np.where(t.life_max_given, np.fmin(t.life_max_m, wear_travel_m), np.nan)
    return {
        "life_travel_min_m": low_m,
        "life_years_min": life.life_years(low_m, stroke, cycles) if rated else nan,
        "life_years_max": life.life_years(high_m, stroke, cycles) if rated else nan,
        "lead_error_m": lead_error(t, travel),
        "thermal_growth_m": accuracy.thermal_growth(
            t.screw_expansion_per_k, travel, app.ambient_c - REFERENCE_TEMPERATURE_C
        ),
    }


def lead_error(t: CandidateTable, travel_m: float) -> Array:
    """Each candidate's lead error over the travel [m]: a leadscrew's lead accuracy times
    the travel (``accuracy.cumulative_lead_error``), a ball screw's limit deviation e_p of
    its ISO 3408-3 class over it, by its maker's table or the transport rule
    (``accuracy.ball_travel_deviation``); NaN where the catalog gives neither (a screw
    without a lead accuracy, a travel beyond its class's table).

    An ISO trapezoidal screw has none; a rolled T7 ball screw over 100 mm has 52 um, its
    v300p (not 100 / 300 of it).
    """
    error = np.asarray(accuracy.cumulative_lead_error(t.lead_accuracy, travel_m), np.float64)
    ball = t.travel_variation_given
    error[ball] = accuracy.ball_travel_deviation(travel_m, t.travel_variation_300mm_m[ball])
    for position, bands in enumerate(t.deviation_tables):
        rows = t.deviation_table == position
        error[rows] = accuracy.ball_travel_deviation(travel_m, math.nan, bands)
    return error


def travel_thrusts(
    app: Application, c: motion.Cycle | None = None
) -> tuple[list[float], list[float]]:
    """The thrust on the nut in each moving segment of every move [N] and the distance
    travelled in it [m] (a ramp covers v t / 2, the constant segment v t,
    ``motion.wear_forms``); none without a stroke. ``c``: the cycle when already worked
    out (``motion.cycle_of``)."""
    c = c or motion.cycle_of(app)
    if c.fastest is None:
        return [], []
    return c.moving_n, c.travels


def operating_mean_load(
    app: Application, preload_n: Array, thrusts: tuple[list[float], list[float]] | None = None
) -> Array:
    """The cubic mean of the load each nut's ball track carries over the cycle [N]: each
    segment's thrust raised by the nut's preload F_pr [N] (0 or NaN: a nut with play)
    below its disengagement force (``ballscrew.preloaded_operating_load``; a NaN preload
    counts as none). ``thrusts``:
    the cycle's ``travel_thrusts`` when already worked out."""
    forces, travels = thrusts or travel_thrusts(app)
    preload = np.asarray(preload_n, dtype=np.float64)
    carried = ballscrew.preloaded_operating_load(np.array(forces)[None, :], preload[:, None])
    mean = np.asarray(ballscrew.cubic_mean_load(carried, travels), dtype=np.float64)
    return np.broadcast_to(mean, preload.shape).copy()  # 0 for every nut when nothing moves


def side_mean_loads(
    app: Application, preload_n: Array, thrusts: tuple[list[float], list[float]] | None = None
) -> tuple[Array, Array]:
    """The cubic means over the cycle of the loads each nut's two sides carry [N]
    (``ballscrew.side_loads``: side 1 pressed by a thrust out or up, side 2 by one back
    or down), each segment weighted by its travel; 0 when nothing moves. ``thrusts``: the
    cycle's ``travel_thrusts`` when already worked out."""
    forces, travels = thrusts or travel_thrusts(app)
    preload = np.asarray(preload_n, dtype=np.float64)
    sides = ballscrew.side_loads(np.array(forces)[None, :], preload[:, None])
    means = [np.asarray(ballscrew.cubic_mean_load(s, travels), dtype=np.float64) for s in sides]
    return np.broadcast_to(means[0], preload.shape).copy(), np.broadcast_to(
        means[1], preload.shape
    ).copy()


#: HIWIN's operating condition factor for a short stroke, under 3 nut lengths: the bottom
#: of its 3.0 to 5.0 (HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K, F 3.8;
#: 1.1 to 1.2 without impact, 1.3 to 1.8 in normal operation, 2.0 to 3.0 with high impact).
SHORT_STROKE_FACTOR = 3.0
#: A stroke shorter than this many nut lengths is a short stroke (HIWIN F 3.8).
SHORT_STROKE_NUT_LENGTHS = 3.0


def ball_load_factors(app: Application, nut_length_m: Array) -> Array:
    """Each ball nut's load factor f_w: the application's ``ball_load_factor``, and at
    least ``SHORT_STROKE_FACTOR`` where the nut travels less than 3 of its lengths (a stroke
    given: ``stroke_span_m``), where HIWIN rates the operating condition 3.0 to 5.0 (its
    balls roll over few of their own circuits). A nut of unknown length takes the
    application's.

    >>> from app.core.model import Application
    >>> app = Application(load_n=0.0, speed_m_s=0.1, length_m=0.5, stroke_m=0.1)
    >>> ball_load_factors(app, np.array([0.03, 0.04, np.nan])).tolist()
    [1.2, 3.0, 1.2]
    """
    span = stroke_span_m(app)
    short = (span > 0.0) & (span < SHORT_STROKE_NUT_LENGTHS * np.asarray(nut_length_m))
    factor = app.ball_load_factor
    return np.where(short, max(factor, SHORT_STROKE_FACTOR), factor).astype(np.float64)


def ball_life_revolutions(
    app: Application,
    dynamic_load_n: Array,
    preload_n: Array,
    load_factor: float | Array,
    thrusts: tuple[list[float], list[float]] | None = None,
) -> Array:
    """Each ball nut's L10 life [revolutions] over the cycle (``ballscrew.nut_life_revolutions``)
    for its rating Ca [N], preload F_pr [N] and load factor f_w (``ball_load_factors``
    gives each nut's): both sides' lives combined for a preloaded nut, the one-sided life
    for one without preload; infinite where nothing loads it. ``thrusts``: the cycle's
    ``travel_thrusts`` when already worked out."""
    thrusts = thrusts or travel_thrusts(app)
    mean = operating_mean_load(app, preload_n, thrusts)
    sides = side_mean_loads(app, preload_n, thrusts)
    revolutions = ballscrew.nut_life_revolutions(
        dynamic_load_n, load_factor, mean, sides, preload_n
    )
    return np.asarray(revolutions, dtype=np.float64)


def track_life_revolutions(
    app: Application, dynamic_load_n: Array, preload_n: Array, force_n: float, load_factor: float
) -> Array:
    """Each ball nut's L10 life [revolutions] at the load its ball track carries, as
    ``ball_track_load`` takes it: over the cycle where the axis moves over a stroke
    (``ball_life_revolutions``), else under the running thrust ``force_n`` [N] throughout
    (both sides of a preloaded nut counted, ``ballscrew.side_loads``), at the load factor
    f_w ``load_factor``."""
    thrusts = travel_thrusts(app)
    if ballscrew.cubic_mean_load(*thrusts) > 0.0:
        return ball_life_revolutions(app, dynamic_load_n, preload_n, load_factor, thrusts)
    preload = np.asarray(preload_n, dtype=np.float64)
    carried = ballscrew.preloaded_operating_load(force_n, preload)
    sides = ballscrew.side_loads(force_n, preload)
    revolutions = ballscrew.nut_life_revolutions(
        dynamic_load_n, load_factor, carried, sides, preload
    )
    return np.asarray(revolutions, dtype=np.float64)


def ball_track_load(app: Application, t: CandidateTable, c: motion.Cycle, force_n: float) -> Array:
    """The load each nut's ball track carries [N]: the cycle's cubic mean of it, each
    segment raised by the nut's preload (``operating_mean_load``), where the axis moves
    over a stroke; else the running thrust ``force_n`` [N] raised by the preload. The
    cycle ``c``: ``motion.cycle_of``. A sliding nut (no preload) carries the thrust."""
    thrusts = travel_thrusts(app, c)
    if thrusts[1] and ballscrew.cubic_mean_load(*thrusts) > 0.0:  # none: no stroke
        return operating_mean_load(app, t.preload_n, thrusts)
    return np.asarray(ballscrew.preloaded_operating_load(force_n, t.preload_n), dtype=np.float64)


def support_bearing(app: Application, t: CandidateTable, c: motion.Cycle) -> dict[str, Any]:
    """The thrust bearing: its allowed static thrust C0a / fs, the cube-mean thrust of the
    cycle ``c`` (``motion.cycle_of``) and its L10 life in years (revolutions times the
    lead over the duty's travel, at the cycles a day given or those the hours a day hold,
    ``c.cycles_per_day``), its mean thrust times the operating factor f_w that a ball
    nut's life takes too: the axis's vibration and shocks load both alike."""
    nan = filled(len(t), np.nan)
    allowed = nan
    if app.support_static_n is not None:
        allowed = filled(
            len(t),
            support.static_allowed_load(app.support_static_n, app.support_static_safety_factor),
        )
    forces, distances = travel_thrusts(app, c)
    mean_n = support.mean_axial_load(forces, distances) if forces else math.nan
    years = nan
    stroke, cycles = motion.equivalent_stroke(app), c.cycles_per_day
    if app.support_dynamic_n is not None and stroke and cycles and mean_n > 0.0:
        revolutions = support.rating_life_revolutions(
            app.support_dynamic_n, mean_n, app.ball_load_factor
        )
        years = life.life_years(revolutions * t.lead_m, stroke, cycles)
    return {
        "support_allowed_n": allowed,
        "support_mean_load_n": filled(len(t), mean_n),
        "support_life_years": years,
    }
