"""Every segment of the move under the motor's torque-speed curve."""

import math

from app.core import motion, segments
from app.core.checks.base import (
    MARGIN_NOTE,
    Application,
    Array,
    CandidateTable,
    Check,
    Mapping,
    Measure,
    Quantities,
    Reach,
    ScrewSpec,
    everywhere,
    least,
    lighter,
)
from app.core.formulas import stepper
from app.core.phrase import Amount, Phrase

#: Said of a stepper whose curve may be the model's, drawn from datasheet values (its
#: drive's supply known: a maker's published curve, or one typed in, has none).
DATASHEET_NOTE = (
    " Where the curve is drawn from datasheet values (the values typed in, or a library "
    "stepper without its maker's published curve or on a drive other than its chart's), "
    "the pull-out is the microstepping model's estimate: confirm it on the maker's curve."
)
#: Said where the move runs past the range where the model is confirmed.
BEYOND_RANGE_NOTE = (
    " The move runs to {peak}, past {limit}, where the back-EMF reaches 40 % of the "
    "supply: beyond it the microstepping model's pull-out falls as 1 / speed, 0.73 to "
    "1.11 times the makers' published points there (STEPPERONLINE, Changzhou Songyang, "
    "Trinamic; /validation), as far as they reach, up to 5.7 times that speed; confirm it "
    "on the maker's curve."
)
#: Said where the supply is below the model's range (4 times the winding's I R).
LOW_SUPPLY_NOTE = (
    " The supply, {supply}, is below 4 times the winding's rated voltage I R ({ir}): "
    "outside the microstepping model's validity range, where makers' curves fall far "
    "faster than the model (STEPPERONLINE 17HS24-0644S at 2.6 times I R: under a quarter "
    "of the model's figure at 420 rpm); use the maker's curve."
)


def model_range_rpm(app: Application) -> float | None:
    """The top of the range [rpm] where the microstepping model is confirmed
    (``stepper.confirmed_range_rpm``, over sqrt 2 for a drive that sets the RMS) for a
    stepper whose curve the model draws from its datasheet values (None: no such values,
    as for a curve typed in or a servo)."""
    values = (app.motor_supply_v, app.motor_phase_current_a, app.motor_holding_torque_nm)
    if app.step_angle_deg is None or any(v is None for v in values):
        return None
    supply, current, holding = (float(v or 0.0) for v in values)
    return stepper.confirmed_range_rpm(supply, current, holding, app.motor_current_rms)


def supply_known(app: Application) -> bool:
    """A stepper's supply, phase current and winding resistance are all given."""
    values = (app.motor_supply_v, app.motor_phase_current_a, app.motor_resistance_ohm)
    return app.step_angle_deg is not None and all(v is not None for v in values)


def supply_too_low(app: Application) -> bool:
    """The model's stepper runs on a supply below its range (``stepper.supply_in_range``:
    4 times its winding's rated voltage I R); False where those values are not known
    (``supply_known``)."""
    if not supply_known(app):
        return False
    return not stepper.supply_in_range(
        app.motor_supply_v or 0.0, app.motor_phase_current_a or 0.0, app.motor_resistance_ohm or 0.0
    )


def worst_segment(app: Application, r: Quantities[float]) -> str:
    """The segment that uses the most of the curve, in words ("accelerate up"; "start
    from rest" where the break-away governs)."""
    if r.motor.motor_worst_segment < 0:
        return "start from rest"
    index = int(r.motor.motor_worst_segment)
    if motion.move_profile(app) is None:  # the moving segments alone, at the top speed
        name, direction = segments.moving_segment_names(app)[index]
        return f"{name} {direction}"
    return motion.segment_labels(app)[index]


def accel_that_fits(r: Quantities[float]) -> float | None:
    """The acceleration at which the accelerate segment fits the curve, when that segment
    governs [m/s^2] (``Quantities.motor.motor_fitting_accel_m_s2``; None: none fits)."""
    accel = r.motor.motor_fitting_accel_m_s2
    return None if math.isnan(accel) else accel


def speed_that_fits(app: Application, r: Quantities[float]) -> float | None:
    """The top speed at which every segment fits the curve, below the speed asked for
    [m/s] (``Quantities.motor.motor_fitting_speed_m_s``; None: no slower move fits, or a
    cycle of moves, whose speeds are the moves' own)."""
    speed = r.motor.motor_fitting_speed_m_s
    return speed if math.isfinite(speed) and 0.0 < speed < app.speed_m_s else None


