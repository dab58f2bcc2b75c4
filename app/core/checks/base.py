"""What a check is: one unit that says when it applies, its demand and capacity over
arrays, its explanation and fix, its formula and the catalog fields it reads.

Utilisation is demand / capacity, so a value above 1 fails. A capacity of NaN means the
limit does not exist for that candidate (e.g. no PV limit published): the check does not
apply to it. A yes/no check has no demand or capacity, only ``flagged`` failures.
"""

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import ClassVar, Literal

import numpy as np

from app.core import input_search, load_caps, motion
from app.core.formulas import column_rules
from app.core.model import FIX_MARGIN, FIXITY_ORDER, Application, EndFixity, ScrewSpec
from app.core.phrase import Amount, Phrase, Quantity
from app.core.quantities import Quantities, compression_sign
from app.core.reach import Reach
from app.core.table import Array, CandidateTable, Mask, filled

__all__ = [
    "FIX_MARGIN",
    "MARGIN_NOTE",
    "Application",
    "Array",
    "CandidateTable",
    "Check",
    "EndFixity",
    "Mapping",
    "Mask",
    "Measure",
    "Quantities",
    "Reach",
    "ScrewSpec",
    "allowed_load",
    "at_least",
    "at_most",
    "least",
    "lighter",
    "makers_stress",
    "most",
    "run_at_most",
    "same",
    "searched_limits",
    "sentence",
    "stiffer_fixity",
    "value_alone",
]

#: A limit rejects a candidate; advice is reported beside it.
Kind = Literal["limit", "advice"]
MARGIN_NOTE = " Each figure keeps a 5 % margin to its limit."


def at_most(limit: float) -> float:
    """A proposed upper value, ``FIX_MARGIN`` below the ``limit`` it must not exceed."""
    return limit * (1.0 - FIX_MARGIN)


def at_least(limit: float) -> float:
    """A proposed lower value, ``FIX_MARGIN`` above the ``limit`` it must reach."""
    return limit * (1.0 + FIX_MARGIN)


def most(limit: float, quantity: Quantity) -> Amount:
    """A fix's upper figure, ``at_most`` the ``limit``, written rounded down: the figure
    the reader takes keeps the margin the fix promises."""
    return Amount(at_most(limit), quantity, "down")


def least(limit: float, quantity: Quantity) -> Amount:
    """A fix's lower figure, ``at_least`` the ``limit``, written rounded up."""
    return Amount(at_least(limit), quantity, "up")


# Not frozen: a frozen dataclass sets each field through object.__setattr__, and a
# select builds one per check. Nothing assigns to one.
@dataclass(slots=True)
class Measure:
    """A check over many candidates: where it applies, demand and capacity, or failures."""

    applicable: Mask
    demand: Array | None = None
    capacity: Array | None = None
    flagged: Mask | None = None

    def utilization(self) -> Array | None:
        """demand / capacity (NaN where the limit does not exist); None for yes/no. The
        caller silences NumPy's warnings for the missing limits (``np.errstate``)."""
        if self.demand is None or self.capacity is None:
            return None
        return self.demand / self.capacity


