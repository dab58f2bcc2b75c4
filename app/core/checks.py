"""Every limit check for one evaluated screw, each with message, formula and fix.

Utilization is demand / capacity, so a value above 1 fails. Messages quote metric
engineering units (mm, mm/s, N, N m, rpm, MPa m/s); the numeric fields stay SI.
"""

from collections.abc import Callable, Mapping

from app.core import buckling, critical_speed, limits
from app.core.model import STANDARD_GRAVITY_M_S2, Application, Check, Evaluation

FIXITY_ORDER = ("fixed-free", "simple-simple", "fixed-simple", "fixed-fixed")


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
    ok_text: str,
    fail_text: str,
    fix: str | None,
    input_limits: Mapping[str, float] | None = None,
) -> Check:
    utilization = value / limit
    passed = utilization <= 1.0
    return Check(
        name=name,
        label=label,
        passed=passed,
        value=value,
        limit=limit,
        unit=unit,
        utilization=utilization,
        message=ok_text if passed else fail_text,
        formula=formula,
        sources=sources,
        fix=None if passed else fix,
        input_limits={} if passed else dict(input_limits or {}),
    )


def _stiffer_fixities(app: Application, ev: Evaluation, passes: Callable[[str], bool]) -> str:
    found = [f for f in FIXITY_ORDER[FIXITY_ORDER.index(app.end_fixity) + 1 :] if passes(f)]
    return f"mount the ends {found[0]}" if found else "add an intermediate support"


def _load_input(app: Application, axial_limit_n: float) -> float:
    """Largest user load whose axial force (incl. weight when vertical) meets a limit."""
    if app.orientation == "vertical":
        return axial_limit_n - app.moving_mass_kg * STANDARD_GRAVITY_M_S2
    return axial_limit_n


def critical_speed_check(app: Application, ev: Evaluation) -> Check:
    s, c = ev.screw, ev.critical_speed
    d_min = critical_speed.min_root_diameter_for_speed(s.root_diameter_m, c.allowed_rpm, ev.rpm)
    lead_min = critical_speed.min_lead_for_speed(app.speed_m_s, c.allowed_rpm)
    l_max = critical_speed.max_length_for_speed(app.length_m, c.allowed_rpm, ev.rpm)

    def passes(fixity: str) -> bool:
        n = critical_speed.critical_speed_rpm(
            s.root_diameter_m, app.length_m, s.youngs_modulus_pa, s.density_kg_m3, fixity
        )
        return ev.rpm <= c.safety_factor * n

    support = _stiffer_fixities(app, ev, passes)
    return _numeric(
        "critical_speed",
        "Critical speed",
        ev.rpm,
        c.allowed_rpm,
        "rpm",
        "n = 60 v / lead; n_allowed = SF (60 / 2pi) (beta / L)^2 sqrt(E / rho) d_r / 4",
        ("root_diameter", "youngs_modulus", "density"),
        f"{ev.rpm:.0f} rpm is below the allowed {c.allowed_rpm:.0f} rpm "
        f"({c.safety_factor:g} x critical {c.theoretical_rpm:.0f} rpm, {c.end_fixity}).",
        f"{ev.rpm:.0f} rpm exceeds the allowed {c.allowed_rpm:.0f} rpm "
        f"({c.safety_factor:g} x critical {c.theoretical_rpm:.0f} rpm, {c.end_fixity}).",
        f"Use a lead of at least {_mm(lead_min)}, or a root diameter of at least "
        f"{_mm(d_min)}, or {support} (unsupported length at most {_mm(l_max)}).",
        {"speed_m_s": c.allowed_rpm * s.lead_m / 60.0, "length_m": l_max},
    )


def buckling_check(app: Application, ev: Evaluation) -> Check:
    s, b = ev.screw, ev.buckling
    l_max = buckling.max_length_for_load(app.length_m, b.allowed_load_n, ev.axial_load_n)
    d_min = buckling.min_root_diameter_for_load(
        s.root_diameter_m, b.allowed_load_n, ev.axial_load_n
    )

    def passes(fixity: str) -> bool:
        f_cr = buckling.euler_critical_load(
            s.youngs_modulus_pa,
            buckling.second_moment_round(s.root_diameter_m),
            app.length_m,
            fixity,
        )
        return ev.axial_load_n <= b.safety_factor * f_cr

    return _numeric(
        "buckling",
        "Column buckling",
        ev.axial_load_n,
        b.allowed_load_n,
        "N",
        "F_allowed = SF k pi^2 E (pi d_r^4 / 64) / L^2",
        ("root_diameter", "youngs_modulus"),
        f"{ev.axial_load_n:.4g} N compression is within the allowed {b.allowed_load_n:.4g} N "
        f"({b.safety_factor:g} x Euler {b.critical_load_n:.4g} N).",
        f"{ev.axial_load_n:.4g} N compression exceeds the allowed {b.allowed_load_n:.4g} N "
        f"({b.safety_factor:g} x Euler {b.critical_load_n:.4g} N).",
        f"Use a root diameter of at least {_mm(d_min)}, or "
        f"{_stiffer_fixities(app, ev, passes)} (column at most {_mm(l_max)}), "
        "or load the screw in tension.",
        {"load_n": _load_input(app, b.allowed_load_n), "length_m": l_max},
    )


