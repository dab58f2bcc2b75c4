"""Every limit check for one evaluated screw, each with message, formula and fix.

Utilization is demand / capacity, so a value above 1 fails. Messages quote metric
engineering units (mm, mm/s, N, N m, rpm, MPa m/s); the numeric fields stay SI. Texts
are passed as callables and built only for the branch taken (pass or fail): most checks
pass, and formatting is most of a check's cost.
"""

from collections.abc import Callable, Mapping

from app.core import buckling, critical_speed, limits
from app.core.model import (
    PASS_UTILIZATION,
    STANDARD_GRAVITY_M_S2,
    Application,
    Check,
    Evaluation,
)

FIXITY_ORDER = ("fixed-free", "simple-simple", "fixed-simple", "fixed-fixed")
Text = Callable[[], str]


def _mm(x_m: float) -> str:
    return f"{x_m * 1000:.4g} mm"


def _mm_s(x_m_s: float) -> str:
    return f"{x_m_s * 1000:.4g} mm/s"


def _numeric(
    name: str,
    label: str,
    value: float,
    limit: float,
    unit: str,
    formula: str,
    sources: tuple[str, ...],
    ok: Text,
    fail: Text,
    fix: Text,
    input_limits: Callable[[], Mapping[str, float]] | None = None,
) -> Check:
    """A value-against-limit check."""
    utilization = value / limit
    if utilization <= PASS_UTILIZATION:
        return Check(name, label, True, value, limit, unit, utilization, ok(), formula, sources)
    return Check(
        name,
        label,
        False,
        value,
        limit,
        unit,
        utilization,
        fail(),
        formula,
        sources,
        fix(),
        dict(input_limits()) if input_limits else None,
    )


def _flag(
    name: str,
    label: str,
    passed: bool,
    ok: Text,
    fail: Text,
    fix: str,
    formula: str,
    sources: tuple[str, ...],
) -> Check:
    """A yes/no check: no value, limit or utilisation."""
    return Check(
        name,
        label,
        passed,
        None,
        None,
        "",
        None,
        ok() if passed else fail(),
        formula,
        sources,
        None if passed else fix,
    )


def _stiffer_support(app: Application, passes: Callable[[str], bool]) -> str:
    """The first stiffer end fixity that passes, else an intermediate support."""
    stiffer = FIXITY_ORDER[FIXITY_ORDER.index(app.end_fixity) + 1 :]
    found = [f for f in stiffer if passes(f)]
    return f"mount the ends {found[0]}" if found else "add an intermediate support"


def _load_input(app: Application, axial_limit_n: float) -> float:
    """Largest user load whose axial force (incl. weight when vertical) meets a limit."""
    if app.orientation == "vertical":
        return axial_limit_n - app.moving_mass_kg * STANDARD_GRAVITY_M_S2
    return axial_limit_n


def critical_speed_check(app: Application, ev: Evaluation) -> Check:
    s, c = ev.screw, ev.critical_speed
    where = f"{c.safety_factor:g} x critical {c.theoretical_rpm:.0f} rpm, {c.end_fixity}"

    def fix() -> str:
        lead_min = critical_speed.min_lead_for_speed(app.speed_m_s, c.allowed_rpm)
        d_min = critical_speed.min_root_diameter_for_speed(s.root_diameter_m, c.allowed_rpm, ev.rpm)
        l_max = critical_speed.max_length_for_speed(app.length_m, c.allowed_rpm, ev.rpm)
        support = _stiffer_support(
            app,
            lambda fixity: (
                ev.rpm
                <= c.safety_factor
                * (
                    critical_speed.critical_speed_rpm(
                        s.root_diameter_m,
                        app.length_m,
                        s.youngs_modulus_pa,
                        s.density_kg_m3,
                        fixity,
                    )
                )
            ),
        )
        return (
            f"Use a lead of at least {_mm(lead_min)}, or a root diameter of at least "
            f"{_mm(d_min)}, or {support} (unsupported length at most {_mm(l_max)})."
        )

    return _numeric(
        "critical_speed",
        "Critical speed",
        ev.rpm,
        c.allowed_rpm,
        "rpm",
        "n = 60 v / lead; n_allowed = SF (60 / 2pi) (beta / L)^2 sqrt(E / rho) d_r / 4",
        ("root_diameter", "youngs_modulus", "density"),
        lambda: f"{ev.rpm:.0f} rpm is below the allowed {c.allowed_rpm:.0f} rpm ({where}).",
        lambda: f"{ev.rpm:.0f} rpm exceeds the allowed {c.allowed_rpm:.0f} rpm ({where}).",
        fix,
        lambda: {
            "speed_m_s": c.allowed_rpm * s.lead_m / 60.0,
            "length_m": critical_speed.max_length_for_speed(app.length_m, c.allowed_rpm, ev.rpm),
        },
    )