class Check:
    """Base of every check. Subclasses set the class attributes and override the methods.

    ``formula`` is the text shown beside the numbers. For a numeric check it is
    ``"demand = ...; capacity = ..."``, each side an expression in the names that
    ``symbols`` binds, so a test evaluates the text and compares it with ``measure``.
    """

    name: ClassVar[str]
    label: ClassVar[str]
    description: ClassVar[str]
    kind: ClassVar[Kind] = "limit"
    quantity: ClassVar[Quantity | None] = None
    formula: ClassVar[str]
    source: ClassVar[str]
    sources: ClassVar[tuple[str, ...]] = ()
    #: catalog fields the capacity rests on; empty: the capacity is the axis's (below)
    capacity_sources: ClassVar[tuple[str, ...]] = ()
    #: the axis's value the capacity is, where no catalog field gives it: its provenance
    #: comes with the axis (``AxisProvenance``: typed in, or a library motor's or support
    #: unit's); empty, or not in that mapping: the user's input
    capacity_given: ClassVar[str] = ""
    #: the catalog values whose lack stops the check, where not its capacity's (empty:
    #: those, else every catalog value it reads): named when it could not run
    needs: ClassVar[tuple[str, ...]] = ()
    #: when this check excludes every screw of the catalog: why no screw can do it
    #: and what kind of drive could (lower case, no full stop); empty: the remedy says
    #: only that the check excludes every screw
    why_none: ClassVar[str] = ""
    #: ``why_none`` where only ball screws were screened, for a check whose ``why_none``
    #: suggests one (empty: ``why_none`` serves both)
    why_none_ball: ClassVar[str] = ""
    #: whether the check judges the motor rather than the screw (another motor may
    #: still drive the screws it rejects)
    judges_motor: ClassVar[bool] = False
    #: whether a motor's own values can clear the check where it fails without one (a
    #: stepper's energised holding torque or its detent torque holds the load): the
    #: screw + motor pairs screen such a screw with every motor
    motor_may_clear: ClassVar[bool] = False
    #: whether a slower top speed may clear it (the motor's curve and speed, the step
    #: rate, whirl, a ball's DN, a nut's PV, pressure, sliding speed and heat): the
    #: no-pass summary then tries the speeds at which such screws fit their motor
    slower_may_clear: ClassVar[bool] = False
    #: the check that judges the same limit of a nut this one has no value for (the
    #: seed's PV and an ISO nut's flank pressure against its material's PV): where that
    #: one runs, this one not running is no gap in the verdict
    judged_instead_by: ClassVar[str] = ""

    def applies(self, app: Application) -> bool:
        """Whether the check runs at all for this application (default: always)."""
        return True

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        raise NotImplementedError

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        """Values of the names in ``formula`` (SI), for checking the text against the code."""
        return {}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        raise NotImplementedError

    def left_out(self, app: Application, s: ScrewSpec, r: Quantities[float]) -> tuple[str, ...]:
        """The catalog values ``s`` lacks that the check ran without, their terms left
        out of its judgement (catalog keys); empty where it judged every term."""
        return ()

    def fix(
        self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach
    ) -> Phrase | None:
        """What would make a failing candidate pass, within what the catalog offers. A fix
        that offers another lead of the size names it ``{lead}``: the candidate's fix
        then says how the screw of that lead fares on the axis (``batch.Slot.fix_of``)."""
        return None

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float] | None:
        """Application inputs (core names, SI), any one of which would clear the check."""
        return None

    @property
    def offers_inputs(self) -> bool:
        """Whether the check can name an input that clears it (it has ``input_limits`` of
        its own): a check that cannot (self-locking, a temperature) is cleared by another
        screw, nut or motor only."""
        return type(self).input_limits is not Check.input_limits


def makers_stress(s: ScrewSpec) -> float:
    """The makers' allowed axial stress at the root of ``s`` [Pa]
    (``column_rules.makers_allowed_stress``): THK's P2 over the root area, 147.7 MPa, for a
    ball screw whose family declares no buckling rule; else inf (no cap)."""
    hiwin = s.buckling_rule == column_rules.HIWIN_BUCKLING_RULE
    return float(column_rules.makers_allowed_stress(s.screw_type == "ball", hiwin))


def everywhere(t: CandidateTable) -> Mask:
    return np.ones(len(t), dtype=bool)


def same(t: CandidateTable, value: float | None) -> Array:
    """An application value for every candidate (NaN when not given)."""
    return filled(len(t), np.nan if value is None else value)


def where_given(capacity: Array) -> Mask:
    """Candidates that have this limit (not NaN)."""
    return ~np.isnan(capacity)


def lighter(app: Application) -> str:
    """The words for what lowers a torque besides the acceleration and the lead: the
    load where the axis has one, the moving mass where it has one (its m a, and its
    weight on a vertical axis); empty for neither.

    >>> lighter(Application(load_n=0.0, speed_m_s=0.1, length_m=0.5, moving_mass_kg=2.0))
    'moving mass'
    """
    moves = app.moves
    loaded = app.load_n > 0.0 if not moves else any(m.load_n > 0.0 for m in moves)
    heavy = app.moving_mass_kg > 0.0 if not moves else any(m.moving_mass_kg > 0.0 for m in moves)
    return " or ".join(word for word, has in (("load", loaded), ("moving mass", heavy)) if has)


def run_at_most(app: Application) -> str:
    """The words that cap the speed: of the move, or of every move of a cycle of the
    user's own (whose speeds the speed input does not set).

    >>> run_at_most(Application(load_n=1.0, speed_m_s=0.1, length_m=0.5))
    'Run at most'
    """
    return "Run every move at most" if app.moves else "Run at most"


def load_input(app: Application, allowed_n: float, compressive: bool = False) -> dict[str, float]:
    """The largest user load at which the peak thrust (``compressive``: the peak thrust
    that compresses the screw) meets ``allowed_n``, as an input change; empty when no load
    does (the moving mass's m a alone exceeds it)."""
    forms = motion.nut_force_forms(app)
    if compressive:
        c = compression_sign(app)
        bounds = [(c * g, c * h) for g, h in forms]
    else:
        bounds = [*forms, *((-g, -h) for g, h in forms)]
    load = load_caps.largest_load(bounds, allowed_n)
    return {} if load is None else {"load_n": load}


