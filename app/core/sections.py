"""The sections of a candidate's record (torque, critical speed, life): parts whose
numbers are read from the screening's columns when first asked for (``app.core.record``
builds them; ``app.core.batch`` holds the columns)."""

import math
from functools import cached_property
from typing import Generic, Literal, Protocol, TypeVar, cast

import numpy as np

from app.core import motion
from app.core.batch import Batch
from app.core.checks.ball_life import BallLife
from app.core.checks.life import Life as RatedLife
from app.core.checks.wear_life import WearLife, life_band
from app.core.formulas import critical_speed, life

T = TypeVar("T")


def number(x: float | None) -> float | None:
    """None for a missing or NaN value."""
    return None if x is None or math.isnan(x) else x


class InBatch(Protocol):
    """A candidate's record or one of its sections: its batch and its place in it."""

    @property
    def batch(self) -> Batch: ...
    @property
    def k(self) -> int: ...


class Column(Generic[T]):
    """An attribute of a record or of one of its sections read from one column of the
    screening (quantities, verdicts or table) when read."""

    def __init__(self, name: str) -> None:
        self.name = name

    def __get__(self, owner: InBatch, cls: type) -> T:
        value: T = owner.batch.column(self.name)[owner.k]
        return value


class Section:
    """A part of a candidate's record (SI) whose numbers are read when first asked for."""

    __slots__ = ("app", "batch", "k", "screw")

    def __init__(self, batch: Batch, k: int) -> None:
        self.batch, self.k, self.app = batch, k, batch.app
        self.screw = batch.slots[k].screw


class Torque(Section):
    """Drive torque breakdown [N m] (seed: inertia + static drag + load); the angular
    acceleration [rad/s^2] and the inertia the motor sees [kg m^2]."""

    __slots__ = ()
    inertia_screw_nm = Column[float]("inertia_screw_nm")
    inertia_mass_nm = Column[float]("inertia_mass_nm")
    inertia_motor_nm = Column[float]("inertia_motor_nm")
    inertia_nm = Column[float]("inertia_nm")
    drag_nm = Column[float]("drag_nm")
    load_nm = Column[float]("load_nm")
    total_nm = Column[float]("total_nm")
    breakaway_nm = Column[float]("breakaway_nm")
    required_nm = Column[float]("required_nm")
    angular_accel_rad_s2 = Column[float]("angular_accel_rad_s2")
    inertia_kg_m2 = Column[float]("inertia_kg_m2")

    @property
    def drag_min_nm(self) -> float:
        return self.screw.drag_torque_min_nm

    @property
    def drag_max_nm(self) -> float:
        return self.screw.drag_torque_max_nm

    @property
    def safety_factor(self) -> float:
        return self.app.torque_safety_factor

    @property
    def peak_segment(self) -> str:
        """Where the peak motor torque occurs, in words: "starting from rest" (the
        break-away) or the moving segment's ("decelerating down"; "decelerating down,
        move 3" in a cycle of the user's own moves)."""
        index = int(self.batch.column("peak_torque_segment")[self.k])
        if index < 0:
            return "starting from rest"
        name, direction = self.batch.moving_segment_names[index]
        where = f", move {index // 3 + 1}" if self.app.moves else ""
        return f"{SEGMENT_WORDS[name]} {direction}{where}"


#: A moving segment's name as the sub-line of the peak torque says it.
SEGMENT_WORDS = {
    "accelerate": "accelerating",
    "constant": "at constant speed",
    "decelerate": "decelerating",
}


class CriticalSpeed(Section):
    """The screw's critical speed and the speed allowed [rpm], and the margin
    allowed / running speed."""

    __slots__ = ()
    theoretical_rpm = Column[float]("critical_rpm")
    allowed_rpm = Column[float]("allowed_rpm")

    @property
    def margin(self) -> float:
        return critical_speed.speed_margin(self.allowed_rpm, self.batch.column("rpm")[self.k])

    @property
    def safety_factor(self) -> float:
        return self.app.critical_speed_safety_factor

    @property
    def end_fixity(self) -> str:
        return self.app.end_fixity


#: What each life model's numbers rest on.
LIFE_NOTES = {
    "rated": "Rated travel (seed). Life varies with load, environment and duty cycle; "
    "longer leads generally last longer (seed). The seed gives no load for its rating: "
    "where the nut material has a wear rate, each end counts for no more than the nut's "
    "wear life at the cycle's wear thrust (Archard's law, assumed wear rate).",
    "wear": "Wear life by Archard's law at the cycle's wear thrust (every segment of both "
    "moves, m a on the ramps, weighted by its travel): the nut travel until its "
    "flanks wear the allowed depth, at the high and the low end of the nut material's "
    "assumed wear rate (3:1 either way of its value; published rates scatter 2-3:1). "
    "Lubrication, heat and dirt move it further.",
    "l10": "L10 rated fatigue life of the ball nut (ISO 3408-5): (Ca / (f_w F_m))^3 x 10^6 "
    "revolutions at the cycle's cubic mean load F_m (each moving segment weighted by its "
    "revolutions; a preloaded nut's load raised by its preload below 2^(3/2) times it, "
    "HIWIN F 3.7), times the load factor f_w (1.2 by default: HIWIN's 1.1 to 1.2 without "
    "impact, 1.3 to 1.8 in normal operation; at least 3.0 on a stroke under 3 nut "
    "lengths, HIWIN F 3.8's 3.0 to 5.0); 90 % of nuts reach it. "
    "Lubrication and contamination move it (HIWIN sec. 3.7.2).",
}