def buckling_check(app: Application, ev: Evaluation) -> Check:
    s, b, force = ev.screw, ev.buckling, ev.axial_load_n
    where = f"{b.safety_factor:g} x Euler {b.critical_load_n:.4g} N"

    def fix() -> str:
        l_max = buckling.max_length_for_load(app.length_m, b.allowed_load_n, force)
        d_min = buckling.min_root_diameter_for_load(s.root_diameter_m, b.allowed_load_n, force)
        support = _stiffer_support(
            app,
            lambda fixity: (
                force
                <= b.safety_factor
                * (
                    buckling.euler_critical_load(
                        s.youngs_modulus_pa,
                        buckling.second_moment_round(s.root_diameter_m),
                        app.length_m,
                        fixity,
                    )
                )
            ),
        )
        return (
            f"Use a root diameter of at least {_mm(d_min)}, or {support} (column at most "
            f"{_mm(l_max)}), or load the screw in tension."
        )

    return _numeric(
        "buckling",
        "Column buckling",
        force,
        b.allowed_load_n,
        "N",
        "F_allowed = SF k pi^2 E (pi d_r^4 / 64) / L^2",
        ("root_diameter", "youngs_modulus"),
        lambda: (
            f"{force:.4g} N compression is within the allowed {b.allowed_load_n:.4g} N ({where})."
        ),
        lambda: (
            f"{force:.4g} N compression exceeds the allowed {b.allowed_load_n:.4g} N ({where})."
        ),
        fix,
        lambda: {
            "load_n": _load_input(app, b.allowed_load_n),
            "length_m": buckling.max_length_for_load(app.length_m, b.allowed_load_n, force),
        },
    )


def pv_check(app: Application, ev: Evaluation) -> Check | None:
    p = ev.pv
    limit, max_load, max_speed = p.limit_pa_m_s, p.max_load_n, p.max_speed_m_s
    if limit is None or max_load is None or max_speed is None:
        return None
    coat = "" if ev.screw.coated else "; a TFE-coated screw has a higher limit"
    return _numeric(
        "pv",
        "PV (nut material)",
        p.value_pa_m_s,
        limit,
        "Pa m/s",
        "PV = F / (3 H.T. h) x n H.T. = n F / (3 h)",
        ("pv_limit", "root_diameter", "outer_diameter"),
        lambda: (
            f"PV {p.value_pa_m_s / 1e6:.3g} MPa m/s is within the nut limit "
            f"{limit / 1e6:.3g} MPa m/s."
        ),
        lambda: (
            f"PV {p.value_pa_m_s / 1e6:.3g} MPa m/s exceeds the nut limit "
            f"{limit / 1e6:.3g} MPa m/s."
        ),
        lambda: (
            f"At this speed the load may be at most {max_load:.4g} N; at this load the "
            f"speed may be at most {_mm_s(max_speed)}{coat}."
        ),
        lambda: {"load_n": _load_input(app, max_load), "speed_m_s": max_speed},
    )