def allowed_load(app: Application, cap_n: float, name: str = "cap") -> Phrase:
    """The words that cap the load for a limit ``cap_n`` on the peak thrust [N], kept
    ``FIX_MARGIN`` inside it: "the load may be at most {cap}" where the thrust is the load
    alone; where it is more (a weight held, m a on the ramps), the thrust's cap and the
    axial load that keeps it (``load_input``), or that the moving mass alone exceeds it;
    in a cycle of moves, each carrying its own load, that the moves' masses and loads
    exceed it. The cap's field is ``name``."""
    cap = at_most(cap_n)
    load = load_input(app, cap).get("load_n")
    values: dict[str, Amount | str | Phrase] = {name: Amount(cap, "force", "down")}
    if load is not None and math.isclose(load, cap):
        return Phrase("the load may be at most {" + name + "}", values)
    if app.moves:  # each move carries its own load: the load input moves no thrust
        return Phrase(
            "the peak thrust may be at most {" + name + "}, which the moves' own masses "
            "and loads exceed",
            values,
        )
    if load is None or load < 0.0:
        return Phrase(
            "the peak thrust may be at most {" + name + "}, which the moving mass alone exceeds",
            values,
        )
    values["load"] = Amount(load, "force", "down")
    return Phrase(
        "the peak thrust may be at most {" + name + "} (an axial load of at most {load})",
        values,
    )


def sentence(template: str, values: dict[str, "Amount | str"]) -> Phrase:
    """A phrase that starts with a capital, also when it starts with a word-valued field."""
    if template.startswith("{"):
        name = template[1 : template.index("}")]
        word = values.get(name)
        if isinstance(word, str):
            values = {**values, name: word[:1].upper() + word[1:]}
        return Phrase(template, values)
    return Phrase(template[:1].upper() + template[1:], values)


def stiffer_fixity(app: Application, passes: Callable[[EndFixity], bool]) -> EndFixity | None:
    """The first end fixity stiffer than ``app``'s for which ``passes`` holds (the check
    with its fix margin), else None (an intermediate support is needed)."""
    stiffer = FIXITY_ORDER[FIXITY_ORDER.index(app.end_fixity) + 1 :]
    return next((f for f in stiffer if passes(f)), None)


def searched_limits(
    check: Check,
    app: Application,
    s: ScrewSpec,
    lower: tuple[str, ...],
    raise_: tuple[str, ...] = (),
    share: float = 1.0,
    convex: bool = False,
) -> dict[str, float]:
    """The value of each input of ``lower`` (below its own) and of ``raise_`` (above
    it) at which ``check`` of ``s`` meets ``share`` of its limit, found by working the
    check again (``input_search``: its own utilisation, demand / capacity, at each
    trial); an input no value of which meets it is left out. ``share`` 1 is the limit
    (``input_limits``), 1 / (1 + FIX_MARGIN) a fix's figure; ``convex``: the utilisation
    is convex in the inputs of ``lower`` (``input_search.largest_below``)."""

    def used(a: Application, t: CandidateTable, q: Quantities[Array]) -> float:
        u = check.measure(a, t, q).utilization()
        return math.nan if u is None else float(u[0])

    found = {k: input_search.largest_below(app, s, k, used, share, convex) for k in lower}
    found |= {k: input_search.smallest_above(app, s, k, used, share) for k in raise_}
    return {k: v for k, v in found.items() if v is not None}


#: The words and the quantity of each input a fix may name by its value alone.
ALONE_WORDS: dict[str, tuple[str, Quantity]] = {
    "dwell_s": ("a dwell", "time"),
    "accel_m_s2": ("an acceleration", "accel"),
    "load_n": ("a load", "force"),
}


def value_alone(app: Application, figures: Mapping[str, float]) -> tuple[str, dict[str, Amount]]:
    """The sentence naming each input of ``figures`` (a fix's values, its margin kept
    already: ``searched_limits``) that alone clears a check, "of at most" one below its
    value in ``app``, "of at least" one above, with its values rounded away from the
    limit; empty for none.

    >>> app = Application(load_n=10.0, speed_m_s=0.1, length_m=0.5)
    >>> value_alone(app, {"load_n": 5.0})[0]
    ' Alone, a load of at most {load_n} would do.'
    """
    named = [(k, v) for k, v in figures.items() if k in ALONE_WORDS]
    if not named:
        return "", {}
    parts, values = [], {}
    for key, value in named:
        word, quantity = ALONE_WORDS[key]
        lower = value < float(getattr(app, key))
        parts.append(f"{word} of at {'most' if lower else 'least'} {{{key}}}")
        values[key] = Amount(value, quantity, "down" if lower else "up")
    return " Alone, " + " or ".join(parts) + " would do.", values