class Life(Section):
    """The nut's life as a band [m of travel] and, with a stroke and a duty, in years,
    with the model it comes from: the seed's rated travel ("rated") or, for a nut the
    seed gives none, the nut's wear by Archard's law over the wear rate's published
    scatter ("wear"; ``app.core.checks.wear_life``). Also in hours of operation and,
    with a stroke, in cycles (out and back). Its band of travel is worked out once: the
    years, hours and cycles all read it."""

    @property
    def model(self) -> Literal["rated", "wear", "l10"]:
        if self.screw.screw_type == "ball":
            return "l10"
        return "rated" if self.screw.life_min_m is not None else "wear"

    def _l10_travel_m(self) -> float:
        """A ball nut's L10 life as travel [m]: its rated revolutions (``Batch.l10_revolutions``,
        both sides of a preloaded nut) times the lead (infinite without a stroke or a load
        on its balls)."""
        revolutions, s = self.batch.l10_revolutions[self.k], self.screw
        if not (s.dynamic_load_n and revolutions < math.inf):
            return math.inf
        return revolutions * s.lead_m

    @property
    def note(self) -> str:
        """Which model the numbers come from, and how far to trust them."""
        return LIFE_NOTES[self.model]

    @property
    def sources(self) -> tuple[str, ...]:
        """The catalog values the numbers are worked from, those of the check that judges
        a life of its model: the seed's rated travel (and the nut's wear where it cuts
        that), the nut's wear, or a ball nut's ratings."""
        if self.model == "l10":
            return BallLife.sources
        if self.model == "wear":
            return WearLife.sources
        return RatedLife.sources if self.capped_by_wear else ("life",)

    def _band(self, name: str) -> tuple[float, float]:
        """A wear quantity at the high and the low end of the wear rate's range."""
        value = float(self.batch.column(name)[self.k])
        low, high = life_band(self.screw)
        return value * low, value * high

    @cached_property
    def travel_m(self) -> tuple[float, float]:
        """The band of travel: the wear band, or the seed's rated band with each end at
        most the wear band's (no cap where the nut has no wear rate)."""
        if self.model == "l10":
            travel = self._l10_travel_m()
            return travel, travel
        low, high = self._band("wear_travel_m")
        if self.model == "rated":
            seed = cast(float, self.screw.life_min_m), cast(float, self.screw.life_max_m)
            return float(np.fmin(seed[0], low)), float(np.fmin(seed[1], high))
        return low, high

    @property
    def capped_by_wear(self) -> bool:
        """Whether the nut's wear life cuts the seed's rated travel at either end of the
        band (``travel_m``): the numbers are then the wear's, at its assumed rate."""
        if self.model != "rated":
            return False
        seed = cast(float, self.screw.life_min_m), cast(float, self.screw.life_max_m)
        low, high = self.travel_m
        return low < seed[0] or high < seed[1]

    @property
    def travel_min_m(self) -> float:
        return self.travel_m[0]

    @property
    def travel_max_m(self) -> float:
        return self.travel_m[1]

    def _years(self, end: int) -> float | None:
        """The travel band's low (``end`` 0) or high (1) end in years of the duty (None
        without one: the travel is then not worked out for it)."""
        stroke, cycles = self.batch.duty
        if not (stroke and cycles):
            return None
        return number(life.life_years(self.travel_m[end], stroke, cycles))

    @property
    def years_min(self) -> float | None:
        return self._years(0)

    @property
    def years_max(self) -> float | None:
        return self._years(1)

    @property
    def hours(self) -> tuple[float, float]:
        """Hours of operation until the travel is done: the cycles times the time of one
        (every move, ramp and dwell: ``motion.move_profile``) where the move is given, as
        the years count them; otherwise the travel at the top speed reached."""
        low, high = self.travel_m
        p, cycles = motion.move_profile(self.app), self.cycles
        if p is None or cycles is None:
            speed = self.batch.reached_speed_m_s
            return low / speed / life.SECONDS_PER_HOUR, high / speed / life.SECONDS_PER_HOUR
        return (
            life.operating_hours(cycles[0], p.cycle_time_s),
            life.operating_hours(cycles[1], p.cycle_time_s),
        )

    @property
    def cycles(self) -> tuple[float, float] | None:
        """Cycles (out and back over the stroke) until the travel is done."""
        stroke = motion.equivalent_stroke(self.app)
        if not stroke:
            return None
        low, high = self.travel_m
        return low / (2.0 * stroke), high / (2.0 * stroke)
