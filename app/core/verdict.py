"""Why this screw, in two lines: what governs it and by how much, which assumed catalog
values that rests on, and what to watch.

``verdict(candidate)`` reads a candidate record (``Record``, the part of
``app.core.record.Candidate`` it reads, so the record imports the verdict, not back): its
governing check (the rejecting check closest to its limit), its other checks, the
provenance of the catalog values each check reads and the ranged values its pass hinges
on (``app.core.robustness``). Catalog keys (``pv_limit_mpa_m_s``, ``dynamic_load_lbf``)
are named in words (``value_label``); the sentences are ``Phrase``s, rendered at the edge.
"""

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Protocol

from app.core import holding, motion
from app.core.batch import CheckResult
from app.core.checks.base import Check
from app.core.model import Application, Provenance, ScrewSpec
from app.core.phrase import Amount, Phrase, in_words, join, plural
from app.core.sections import Life
from app.core.wording import percent, share, value_label

#: Provenance kinds a result may rest on without having been measured for this part.
UNCERTAIN = ("assumed",)
#: The screw's value behind each catalog key a check reads that a screw may lack (None or
#: an empty table: not given), to say why a check could not run.
SPEC_VALUES: Mapping[str, str] = {
    "allowed_wear": "allowed_wear_fraction",
    "bearing_pressure": "bearing_pressure_table",
    "bearing_pv_limit": "nut_pv_limit_pa_m_s",
    "design_load": "design_load_n",
    "dynamic_pressure": "dynamic_pressure_pa",
    "lead_accuracy": "lead_accuracy_m_per_m",
    "life": "life_min_m",
    "max_length": "max_length_m",
    "max_pressure": "max_pressure_pa",
    "max_sliding_speed": "max_sliding_speed_m_s",
    "nut_length": "nut_length_m",
    "outgassing": "outgassing",
    "pitch": "pitch_m",
    "pv_limit": "pv_limit_pa_m_s",
    "repeatability": "repeatability_m",
    "temperature_range": "temperature_max_c",
    "thermal_conductivity": "thermal_conductivity_w_m_k",
    "traverse_speed": "traverse_bands",
    "wear_rate": "wear_rate_m2_n",
    "yield_strength": "yield_strength_pa",
}


@dataclass(frozen=True, slots=True)
class Rest:
    """A catalog value the governing result rests on: its key, its name in words, its
    provenance kind, and whether the pass fails at one end of its range (``hinges``)."""

    field: str
    label: str
    kind: str
    hinges: bool


@dataclass(frozen=True, slots=True)
class Skip:
    """A check that runs for the application but could not for this screw: its name,
    its label and the values the screw lacks, in words."""

    check: str
    label: str
    missing: tuple[str, ...]

    def phrase(self) -> str:
        """'Nut contact pressure (no nut length or pitch)'."""
        return f"{self.label} (no {in_words(self.missing, 'or')})"


#: The checks of a sliding nut's ratings (PV, flank pressure, sliding and traverse speed,
#: design load, wear, rated travel, friction heat): a ball nut rolls and has none of
#: these ratings (its own are the L10 life, the static rating and the DN speed), so for
#: a ball screw they do not apply: not a check that could not run.
LEADSCREW_NUT_CHECKS = frozenset(
    {
        "pv",
        "bearing_pressure",
        "max_sliding_speed",
        "traverse_speed",
        "design_load",
        "wear_life",
        "life",
        "nut_heat",
    }
)
NOT_APPLICABLE_TEXT = "Leadscrew-nut checks do not apply to a ball screw."


def not_applicable(checks: Sequence[Check], screw: ScrewSpec) -> tuple[str, ...]:
    """The labels of ``checks`` that do not apply to ``screw``: a leadscrew nut's checks
    on a ball screw; none for a leadscrew."""
    if screw.screw_type != "ball":
        return ()
    return tuple(c.label for c in checks if c.name in LEADSCREW_NUT_CHECKS)


#: Thread values a nut rating is read over (the engaged flank area): missing, they
#: stop the check whatever the nut's rating.
THREAD_VALUES = ("nut_length", "pitch")


