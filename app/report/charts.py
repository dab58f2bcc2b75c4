"""The numbers behind a result's charts that the candidates' output models do not carry:
the axis read from the inputs once, the lead sweep of the top candidate's size
(``app.core.sweep.lead_sweep``) and the wear life of the wear-rated candidates at the
cycle's wear thrust (``app.core.sweep.wear_points``) and the pressure each top nut allows
against the sliding speed (``app.core.sweep.pressure_limits``). The pages draw them
(``app.web.figures``); nothing here knows a chart."""

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from app.catalog import Catalog
from app.catalog.axis_motor import CurveOrigin, curve_origin
from app.contract.schemas import ApplicationIn
from app.core import drive, motion, segments
from app.core.checks.wear_life import life_band
from app.core.index import size_of
from app.core.model import Application
from app.core.sweep import LeadPoint as LeadPoint
from app.core.sweep import PressureLimit as PressureLimit
from app.core.sweep import lead_sweep, pressure_limits, wear_points
from app.core.units import from_si


@dataclass(frozen=True, slots=True)
class WearLine:
    """One wear-rated candidate at the cycle's wear thrust ``force_n`` [N]: its life
    (years of the duty, or km of travel without a duty), the shares of that life at
    the wear rate's high and low ends (``life_band``) and, for a nut the seed rates, its
    rated travel band in the same unit (None: no rating), which the results' life never
    exceeds at either end."""

    id: str
    force_n: float
    life: float
    band: tuple[float, float]
    cap: tuple[float, float] | None = None


@dataclass(frozen=True, slots=True)
class ChartData:
    """The axis's numbers in SI that the charts mark (length [m], the speed the move
    reaches [m/s], ``motion.reached_speed``, the torque line [N m] or None, the motor's
    curve as (rpm, N m) pairs, the torque safety factor and the curve's margin,
    ``segments.curve_margin``), the lead sweep (empty without a catalog)
    the wear lines (``wear_in_years``: their life is in years of a duty) and the nuts'
    pressure limits (empty without a catalog)."""

    length_m: float
    speed_m_s: float
    #: the most the torque before its safety factor may reach [N m]
    #: (``drive.torque_before_factor_nm``)
    torque_line_nm: float | None
    curve: tuple[tuple[float, float], ...]
    #: where the curve comes from (``axis_motor.curve_origin``; None without a curve)
    curve_origin: CurveOrigin | None
    #: the continuous torque the cycle's RMS torque is held to, as (rpm, N m) points over
    #: the curve's speeds (``continuous_line``; empty without a continuous rating)
    continuous: tuple[tuple[float, float], ...]
    torque_safety_factor: float
    curve_margin: float
    sweep: list[LeadPoint]
    wear: list[WearLine]
    wear_in_years: bool
    pressure: list[PressureLimit]


def _wear_lines(
    app: Application, catalog: Catalog, ids: Sequence[str], top: int
) -> tuple[list[WearLine], bool]:
    lines = []
    for point in wear_points(app, catalog.index, ids)[:top]:
        life = point.life_years
        if life is None:
            life = from_si(point.travel_m, "km")
        per_m = life / point.travel_m  # the life's years (or km) per metre of travel
        rated = point.rated_m
        cap = None if rated is None else (rated[0] * per_m, rated[1] * per_m)
        band = life_band(catalog.by_id[point.id])
        lines.append(WearLine(point.id, point.force_n, life, band, cap))
    return lines, bool(app.stroke_m and motion.cycles_per_day(app))


def continuous_line(app: Application) -> tuple[tuple[float, float], ...]:
    """The motor's continuous torque [N m] against speed [rpm] as the RMS check holds the
    cycle to it (``segments.continuous_torque``): its continuous duty zone's points where
    it has one, else its continuous rating flat, each from standstill to the top of its
    curve (or of the zone); empty without a continuous rating or a curve to draw it on.
    A rating of 0.3 N m on a curve from 0 to 3000 rpm: ((0, 0.3), (3000, 0.3)).
    """
    rating = segments.continuous_rating(app)
    if rating is None or not app.motor_curve:
        return ()
    if not app.motor_rms_curve:
        return ((app.motor_curve[0][0], rating), (app.motor_curve[-1][0], rating))
    rpm = sorted({x for x, _ in app.motor_curve} | {x for x, _ in app.motor_rms_curve})
    torque = segments.continuous_torque(app, np.array(rpm, dtype=np.float64)).tolist()
    return tuple(zip(rpm, torque, strict=True))


#: the pressure-limit curves span the operating sliding speed divided and multiplied by
#: this factor, at this many points.
PRESSURE_SPAN = 10.0
PRESSURE_POINTS = 41


def chart_data(
    inputs: ApplicationIn, catalog: Catalog | None, ids: Sequence[str], wear_top: int
) -> ChartData:
    """The charts' numbers for a result whose candidates are ``ids``, best first (at
    least one): the lead sweep of the first one's size and the wear lines of the first
    ``wear_top`` wear-rated ones, given the catalog; the axis alone without it."""
    if catalog is not None:
        app, origin, _ = inputs.to_core_traced(catalog.motors, catalog.supports)
    else:
        app = inputs.axis()
        origin = curve_origin(app, app, {})
    sweep: list[LeadPoint] = []
    wear: list[WearLine] = []
    pressure: list[PressureLimit] = []
    in_years = False
    if catalog is not None:
        sweep = lead_sweep(app, catalog.index, size_of(catalog.by_id[ids[0]]))
        wear, in_years = _wear_lines(app, catalog, ids, wear_top)
        pressure = pressure_limits(
            app, catalog.index, ids[:wear_top], PRESSURE_SPAN, PRESSURE_POINTS
        )
    return ChartData(
        length_m=app.length_m,
        speed_m_s=motion.reached_speed(app),
        torque_line_nm=drive.torque_before_factor_nm(app),
        curve=app.motor_curve,
        curve_origin=origin,
        continuous=continuous_line(app),
        torque_safety_factor=app.torque_safety_factor,
        curve_margin=segments.curve_margin(app),
        sweep=sweep,
        wear=wear,
        wear_in_years=in_years,
        pressure=pressure,
    )
