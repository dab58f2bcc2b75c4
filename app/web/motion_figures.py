"""The motor and the move as Plotly figures (plain dicts): the motor's torque-speed curve
with each candidate's segments as points, and the top candidate's speed and torque over
one cycle. Numbers come from the core's segments; nothing is recomputed here."""

from collections.abc import Sequence
from typing import Any

from app.catalog.axis_motor import CURVE_ORIGINS, CurveOrigin
from app.contract.schemas import CandidateOut
from app.contract.sections import SegmentOut
from app.contract.units import Display
from app.web.chart_style import PALETTE, axis, layout

TOP = 5
#: the speed at the start and end of each segment, as a share of its top speed.
RAMPS = {"accelerate": (0.0, 1.0), "constant": (1.0, 1.0), "decelerate": (1.0, 0.0)}
REVERSED = ("down", "back")
#: the hover text of a candidate's RMS point (``_rms_point``)
RMS_POINT = "cycle RMS (against the continuous rating)"


def motor_figure(
    candidates: Sequence[CandidateOut],
    curve: tuple[tuple[float, float], ...],
    safety_factor: float,
    d: Display,
    margin: float = 1.0,
    origin: CurveOrigin | None = None,
    continuous: tuple[tuple[float, float], ...] = (),
) -> dict[str, Any]:
    """The motor's torque against speed (its curve) and, for each top candidate, every
    moving segment's top rpm and torque and the break-away at standstill, times the
    safety factor (``_demand_points``): a point above the line is one the motor cannot
    drive. A stepper's curve (its pull-out) is drawn beside
    the usable torque the checks hold the move against, the pull-out over ``margin``.
    The curve's legend says where it comes from (``origin``, a key of
    ``axis_motor.CURVE_ORIGINS``: typed in, the maker's published curve, or the model).
    A motor with a continuous rating has it drawn too, dotted (``continuous``, the
    torque-speed points of ``charts.continuous_line``): the line the cycle's RMS torque
    times the safety factor is held to, not the segments' points. Each candidate's RMS
    torque as the RMS check judges it is then a square at the line's standstill end
    (``_rms_point``)."""
    unit = d.label("torque")
    name = "Motor curve" if margin == 1.0 else "Pull-out"
    if origin:
        name += f" ({CURVE_ORIGINS[origin]})"
    data = [_line(name, curve, d, "solid", "motor")]
    if margin != 1.0:
        usable = tuple((rpm, torque / margin) for rpm, torque in curve)
        data.append(_line(f"Usable (pull-out / {margin:g})", usable, d, "dash", "usable"))
    if continuous:
        rating = "Continuous rating (for the cycle's RMS torque)"
        data.append(_line(rating, continuous, d, "dot", "continuous"))
    for colour, c in zip(PALETTE, candidates[:TOP], strict=False):
        rpm, torque_nm, text = _demand_points(c)
        needed = [t * safety_factor for t in torque_nm]
        symbols = ["circle"] * len(rpm)
        rms = _rms_point(c, continuous[0][1]) if continuous else None
        if rms is not None:
            rpm, needed = [*rpm, continuous[0][0]], [*needed, rms]
            text, symbols = [*text, RMS_POINT], [*symbols, "square"]
        data.append(
            {
                "type": "scatter",
                "mode": "markers",
                "name": c.id,
                "x": rpm,
                "y": [d.value(t, "torque") for t in needed],
                "text": text,
                "marker": {"color": colour, "size": 9, "symbol": symbols},
                "hovertemplate": f"%{{text}}<br>%{{x:.4g}} rpm, %{{y:.4g}} {unit}"
                f"<extra>{c.id}</extra>",
            }
        )
    x_axis = {**axis("Screw speed [rpm]"), "rangemode": "tozero"}
    y_axis = {**axis(f"Torque [{unit}]"), "rangemode": "tozero"}
    return {"data": data, "layout": layout(x_axis, y_axis)}