def _lacks(screw: ScrewSpec, key: str) -> bool:
    attr = SPEC_VALUES.get(key)
    return attr is not None and getattr(screw, attr) in (None, ())


def missing_values(check: Check, screw: ScrewSpec) -> tuple[str, ...]:
    """The values ``check`` needs that ``screw`` lacks, in words, each once: its
    capacity's values (the limit it is held to) and the thread values its rating is read
    over; when one of its ratings is there, only the thread values it lacks. A check that
    declares what it ``needs`` needs each of them: every one it lacks is named."""
    thread = [k for k in THREAD_VALUES if k in check.sources or k in check.capacity_sources]
    if check.needs:
        needed = [*check.needs, *thread]
        return tuple(dict.fromkeys(value_label(k) for k in needed if _lacks(screw, k)))
    declared = check.capacity_sources
    ratings = [k for k in declared if k not in THREAD_VALUES] or [
        k for k in check.sources if k not in THREAD_VALUES and k in SPEC_VALUES
    ]
    rated = any(not _lacks(screw, k) for k in ratings if k in SPEC_VALUES)
    needed = thread if rated else [*ratings, *thread]
    return tuple(dict.fromkeys(value_label(k) for k in needed if _lacks(screw, k)))


def skips(checks: Sequence[Check], screw: ScrewSpec) -> tuple[Skip, ...]:
    """Each check in ``checks`` that could not run for ``screw`` for want of a value,
    with the values it lacks (a check with nothing to judge on this screw, such as oil on
    a nut that suits oil, is not a skip, nor a check that does not apply to its kind of
    screw: ``not_applicable``), nor a check whose limit another that ran judges for
    this screw (``Check.judged_instead_by``: an ISO nut's PV, in its flank pressure)."""
    inapplicable = set(not_applicable(checks, screw))
    idle = {c.name for c in checks}
    found = (
        Skip(c.name, c.label, missing_values(c, screw))
        for c in checks
        if c.label not in inapplicable
        and not (c.judged_instead_by and c.judged_instead_by not in idle)
    )
    return tuple(skip for skip in found if skip.missing)


def partial(checks: Sequence[CheckResult]) -> tuple[Skip, ...]:
    """The checks that ran without a catalog value the screw lacks, each with the values
    whose terms they left out, in words (``Check.left_out``: a positioning accuracy
    judged on the known terms, without the lead error of a screw with no lead accuracy)."""
    found = ((c, c.left_out) for c in checks)
    return tuple(
        Skip(c.name, c.label, tuple(dict.fromkeys(map(value_label, gaps))))
        for c, gaps in found
        if gaps
    )


def summary(
    passed: bool,
    checks: Sequence[CheckResult],
    skipped: Sequence[Skip],
    inapplicable: Sequence[str] = (),
    judged_in_part: Sequence[Skip] = (),
) -> Phrase:
    """The one-line summary every page shows: never "passes every check" when a check
    could not run or ran without a value the screw lacks; then the checks that did not run
    and why, those that judged the known terms alone and what they left out, and once, for
    a ball screw, that the leadscrew nut's checks do not apply (they are not counted as
    not checked).

    A pass with nothing skipped is "Passes every check."; with skipped checks it is
    "Passes the N limits that ran; not checked: ..." (advice, which never rejects, counted
    apart: the detail lists every check that ran).
    """
    limits = [c for c in checks if c.kind == "limit"]
    if not passed:
        failed = [c.label for c in checks if not c.passed and c.kind == "limit"]
        head = f"Fails {', '.join(failed)}." if failed else "Fails."
    elif not skipped and not judged_in_part:
        head = "Passes every check."
    else:
        advice = len(checks) - len(limits)
        besides = (
            f", besides {advice} {plural(advice, 'piece', 'pieces')} of advice" if advice else ""
        )
        head = f"Passes the {len(limits)} limits that ran{besides}."
    parts = [head]
    if skipped:
        parts.append(f"Not checked: {'; '.join(s.phrase() for s in skipped)}.")
    if judged_in_part:
        known = "; ".join(s.phrase() for s in judged_in_part)
        parts.append(f"Judged without a value the screw lacks, its term left out: {known}.")
    if inapplicable:
        parts.append(NOT_APPLICABLE_TEXT)
    return Phrase(" ".join(parts))