def traverse_check(app: Application, ev: Evaluation) -> Check | None:
    lim = ev.traverse_speed_limit_m_s
    if lim is None:
        return None
    note = " (lead outside the 2.5-60 mm table: nearest band)" if ev.traverse_extrapolated else ""

    def fix() -> str:
        faster = [band for band in ev.screw.traverse_bands if band[2] >= app.speed_m_s]
        band = f", or a lead of at least {_mm(faster[0][0])}" if faster else ""
        return f"Run at most {_mm_s(lim)}{band}."

    return _numeric(
        "traverse_speed",
        "Traverse speed",
        app.speed_m_s,
        lim,
        "m/s",
        "seed table: lead 2.5-12 mm: 100 mm/s; 12-25 mm: 250 mm/s; 25-60 mm: 760 mm/s",
        ("lead",),
        lambda: (
            f"{_mm_s(app.speed_m_s)} is within the recommended {_mm_s(lim)} for this lead{note}."
        ),
        lambda: f"{_mm_s(app.speed_m_s)} exceeds the recommended {_mm_s(lim)} for this lead{note}.",
        fix,
        lambda: {"speed_m_s": lim},
    )


def design_load_check(app: Application, ev: Evaluation) -> Check | None:
    cap, force = ev.screw.design_load_n, ev.axial_load_n
    if cap is None:
        return None
    return _numeric(
        "design_load",
        "Design load",
        force,
        cap,
        "N",
        "F <= design load of the size",
        ("design_load",),
        lambda: f"{force:.4g} N is within the design load {cap:.4g} N.",
        lambda: f"{force:.4g} N exceeds the design load {cap:.4g} N.",
        lambda: f"Reduce the load to at most {cap:.4g} N or choose a larger size.",
        lambda: {"load_n": _load_input(app, cap)},
    )


def length_check(app: Application, ev: Evaluation) -> Check | None:
    cap = ev.screw.max_length_m
    if cap is None:
        return None
    coated = "Uncoated screws are made up to 4 m; or s" if ev.screw.coated else "S"
    return _numeric(
        "length",
        "Length",
        app.length_m,
        cap,
        "m",
        "L <= maximum length (4 m, 2.4 m coated)",
        ("max_length",),
        lambda: f"{_mm(app.length_m)} is within the maximum {_mm(cap)}.",
        lambda: f"{_mm(app.length_m)} exceeds the maximum length {_mm(cap)}.",
        lambda: f"{coated}horten the screw to at most {_mm(cap)}.",
        lambda: {"length_m": cap},
    )


def back_driving_check(app: Application, ev: Evaluation) -> Check:
    """Vertical axes must not drop the load: the screw must self-lock."""
    return _numeric(
        "back_driving",
        "Back-driving (vertical axis)",
        ev.screw.lead_m,
        ev.max_self_locking_lead_m,
        "m",
        "self-locking when lead <= pi d_p mu_s / cos(a_n)",
        ("friction_static", "thread_half_angle"),
        lambda: "Self-locking: the load cannot drive the screw down.",
        lambda: (
            f"Back-drivable: the load can drive the screw down; holding torque "
            f"{ev.holding_torque_seed_nm:.3g} N m (seed method), "
            f"{ev.holding_torque_physics_nm:.3g} N m (physics)."
        ),
        lambda: (
            f"Fit a brake of at least {ev.brake_torque_nm:.3g} N m or use a lead of "
            f"at most {_mm(ev.max_self_locking_lead_m)}."
        ),
    )


def torque_check(app: Application, ev: Evaluation) -> Check | None:
    available = app.max_torque_nm
    if available is None:
        return None
    required = ev.torque.required_nm
    return _numeric(
        "torque",
        "Drive torque",
        required,
        available,
        "N m",
        "T_req = SF x max(T_inertia + T_drag + T_load, T_breakaway)",
        ("inertia_per_length", "drag_torque", "friction_dynamic", "friction_static"),
        lambda: f"{required:.3g} N m required is within the {available:.3g} N m available.",
        lambda: f"{required:.3g} N m required exceeds the {available:.3g} N m available.",
        lambda: (
            f"A drive of at least {required:.3g} N m, or a shorter lead, lower load or "
            "acceleration."
        ),
    )