def _line(
    name: str, points: tuple[tuple[float, float], ...], d: Display, dash: str, tag: str
) -> dict[str, Any]:
    """A black line through torque-speed ``points`` (rpm, N m), in the torque unit shown;
    ``tag`` names it in the hover label."""
    unit = d.label("torque")
    return {
        "type": "scatter",
        "mode": "lines",
        "name": name,
        "x": [rpm for rpm, _ in points],
        "y": [d.value(torque, "torque") for _, torque in points],
        "line": {"color": "#000000", "width": 2, "dash": dash},
        "hovertemplate": f"%{{x:.4g}} rpm<br>%{{y:.4g}} {unit}<extra>{tag}</extra>",
    }


def _demand_points(c: CandidateOut) -> tuple[list[float], list[float], list[str]]:
    """The points the motor-curve check holds against the curve: each moving segment at
    its top speed with its torque [N m] (its magnitude), and the break-away that starts
    a move from rest (``torque.breakaway_nm``: the thread at static friction) at
    standstill, as (rpm, torque, what each is)."""
    moving = [s for s in c.segments or [] if s.name != "dwell"]
    rpm = [s.rpm for s in moving] + [0.0]
    torque_nm = [abs(s.torque_nm) for s in moving] + [abs(c.torque.breakaway_nm)]
    text = [f"{s.name}, {s.direction}" for s in moving] + ["start from rest"]
    return rpm, torque_nm, text


def _rms_point(c: CandidateOut, rating_nm: float) -> float | None:
    """The RMS check's demand [N m], its utilisation times the continuous rating at
    standstill ``rating_nm`` it is held to: the cycle's RMS torque times the safety
    factor, each segment's scaled up where the continuous zone narrows with speed
    (``checks.motor_rms``); None where the check did not run."""
    use = c.utilization.get("motor_rms")
    return None if use is None else use * rating_nm


def _trace_points(segments: list[SegmentOut]) -> tuple[list[float], list[float], list[float]]:
    """Time, speed and motor torque at each segment's start and end, both signed by the
    shaft's direction (the back or down move turns the shaft the other way), so that a
    torque of the speed's sign drives and one of the opposite sign brakes. A dwell's
    torque holds the load (a weight, a load of fixed direction) against its direction,
    the way the out or up move drives: the same sign after either move."""
    times, speeds, torques = [], [], []
    t = 0.0
    for s in segments:
        start, end = RAMPS.get(s.name, (0.0, 0.0))
        sign = -1.0 if s.direction in REVERSED else 1.0
        turn = 1.0 if s.name == "dwell" else sign
        times += [t, t + s.duration_s]
        speeds += [sign * start * s.rpm, sign * end * s.rpm]
        torques += [turn * s.torque_nm, turn * s.torque_nm]
        t += s.duration_s
    return times, speeds, torques


def move_figure(top: CandidateOut, d: Display) -> dict[str, Any]:
    """The top candidate's screw speed and motor torque over one cycle (out and back, or
    up and down, with the dwells): speed on the left axis, torque steps on the right."""
    times, speeds, torques = _trace_points(top.segments or [])
    shown = [d.value(t, "torque") for t in torques]
    unit = d.label("torque")
    data = [
        {
            "type": "scatter",
            "mode": "lines",
            "name": "Screw speed",
            "x": times,
            "y": speeds,
            "line": {"color": "#0072B2", "width": 2},
            "hovertemplate": "%{x:.3g} s<br>%{y:.4g} rpm<extra>speed</extra>",
        },
        {
            "type": "scatter",
            "mode": "lines",
            "name": "Motor torque",
            "x": times,
            "y": shown,
            "yaxis": "y2",
            "line": {"color": "#D55E00", "width": 2},
            "hovertemplate": f"%{{x:.3g}} s<br>%{{y:.4g}} {unit}<extra>torque</extra>",
        },
    ]
    speed_axis = {**axis("Screw speed [rpm]"), **_about_zero(speeds)}
    torque_axis = {
        **axis(f"Motor torque [{unit}]"),
        **_about_zero(shown),
        "overlaying": "y",
        "side": "right",
    }
    return {"data": data, "layout": layout(axis("Time [s]"), speed_axis, yaxis2=torque_axis)}