def pv_check(app: Application, ev: Evaluation) -> Check | None:
    p = ev.pv
    if p.limit_pa_m_s is None or p.max_load_n is None or p.max_speed_m_s is None:
        return None
    coat = "" if ev.screw.coated else "; a TFE-coated screw has a higher limit"
    return _numeric(
        "pv",
        "PV (nut material)",
        p.value_pa_m_s,
        p.limit_pa_m_s,
        "Pa m/s",
        "PV = F / (3 H.T. h) x n H.T. = n F / (3 h)",
        ("pv_limit", "root_diameter", "outer_diameter"),
        f"PV {p.value_pa_m_s / 1e6:.3g} MPa m/s is within the nut limit "
        f"{p.limit_pa_m_s / 1e6:.3g} MPa m/s.",
        f"PV {p.value_pa_m_s / 1e6:.3g} MPa m/s exceeds the nut limit "
        f"{p.limit_pa_m_s / 1e6:.3g} MPa m/s.",
        f"At this speed the load may be at most {p.max_load_n:.4g} N; at this load the speed "
        f"may be at most {_mm_s(p.max_speed_m_s)}{coat}.",
        {"load_n": _load_input(app, p.max_load_n), "speed_m_s": p.max_speed_m_s},
    )


def traverse_check(app: Application, ev: Evaluation) -> Check:
    lim = ev.traverse_speed_limit_m_s
    note = " (lead outside the 2.5-60 mm table: nearest band)" if ev.traverse_extrapolated else ""
    faster = [band for band in limits.TRAVERSE_BANDS if band[2] >= app.speed_m_s]
    band_fix = (
        f", or a lead of at least {_mm(faster[0][0])}" if faster and faster[0][2] > lim else ""
    )
    return _numeric(
        "traverse_speed",
        "Traverse speed",
        app.speed_m_s,
        lim,
        "m/s",
        "seed table: lead 2.5-12 mm: 100 mm/s; 12-25 mm: 250 mm/s; 25-60 mm: 760 mm/s",
        ("lead",),
        f"{_mm_s(app.speed_m_s)} is within the recommended {_mm_s(lim)} for this lead{note}.",
        f"{_mm_s(app.speed_m_s)} exceeds the recommended {_mm_s(lim)} for this lead{note}.",
        f"Run at most {_mm_s(lim)}{band_fix}.",
        {"speed_m_s": lim},
    )


def design_load_check(app: Application, ev: Evaluation) -> Check | None:
    cap = ev.screw.design_load_n
    if cap is None:
        return None
    return _numeric(
        "design_load",
        "Design load",
        ev.axial_load_n,
        cap,
        "N",
        "F <= design load of the size",
        ("design_load",),
        f"{ev.axial_load_n:.4g} N is within the design load {cap:.4g} N.",
        f"{ev.axial_load_n:.4g} N exceeds the design load {cap:.4g} N.",
        f"Reduce the load to at most {cap:.4g} N or choose a larger size.",
        {"load_n": _load_input(app, cap)},
    )


def length_check(app: Application, ev: Evaluation) -> Check | None:
    cap = ev.screw.max_length_m
    if cap is None:
        return None
    fix = (
        "Uncoated screws are made up to 4 m; or shorten the screw to "
        if ev.screw.coated
        else "Shorten the screw to "
    )
    return _numeric(
        "length",
        "Length",
        app.length_m,
        cap,
        "m",
        "L <= maximum length (4 m, 2.4 m coated)",
        ("max_length",),
        f"{_mm(app.length_m)} is within the maximum {_mm(cap)}.",
        f"{_mm(app.length_m)} exceeds the maximum length {_mm(cap)}.",
        f"{fix}at most {_mm(cap)}.",
        {"length_m": cap},
    )


def _flag(
    name: str,
    label: str,
    passed: bool,
    ok: str,
    fail: str,
    fix: str,
    formula: str,
    sources: tuple[str, ...],
) -> Check:
    return Check(
        name=name,
        label=label,
        passed=passed,
        value=None,
        limit=None,
        unit="",
        utilization=None,
        message=ok if passed else fail,
        formula=formula,
        sources=sources,
        fix=None if passed else fix,
    )