def life_check(app: Application, ev: Evaluation) -> Check | None:
    required = app.required_life_years
    if required is None or not app.stroke_m or not app.cycles_per_day:
        return None  # no duty to convert the rated travel to years
    formula = "life = rated travel / (2 stroke x cycles per year)"
    if ev.life is None or ev.life.years_min is None:
        return _flag(
            "life",
            "Life",
            False,
            lambda: "",
            lambda: "No life rating is published for this series.",
            "Choose an anti-backlash series, whose life is rated.",
            formula,
            ("life",),
        )
    years = ev.life.years_min
    return _numeric(
        "life",
        "Life",
        required,
        years,
        "year",
        formula,
        ("life",),
        lambda: f"At least {years:.3g} years rated, {required:g} required.",
        lambda: f"Only {years:.3g} years rated (low end), {required:g} required.",
        lambda: (
            "Choose a TFE-coated screw or a series with a longer rated life, or shorten "
            "the stroke or the duty."
        ),
    )


def accuracy_check(app: Application, ev: Evaluation) -> Check | None:
    tol, a = app.positioning_tolerance_m, ev.accuracy
    if tol is None or a.lead_error_m is None:
        return None
    error = a.lead_error_m + a.backlash_max_m + (a.repeatability_m or 0.0)
    return _numeric(
        "accuracy",
        "Positioning accuracy",
        error,
        tol,
        "m",
        "error = lead accuracy x stroke + backlash (max) + repeatability",
        ("lead_accuracy", "backlash", "repeatability"),
        lambda: f"Worst-case error {_mm(error)} is within the {_mm(tol)} tolerance.",
        lambda: f"Worst-case error {_mm(error)} exceeds the {_mm(tol)} tolerance.",
        lambda: (
            "Choose an anti-backlash series (no backlash) or a precision lead grade "
            "(to 0.0001 mm/mm)."
        ),
    )


def coating_check(app: Application) -> Check:
    return _flag(
        "coating_environment",
        "TFE coating and oil",
        not app.oil_present,
        lambda: "No oil present: the TFE coating may be used.",
        lambda: "TFE-coated screws must not be used where oil contamination is possible.",
        "Use the uncoated screw.",
        "seed: no TFE where oil is possible",
        ("coating",),
    )


def temperature_check(app: Application, low_c: float, high_c: float) -> Check:
    band = f"{low_c:g}-{high_c:g} C"
    return _flag(
        "temperature",
        "Operating temperature",
        limits.temperature_ok(app.ambient_c, low_c, high_c),
        lambda: f"{app.ambient_c:g} C is within {band}.",
        lambda: f"{app.ambient_c:g} C is outside {band}.",
        "No series in this catalog is rated for this temperature: control the ambient.",
        "T_min <= T_ambient <= T_max",
        ("temperature_range",),
    )


def anti_backlash_check(ev: Evaluation) -> Check:
    return _flag(
        "anti_backlash",
        "Anti-backlash",
        ev.screw.anti_backlash,
        lambda: "Anti-backlash nut.",
        lambda: f"Free-wheeling nut with up to {_mm(ev.screw.backlash_max_m)} backlash.",
        "Choose an anti-backlash series (ZBX, KHD, VHD).",
        "series type",
        ("type",),
    )


def build_checks(app: Application, ev: Evaluation) -> tuple[Check, ...]:
    """All checks that apply to this screw and application, in a fixed order.

    ``app.core.screening.screen`` applies the same rules to arrays; keep them in step.
    """
    s = ev.screw
    checks: list[Check | None] = [
        torque_check(app, ev),
        critical_speed_check(app, ev),
        buckling_check(app, ev) if app.compression else None,
        pv_check(app, ev),
        traverse_check(app, ev),
        design_load_check(app, ev),
        length_check(app, ev),
        coating_check(app) if s.coated else None,
        (
            temperature_check(app, s.temperature_min_c, s.temperature_max_c)
            if s.temperature_min_c is not None and s.temperature_max_c is not None
            else None
        ),
        back_driving_check(app, ev) if app.orientation == "vertical" else None,
        anti_backlash_check(ev) if app.require_anti_backlash else None,
        life_check(app, ev),
        accuracy_check(app, ev),
    ]
    return tuple(c for c in checks if c is not None)
