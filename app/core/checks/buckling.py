"""Compressive peak thrust against the allowed fraction of the column's critical load:
Euler when the screw is slender, Johnson's parabola when it is short."""

import math

from app.core.checks.base import (
    MARGIN_NOTE,
    Application,
    Array,
    CandidateTable,
    Check,
    EndFixity,
    Mapping,
    Measure,
    Quantities,
    Reach,
    ScrewSpec,
    at_least,
    load_input,
    makers_stress,
    sentence,
    stiffer_fixity,
)
from app.core.column import column_length
from app.core.formulas import buckling, column_rules
from app.core.input_rules import least_inputs
from app.core.phrase import Amount, Phrase


class ColumnBuckling(Check):
    name = "buckling"
    why_none = (
        "the thrust buckles every screw of this length: consider mounting it so that it pulls"
        " (tension), a screw support, or a ball screw"
    )
    why_none_ball = (
        "the thrust buckles every ball screw of this length: consider mounting it so that "
        "it pulls (tension), a screw support, or a roller screw"
    )
    label = "Column buckling"
    description = (
        "A screw pushed in compression buckles as a column. Slender screws follow Euler; "
        "short ones (below the transition slenderness) follow Johnson's parabola, which "
        "ends at the yield load of the root section. The allowed force is a fraction (the "
        "buckling factor) of that critical load, judged at the largest thrust that pushes "
        "the screw onto its thrust bearing in any segment of either move. A ball screw's "
        "critical load is at most its maker's Euler load (HIWIN's rule where its family "
        "declares it, else the lowest published rule, Rockford's and Thomson's), and its "
        "allowed force, where its family declares no rule, at most THK's permissible "
        "P2 = 116 d1^2 N (147.7 MPa on the root area). A leadscrew's critical load is at "
        "most its makers' Euler load for its class of steel (Thomson's and Nook's for "
        "steel, W.M. Berg's for stainless)."
    )
    quantity = "force"
    formula = (
        "F = F_c; F_allowed = min(SF * min(pi^2 * E * A / s^2 if s >= sqrt(2 * pi^2 * E / S_y) "
        "else A * (S_y - (S_y * s / (2 * pi))^2 / E), pi^2 * E_m * A / s^2), sigma_m * A)"
    )
    source = (
        "Euler column (Timoshenko & Gere); Johnson parabola and transition slenderness, "
        "Shigley's Mechanical Engineering Design, 9th ed., sec. 4-11 to 4-13; a ball "
        "screw's at most its maker's Euler load: HIWIN BS-08-2-EN-1704-K F 3.25 where its "
        "family declares it, else the lowest published, Rockford Ball Screw 'How To Size A "
        "Ball Screw' step 9 and Thomson (14.03e6 C d^4 / L^2, E_m = 199.7 GPa), and its "
        "allowed load at most THK's P2 = 116 d1^2 N (General Catalog, Ball Screw, A15-30, "
        "formula 6; sigma_m = 147.7 MPa); a leadscrew's at most its makers' for its class "
        "of steel: Thomson's and Nook's 14.03e6 F_c d^4 / L^2 for steel (E_m = 199.7 GPa), "
        "W.M. Berg's Maximum Column Load Formula 13.4e6 K d^4 / D^2 for stainless "
        "(E_m = 190.7 GPa)"
    )
    sources = ("root_diameter", "youngs_modulus", "yield_strength")
    capacity_sources = ("root_diameter", "youngs_modulus", "yield_strength")

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        pushed = q.axis.compressive_force_n > 0.0
        return Measure(pushed, q.axis.compressive_force_n, q.column.allowed_load_n)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "F_c": q.axis.compressive_force_n,
            "SF": app.buckling_safety_factor,
            "E": t.youngs_modulus_pa,
            # the makers' column modulus (a leadscrew's that of its class of steel), which
            # rates the column no higher than its makers' Euler load
            "E_m": t.makers_modulus_pa,
            "A": buckling.root_area(t.root_diameter_m),
            "s": buckling.slenderness(t.root_diameter_m, column_length(app), app.end_fixity),
            "S_y": t.yield_strength_pa,
            # the makers' allowed root stress (inf: none published), THK's P2 over A
            "sigma_m": t.makers_stress_pa,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        short = r.column.slenderness < r.column.transition_slenderness
        model = "Johnson, short column" if short else "Euler"
        # held to THK's P2 below the buckling factor's share of the critical load
        capped = r.column.allowed_load_n < buckling.allowed_buckling_load(
            r.column.critical_load_n, app.buckling_safety_factor
        )
        limit = "THK's P2 = 116 d1^2 N, below " if capped else ""
        rule = _makers_rule(app, s, r)
        span = (
            ""
            if app.bearing_to_nut_m is None
            else ", over {col} from the thrust bearing to the nut"
        )
        return Phrase(
            "Peak thrust {f} in compression "
            + verb
            + " the allowed {allowed} ("
            + limit
            + "{sf} x "
            + model
            + " {f_cr}"
            + (f" with E {{e_m}}, {rule}" if rule else "")
            + ", slenderness {s}"
            + span
            + ").",
            {
                "e_m": Amount(_modulus(s), "pressure"),
                "f": Amount(r.axis.compressive_force_n, "force"),
                "allowed": Amount(r.column.allowed_load_n, "force"),
                "sf": Amount(app.buckling_safety_factor, "factor"),
                "f_cr": Amount(r.column.critical_load_n, "force"),
                "s": Amount(r.column.slenderness, "factor"),
                "col": Amount(r.column.column_length_m, "length"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        def allowed(fixity: EndFixity) -> float:
            critical = buckling.column_critical_load(
                _modulus(s), s.root_diameter_m, column_length(app), fixity, _yield(s)
            )
            return min(app.buckling_safety_factor * critical, _most_n(s, s.root_diameter_m))

        force_n = at_least(r.axis.compressive_force_n)
        d_column = buckling.min_root_diameter_for_column(
            force_n / app.buckling_safety_factor,
            _modulus(s),
            column_length(app),
            app.end_fixity,
            _yield(s),
        )
        # the root whose area carries the thrust at the makers' allowed stress (THK's P2)
        d_min = max(d_column, (4.0 * force_n / (math.pi * makers_stress(s))) ** 0.5)
        length_m = _max_length(app, s, r, force_n)
        values: dict[str, Amount | str] = {
            "length": Amount(length_m, "length", "down"),
            "fixity": app.end_fixity,
        }
        options = []
        if d_min <= reach.max_root_diameter_m:
            values["d"] = Amount(d_min, "length", "up")
            options.append("use a root diameter of at least {d}")
        spanned = app.bearing_to_nut_m is not None
        what = "span from the thrust bearing to the nut" if spanned else "column"
        # a stiffer mounting is offered only when it keeps the margin at this length
        stiffer = stiffer_fixity(app, lambda f: force_n <= allowed(f))
        if stiffer is not None:
            values["stiffer"] = stiffer
            stiffer_m = _max_length(app, s, r, force_n, stiffer)
            values["stiffer_length"] = Amount(stiffer_m, "length", "down")
            options.append(
                f"mount the ends {{stiffer}} ({what} at most {{stiffer_length}} with the ends "
                "{stiffer})"
            )
        # no column of this screw carries the thrust when its root yields first (or
        # passes the makers' allowed stress): no length or support helps, less load does
        if length_m <= 0.0:
            options.append("reduce the load")
        else:
            shorter = f"{what} at most {{length}} with the ends {{fixity}}"
            # a screw shorter than the stroke is no screw the inputs accept: a support then;
            # nor is a span to the thrust bearing shorter than the nut's travel
            too_short = length_m < least_inputs(app).get(_column_input(app), 0.0)
            if (stiffer is None or too_short) and not spanned:
                options.append(f"add an intermediate support ({shorter})")
            elif not too_short:
                options.append(f"a {shorter.replace(' at most', ' of at most', 1)}")
        options.append("move the thrust bearing so that the load pulls the screw")
        return sentence(", or ".join(options) + "." + MARGIN_NOTE, values)

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        limits = load_input(app, r.column.allowed_load_n, compressive=True)
        length = _max_length(app, s, r)
        return {**limits, _column_input(app): length} if length > 0 else limits


def _column_input(app: Application) -> str:
    """The input that sets the column's length: the span from the thrust bearing to the
    nut when given, else the screw's length."""
    return "length_m" if app.bearing_to_nut_m is None else "bearing_to_nut_m"


def _modulus(s: ScrewSpec) -> float:
    """The Young's modulus [Pa] a fix sizes ``s``'s column with: at most its makers'
    (``column_rules.makers_column_modulus``). Its Johnson parabola is then below the
    rated one (``column_rules.rated_column_load``), so a length or diameter found is on the
    safe side."""
    ball = s.screw_type == "ball"
    hiwin = s.buckling_rule == column_rules.HIWIN_BUCKLING_RULE
    return float(column_rules.makers_column_modulus(s.youngs_modulus_pa, ball, hiwin))


def _makers_rule(app: Application, s: ScrewSpec, r: Quantities[float]) -> str:
    """The makers' column rule, in words, where it and not the screw's own modulus gives
    its critical load (Euler with the makers' E, ``_modulus``, below the column's own);
    "" where the screw's own column governs."""
    e_m = _modulus(s)
    own = s.youngs_modulus_pa
    makers = buckling.euler_critical_load(
        e_m, buckling.second_moment_round(s.root_diameter_m), r.column.column_length_m,
        app.end_fixity,
    )  # fmt: skip
    if not e_m < own or not math.isclose(r.column.critical_load_n, makers):
        return ""
    if s.screw_type == "ball":
        if s.buckling_rule == column_rules.HIWIN_BUCKLING_RULE:
            return "HIWIN's F 3.25"
        return "the lowest published ball-screw rule, Rockford's and Thomson's"
    if e_m == column_rules.LOWEST_COLUMN_MODULUS_PA:
        return "Thomson's and Nook's rule for steel"
    return "W.M. Berg's rule for stainless"


def _most_n(s: ScrewSpec, root_diameter_m: float) -> float:
    """The makers' allowed column load of ``s`` at a root diameter [N]: THK's
    P2 = 116 d1^2 [N, mm] where ``makers_stress`` is, else inf."""
    return makers_stress(s) * buckling.root_area(root_diameter_m)


def _yield(s: ScrewSpec) -> float:
    """The screw's yield strength [Pa] (NaN when unknown: Euler alone)."""
    return float("nan") if s.yield_strength_pa is None else s.yield_strength_pa


def _max_length(
    app: Application,
    s: ScrewSpec,
    r: Quantities[float],
    force_n: float | None = None,
    fixity: EndFixity | None = None,
) -> float:
    """Longest column carrying the peak thrust (or ``force_n``) with the buckling factor,
    with the ends ``app``'s (or ``fixity``) [m]. A fix asks for the column that carries the
    thrust with its margin: in Johnson's short-column range the critical load hardly grows
    as the column shortens, so a length a margin shorter would not keep the margin. 0
    when the thrust is above the makers' allowed load at any length (THK's P2)."""
    force_n = r.axis.compressive_force_n if force_n is None else force_n
    if force_n > _most_n(s, s.root_diameter_m):
        return 0.0
    return buckling.max_length_for_column(
        force_n / app.buckling_safety_factor,
        _modulus(s),
        s.root_diameter_m,
        app.end_fixity if fixity is None else fixity,
        _yield(s),
    )