@dataclass(frozen=True)
class Verdict:
    """A candidate's verdict: the governing check (name, label, utilisation, margin =
    1 - utilisation: the share of the limit left), what it rests on, what to watch, and
    all of it as one or two sentences (``text``). The sentence, the checks that could not
    run and the summary line are worked out when first read: the compact select gives the
    governing check's parts alone."""

    governs: str | None
    governs_label: str
    utilization: float | None
    margin: float | None
    rests_on: tuple[Rest, ...]
    watch: tuple[Phrase, ...]
    #: whether the candidate passes, and its governing check (the sentence's words)
    passed: bool
    governing: CheckResult | None
    #: the screw, its checks, and the checks that run for the application but not for it
    screw: ScrewSpec = field(repr=False, compare=False)
    checks: tuple[CheckResult, ...] = field(repr=False, compare=False)
    runnable: tuple[Check, ...] = field(repr=False, compare=False)

    @cached_property
    def text(self) -> Phrase:
        return sentence(self.governing, self.passed, self.rests_on, self.watch)

    @cached_property
    def skipped(self) -> tuple[Skip, ...]:
        """The checks that could not run for this screw, each with what it lacks."""
        return skips(self.runnable, self.screw)

    @cached_property
    def partial(self) -> tuple[Skip, ...]:
        """The checks that ran without a value this screw lacks, each with what it left
        out (``partial``)."""
        return partial(self.checks)

    @cached_property
    def not_applicable(self) -> tuple[str, ...]:
        """The labels of the checks that do not apply to this kind of screw."""
        return not_applicable(self.runnable, self.screw)

    @cached_property
    def summary(self) -> Phrase:
        return summary(self.passed, self.checks, self.skipped, self.not_applicable, self.partial)


class Record(Protocol):
    """What a verdict reads of a candidate's record."""

    @property
    def app(self) -> Application: ...
    @property
    def screw(self) -> ScrewSpec: ...
    @property
    def value_provenance(self) -> Mapping[str, Provenance]: ...
    @property
    def passed(self) -> bool: ...
    @property
    def checks(self) -> tuple[CheckResult, ...]: ...
    @property
    def governing(self) -> CheckResult | None: ...
    @property
    def warnings(self) -> tuple[CheckResult, ...]: ...
    @property
    def skipped(self) -> tuple[Check, ...]: ...
    @property
    def hinges_on(self) -> tuple[str, ...]: ...
    @property
    def self_locking_with_margin(self) -> bool: ...
    @property
    def brake_to_fit_nm(self) -> float: ...
    @property
    def life(self) -> Life | None: ...


def rests_on(
    governing: CheckResult | None, provenance: Mapping[str, Provenance], hinges: Sequence[str]
) -> tuple[Rest, ...]:
    """The assumed values the governing check reads (the catalog's, and the axis's value
    its capacity is), then the ranged values the pass hinges on (robustness), each once."""
    found: dict[str, Rest] = {}
    for key in () if governing is None else governing.sources:
        p = provenance.get(key)
        if p is not None and p.kind in UNCERTAIN:
            label = value_label(key)
            found[label] = Rest(key, label, p.kind, False)
    for key in hinges:
        label = value_label(key)
        kind = found[label].kind if label in found else "assumed range"
        found[label] = Rest(key, label, kind, True)
    return tuple(found.values())


def runner_up(checks: Sequence[CheckResult], governing: CheckResult | None) -> CheckResult | None:
    """The numeric limit closest to its own, after the governing check."""
    others = [
        c for c in checks if c is not governing and c.kind == "limit" and c.utilization is not None
    ]
    return max(others, key=lambda c: c.utilization or 0.0, default=None)