class MotorCurve(Check):
    name = "motor_curve"
    slower_may_clear = True
    why_none = "the motor's curve is too low for every screw: a larger motor or a gearbox"
    judges_motor = True
    label = "Motor torque-speed curve"
    description = (
        "Each segment of the move (accelerate, constant, decelerate, dwell; both ways) "
        "needs, times the torque safety factor, at most the torque the motor's curve gives "
        "over the speeds it runs through (at its top speed; a ramp, accelerating or "
        "decelerating, the lowest from standstill to its top speed, so a curve's dip at a "
        "resonance counts), a stepper's pull-out divided by its torque margin, "
        "and the break-away that starts each move from rest (the thread at static "
        "friction) at most the curve's torque at standstill; the segment nearest its "
        "curve is shown. A stepper's curve from its datasheet "
        "values is the microstepping model: at low speed the holding torque (rated two "
        "phases on) over sqrt 2 for a drive that sets the sine's peak, the whole of it for "
        "one that sets the RMS (the phase-current input says which), then the phase "
        "circuit with its back-EMF, confirmed up to the speed where the back-EMF reaches "
        "40 % of the supply; past it the pull-out falls as 1 / speed. Held against makers' "
        "published curves: 0.88-1.04 times every point of STEPPERONLINE's 23HS32-4004S on "
        "a DM542T microstepping drive at 36 and 48 V; 0.73-1.30 times the half-step curves "
        "of Changzhou Songyang and Trinamic motors, so over the default stepper torque "
        "margin (1.5) the usable torque lies below every published point. Valid for a sine "
        "drive set to the rated current and a supply 4-25 times I R; moves past the "
        "confirmed speed, and lower supplies, are flagged. Confirm the curve on the maker's."
    )
    quantity = "torque"
    capacity_given = "motor_curve"
    formula = "T_need = SF * T_seg; T_motor = T_curve / M"
    source = (
        "Shigley sec. 8-2 (thread torque by the flow of power); motor torque-speed curve; "
        "stepper margin: Parker Motion knowledge base, Torque Margin (steppers 50 %)"
    )
    sources = ("inertia_per_length", "drag_torque", "friction_dynamic")

    def applies(self, app: Application) -> bool:
        return bool(app.motor_curve)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.motor.motor_worst_needed_nm, q.motor.motor_curve_nm)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "SF": app.torque_safety_factor,
            "T_seg": q.motor.motor_worst_nm,
            "T_curve": q.motor.motor_curve_nm * segments.curve_margin(app),
            "M": segments.curve_margin(app),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        values: dict[str, Amount | str] = {
            "segment": worst_segment(app, r),
            "need": Amount(r.motor.motor_worst_needed_nm, "torque"),
            "rpm": Amount(r.motor.motor_worst_rpm, "rpm"),
            "curve": Amount(r.motor.motor_curve_nm, "torque"),
        }
        text = "The {segment} segment needs {need} at {rpm}, which " + verb + " the motor's "
        margin = segments.curve_margin(app)
        if app.step_angle_deg is None:
            return Phrase(text + "{curve} there.", values)
        values["pull_out"] = Amount(r.motor.motor_curve_nm * margin, "torque")
        values["margin"] = f"{margin:g}"
        text += (
            "usable {curve} there: its pull-out {pull_out} over the stepper torque margin {margin}."
        )
        if app.motor_supply_v is not None:  # a curve the model draws (a maker's has none)
            text += DATASHEET_NOTE
        limit = model_range_rpm(app)
        if limit is not None and r.motor.peak_rpm > limit:
            values["peak"] = Amount(r.motor.peak_rpm, "rpm")
            values["limit"] = Amount(limit, "rpm")
            text += BEYOND_RANGE_NOTE
        if supply_too_low(app):
            current, ohm = app.motor_phase_current_a or 0.0, app.motor_resistance_ohm or 0.0
            values["supply"] = f"{app.motor_supply_v or 0.0:.3g} V"
            values["ir"] = f"{current * ohm:.3g} V"
            text += LOW_SUPPLY_NOTE
        return Phrase(text, values)

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        margin = segments.curve_margin(app)
        values: dict[str, Amount | str] = {
            "short": Amount(r.motor.motor_worst_needed_nm - r.motor.motor_curve_nm, "torque"),
            "need": least(r.motor.motor_worst_needed_nm, "torque"),
            "pull_out": least(r.motor.motor_worst_needed_nm * margin, "torque"),
            "margin": f"{margin:g}",
            "rpm": Amount(r.motor.motor_worst_rpm, "rpm"),
            "segment": worst_segment(app, r),
        }
        # a stepper's pull-out is divided by its margin before the move is held against it
        motor = (
            "a motor giving {need} at {rpm}"
            if app.step_angle_deg is None
            else "a stepper whose pull-out is {pull_out} at {rpm} ({need} usable over the "
            "stepper torque margin {margin})"
        )
        accel, speed = accel_that_fits(r), speed_that_fits(app, r)
        if accel is None and speed is None:
            lower = "speed, acceleration" if app.moves else "acceleration"
            less = lighter(app)
            return Phrase(
                "The {segment} segment is {short} short: "
                + motor
                + ", or a lower "
                + lower
                + (" or " + less if less else "")
                + "."
                + MARGIN_NOTE,
                values,
            )
        # the figures that leave the torque FIX_MARGIN inside the curve, as promised
        options = []
        fix_accel, fix_speed = r.motor.motor_fix_accel_m_s2, r.motor.motor_fix_speed_m_s
        if accel is not None and fix_accel > 0.0:
            values["accel"] = Amount(fix_accel, "accel", "down")
            options.append("an acceleration of at most {accel}")
        if speed is not None and 0.0 < fix_speed < app.speed_m_s:
            values["speed"] = Amount(fix_speed, "speed", "down")
            options.append("a top speed of at most {speed}")
        if not options:
            return Phrase(
                "The {segment} segment is {short} short: " + motor + "." + MARGIN_NOTE, values
            )
        return Phrase(
            "The {segment} segment is {short} short: "
            + ", ".join(options)
            + ", or "
            + motor
            + "."
            + MARGIN_NOTE,
            values,
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float] | None:
        accel, speed = accel_that_fits(r), speed_that_fits(app, r)
        limits = {} if accel is None else {"accel_m_s2": accel}
        if speed is not None:
            limits["speed_m_s"] = speed
        return limits or None