def _about_zero(values: list[float]) -> dict[str, Any]:
    """A range symmetric about zero (10 % headroom) with the zero line drawn, so that the
    speed and the torque axes share their zero."""
    top = max((abs(v) for v in values), default=0.0) * 1.1 or 1.0
    return {"range": [-top, top], "zeroline": True, "zerolinecolor": "#999999"}


def _steps(segments: list[SegmentOut], values: list[float]) -> tuple[list[float], list[float]]:
    """Each segment's value held over its time: the start and end of each, one after the
    other (time [s], value)."""
    times, shown = [], []
    t = 0.0
    for s, value in zip(segments, values, strict=True):
        times += [t, t + s.duration_s]
        shown += [value, value]
        t += s.duration_s
    return times, shown


def _governing(top: CandidateOut, d: Display) -> dict[str, Any] | None:
    """A marker at the middle of the segment that governs the motor, at its torque; where
    none does, the start from rest governs (``drive.worst_point``: the break-away nearest
    the curve at standstill, or the largest torque): a marker at the cycle's start, at the
    break-away driving the first move."""
    segments = top.segments or []
    t = 0.0
    for s in segments:
        if s.governs:
            return _marker(f"Governs: {s.name} {s.direction}", t + s.duration_s / 2, s.torque_nm, d)
        t += s.duration_s
    if not segments:
        return None
    sign = -1.0 if segments[0].direction in REVERSED else 1.0
    return _marker("Governs: starting from rest", 0.0, sign * abs(top.torque.breakaway_nm), d)


def _marker(name: str, time_s: float, torque_nm: float, d: Display) -> dict[str, Any]:
    """The governing point's diamond at ``time_s``, ``torque_nm`` in the torque shown."""
    return {
        "type": "scatter",
        "mode": "markers",
        "name": name,
        "x": [time_s],
        "y": [d.value(torque_nm, "torque")],
        "marker": {"symbol": "diamond", "size": 12, "color": "#CC79A7"},
        "hovertemplate": f"%{{y:.4g}} {d.label('torque')}<extra>governs</extra>",
    }


def cycle_torque_figure(top: CandidateOut, d: Display) -> dict[str, Any]:
    """The top candidate's motor torque over one cycle, a step per segment (negative: the
    motor brakes), beside the motor's usable torque at each segment's top speed (the
    number the torque-speed curve check holds the torque times the safety factor against,
    drawn either way), the governing segment marked."""
    segments = top.segments or []
    unit = d.label("torque")
    times, torques = _steps(segments, [d.value(s.torque_nm, "torque") for s in segments])
    data: list[dict[str, Any]] = [
        {
            "type": "scatter",
            "mode": "lines",
            "name": "Motor torque",
            "x": times,
            "y": torques,
            "line": {"color": "#D55E00", "width": 2},
            "hovertemplate": f"%{{x:.3g}} s<br>%{{y:.4g}} {unit}<extra>torque</extra>",
        }
    ]
    if segments and all(s.curve_nm is not None for s in segments):
        usable = [d.value(s.curve_nm or 0.0, "torque") for s in segments]
        for sign, name in ((1.0, "Usable motor torque"), (-1.0, "Usable braking torque")):
            data.append(
                {
                    "type": "scatter",
                    "mode": "lines",
                    "name": name,
                    "x": times,
                    "y": _steps(segments, [sign * u for u in usable])[1],
                    "line": {"color": "#000000", "width": 1.5, "dash": "dash"},
                    "hovertemplate": f"%{{x:.3g}} s<br>%{{y:.4g}} {unit}<extra>motor</extra>",
                }
            )
    marker = _governing(top, d)
    if marker is not None:
        data.append(marker)
    y_axis = {**axis(f"Motor torque [{unit}]"), "zeroline": True, "zerolinecolor": "#999999"}
    return {"data": data, "layout": layout(axis("Time [s]"), y_axis)}