def back_driving_check(app: Application, ev: Evaluation) -> Check:
    """Vertical axes must not drop the load: the screw must self-lock."""
    s = ev.screw
    return _numeric(
        "back_driving",
        "Back-driving (vertical axis)",
        s.lead_m,
        ev.max_self_locking_lead_m,
        "m",
        "self-locking when lead <= pi d_p mu_s / cos(a_n)",
        ("friction_static", "thread_half_angle"),
        "Self-locking: the load cannot drive the screw down.",
        f"Back-drivable: the load can drive the screw down; holding torque "
        f"{ev.holding_torque_seed_nm:.3g} N m (seed method), "
        f"{ev.holding_torque_physics_nm:.3g} N m (physics).",
        f"Fit a brake of at least {ev.holding_torque_seed_nm:.3g} N m or use a lead of at most "
        f"{_mm(ev.max_self_locking_lead_m)}.",
    )


def torque_check(app: Application, ev: Evaluation) -> Check | None:
    if app.max_torque_nm is None:
        return None
    t = ev.torque
    return _numeric(
        "torque",
        "Drive torque",
        t.required_nm,
        app.max_torque_nm,
        "N m",
        "T_req = SF x max(T_inertia + T_drag + T_load, T_breakaway)",
        ("inertia_per_length", "drag_torque", "friction_dynamic", "friction_static"),
        f"{t.required_nm:.3g} N m required is within the {app.max_torque_nm:.3g} N m available.",
        f"{t.required_nm:.3g} N m required exceeds the {app.max_torque_nm:.3g} N m available.",
        f"A drive of at least {t.required_nm:.3g} N m, or a shorter lead, lower load or "
        "acceleration.",
    )


def life_check(app: Application, ev: Evaluation) -> Check | None:
    if app.required_life_years is None or app.stroke_m is None or app.cycles_per_day is None:
        return None
    if ev.life is None or ev.life.years_min is None:
        return _flag(
            "life",
            "Life",
            False,
            "",
            "No life rating is published for this series.",
            "Choose an anti-backlash series, whose life is rated.",
            "life = rated travel / (2 stroke x cycles per year)",
            ("life",),
        )
    years = ev.life.years_min
    check = _numeric(
        "life",
        "Life",
        app.required_life_years,
        years,
        "year",
        "life = rated travel / (2 stroke x cycles per year)",
        ("life",),
        f"At least {years:.3g} years rated, {app.required_life_years:g} required.",
        f"Only {years:.3g} years rated (low end), {app.required_life_years:g} required.",
        "Choose a TFE-coated screw or a series with a longer rated life, or shorten the "
        "stroke or the duty.",
    )
    return check


def accuracy_check(app: Application, ev: Evaluation) -> Check | None:
    tol = app.positioning_tolerance_m
    a = ev.accuracy
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
        f"Worst-case error {_mm(error)} is within the {_mm(tol)} tolerance.",
        f"Worst-case error {_mm(error)} exceeds the {_mm(tol)} tolerance.",
        "Choose an anti-backlash series (no backlash) or a precision lead grade (to 0.0001 mm/mm).",
    )


def build_checks(app: Application, ev: Evaluation) -> tuple[Check, ...]:
    """All checks that apply to this screw and application, in a fixed order."""
    s = ev.screw
    checks: list[Check | None] = [
        torque_check(app, ev),
        critical_speed_check(app, ev),
        buckling_check(app, ev) if app.compression else None,
        pv_check(app, ev),
        traverse_check(app, ev),
        design_load_check(app, ev),
        length_check(app, ev),
    ]
    if s.coated:
        checks.append(
            _flag(
                "coating_environment",
                "TFE coating and oil",
                limits.tfe_allowed(app.oil_present),
                "No oil present: the TFE coating may be used.",
                "TFE-coated screws must not be used where oil contamination is possible.",
                "Use the uncoated screw.",
                "seed: no TFE where oil is possible",
                ("coating",),
            )
        )
    if s.temperature_min_c is not None and s.temperature_max_c is not None:
        band = f"{s.temperature_min_c:g}-{s.temperature_max_c:g}"
        checks.append(
            _flag(
                "temperature",
                "Operating temperature",
                limits.temperature_ok(app.ambient_c, s.temperature_min_c, s.temperature_max_c),
                f"{app.ambient_c:g} C is within {band} C.",
                f"{app.ambient_c:g} C is outside {band} C.",
                "No series in this catalog is rated for this temperature: control the ambient.",
                "T_min <= T_ambient <= T_max",
                ("temperature_range",),
            )
        )
    if app.orientation == "vertical":
        checks.append(back_driving_check(app, ev))
    if app.require_anti_backlash:
        checks.append(
            _flag(
                "anti_backlash",
                "Anti-backlash",
                s.anti_backlash,
                "Anti-backlash nut.",
                f"Free-wheeling nut with {_mm(s.backlash_max_m)} backlash.",
                "Choose an anti-backlash series (ZBX, KHD, VHD).",
                "series type",
                ("type",),
            )
        )
    checks.append(life_check(app, ev))
    checks.append(accuracy_check(app, ev))
    return tuple(c for c in checks if c is not None)