def watch_list(c: Record) -> tuple[Phrase, ...]:
    """What to keep an eye on: failed advice, the next-closest limit, and how the load is
    held with the power off."""
    found = [Phrase(f"{w.label} (advice)") for w in c.warnings]
    second = runner_up(c.checks, c.governing)
    if second is not None and second.utilization is not None:
        found.append(Phrase(f"{second.label} next, at {percent(second.utilization)}"))
    if motion.holds_a_load(c.app) and not c.self_locking_with_margin:
        found.append(_held_power_off(c))
    short = _unchecked_life(c)
    if short is not None:
        found.append(short)
    return tuple(found)


def _held_power_off(c: Record) -> Phrase:
    """How a load the thread does not hold with margin is held with the power off: by the
    brake or the detent torque given (``holding.unpowered_holder``) at its utilisation
    where it holds, else the brake to fit, a brake's safety factor times the torque to hold (as the
    holding check sizes a brake, ``holding.holding``), rounded up."""
    holder = holding.unpowered_holder(c.app)
    name = {"brake": "holding", "detent": "holding_power_off"}.get(holder or "")
    held = next((k for k in c.checks if k.name == name), None)
    if held is not None and held.utilization is not None and held.passed:
        what = "brake" if holder == "brake" else "detent torque"
        return Phrase(f"power off: held by the {what} at {percent(held.utilization)}")
    brake = Amount(c.brake_to_fit_nm, "torque", "up")
    return Phrase("back-drives: a brake of at least {t} holds it power-off", {"t": brake})


def life_rests_on(life: Life, provenance: Mapping[str, Provenance]) -> tuple[str, ...]:
    """The assumed values, in words, that ``life`` is worked from (``Life.sources``)."""
    found = (k for k in life.sources if (p := provenance.get(k)) and p.kind in UNCERTAIN)
    return tuple(dict.fromkeys(map(value_label, found)))


def _unchecked_life(c: Record) -> Phrase | None:
    """With a duty but no required life (no life check runs): the life at the duty, the
    low end of its band, so that a short-lived screw is seen where its verdict is read,
    and the assumed values it is worked from (a wear life at an assumed wear rate)."""
    if not motion.life_unchecked(c.app) or c.life is None or c.life.years_min is None:
        return None
    years = Amount(c.life.years_min, "years")
    assumed = life_rests_on(c.life, c.value_provenance)
    basis = f" (from assumed {', '.join(assumed)})" if assumed else ""
    text = f"life {{y}} at this duty{basis}, not checked (no required life given)"
    return Phrase(text, {"y": years})


def sentence(
    governing: CheckResult | None, passed: bool, rest: Sequence[Rest], watch: Sequence[Phrase]
) -> Phrase:
    """The verdict in words: governs (utilisation, margin); rests on; watch."""
    if governing is None:
        head = Phrase("No limit applies beyond the catalog's own.")
    elif governing.utilization is None:
        state = "holds" if governing.passed else "fails"
        head = Phrase(f"Governed by {governing.label}: {state}.")
    else:
        u = governing.utilization
        verb = "Governed by" if passed else "Fails on"
        margin = f"{share(1.0 - u)} margin" if u <= 1.0 else f"{share(u - 1.0)} over"
        head = Phrase(f"{verb} {governing.label} at {percent(u)} ({margin}).")
    parts = [head]
    assumed = [r.label for r in rest if not r.hinges]
    hinged = [r.label for r in rest if r.hinges]
    if assumed:
        parts.append(Phrase(f"Rests on assumed {', '.join(assumed)}."))
    if hinged:
        parts.append(Phrase(f"Marginal: fails at one end of the range of {', '.join(hinged)}."))
    if watch:
        parts.append(Phrase("Watch: {w}.", {"w": join(list(watch), "; ")}))
    return join(parts)


def verdict(c: Record) -> Verdict:
    """The verdict of candidate record ``c``."""
    g = c.governing
    u = None if g is None else g.utilization
    return Verdict(
        governs=None if g is None else g.name,
        governs_label="" if g is None else g.label,
        utilization=u,
        margin=None if u is None else 1.0 - u,
        rests_on=rests_on(g, c.value_provenance, c.hinges_on),
        watch=watch_list(c),
        passed=bool(c.passed),
        governing=g,
        screw=c.screw,
        checks=c.checks,
        runnable=c.skipped,
    )
