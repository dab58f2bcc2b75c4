"""PV (pressure x velocity) of the plastic nut by the seed's method [1].

The seed assumes three threads in contact: area ATA = 3 x H.T. x h, surface speed
V = n x H.T., pressure P = F / ATA. H.T. cancels, so PV = n F / (3 h) with n in rev/s.
"""

from app.core.formulas.declare import SEED, formula


def contact_area(helix_travel_m: float, thread_depth_m: float, threads: int = 3) -> float:
    """Total thread contact area ATA = threads x H.T. x h [m^2] (seed: 3 threads).

    Source: seed [1], ``AT = H.T. x (O.D. - R.D.) / 2``, ``ATA = AT x 3``.

    >>> round(contact_area(0.02, 0.001) * 1e6, 3)
    60.0
    """
    return threads * helix_travel_m * thread_depth_m


@formula("P = F / (3 H.T. h)", SEED)
def contact_pressure(load_n: float, contact_area_m2: float) -> float:
    """Nut contact pressure P = F / ATA [Pa].

    Source: seed [1], ``PV = TS x Load / ATA``.

    >>> contact_pressure(60.0, 60e-6)
    1000000.0
    """
    return load_n / contact_area_m2


@formula("V = (n / 60) H.T., H.T. = sqrt(lead^2 + (pi d_p)^2), n in rpm", SEED)
def surface_speed(rpm: float, helix_travel_m: float) -> float:
    """Thread sliding speed V = (n / 60) H.T. [m/s], n in rpm.

    Source: seed [1], ``TS = RPM x H.T. / 12`` (ft/min with H.T. in inches).

    >>> round(surface_speed(600.0, 0.02), 6)
    0.2
    """
    return rpm / 60.0 * helix_travel_m


@formula(
    "PV = F / (3 H.T. h) x (n / 60) H.T., n in rpm",
    SEED + " (PV Calculation, 3 threads in contact)",
)
def pv_value(
    load_n: float,
    rpm: float,
    helix_travel_m: float,
    thread_depth_m: float,
    contact_area_m2: float | None = None,
    pressure_speed: tuple[float, float] | None = None,
) -> float:
    """PV of the nut [Pa m/s] by the seed's three-thread method.

    PV = (F / (3 H.T. h)) x ((n / 60) H.T.) ; F [N], n [rpm], H.T. [m], h [m]; contact_area_m2:
    3 H.T. h [m^2] when already worked out (``contact_area``: the candidate table's
    column), the same number; ``pressure_speed``: P [Pa] and V [m/s] when already worked
    out (``contact_pressure``, ``surface_speed``), the same numbers.
    Source: seed [1], PV calculation. bnb-industries bushing example (5/8 in, 35 lb,
    120 rpm, PV 1066 psi ft/min) checks the same P x V arithmetic.

    >>> round(pv_value(100.0, 600.0, 0.02, 0.001), 1)
    333333.3
    """
    if pressure_speed is not None:
        pressure_pa, speed_m_s = pressure_speed
        return pressure_pa * speed_m_s
    area = (
        contact_area(helix_travel_m, thread_depth_m) if contact_area_m2 is None else contact_area_m2
    )
    return contact_pressure(load_n, area) * surface_speed(rpm, helix_travel_m)


@formula("F = PV_lim 3 h / (n / 60), n in rpm", SEED + " (inverted)")
def max_load_for_pv(pv_limit_pa_m_s: float, rpm: float, thread_depth_m: float) -> float:
    """Largest load the PV limit allows at this speed, F = PV_lim 3 h / (n / 60) [N].

    Inverse of ``pv_value`` (H.T. cancels); n in rpm.

    >>> round(max_load_for_pv(1.0e5, 600.0, 0.001), 3)
    30.0
    """
    return pv_limit_pa_m_s * 3.0 * thread_depth_m / (rpm / 60.0)


def max_load_at_speed(max_load_n: float, speed_m_s: float, new_speed_m_s: float) -> float:
    """The PV-limited load moved to another linear speed [N].

    F_max = PV_lim 3 h / (n / 60) and n = 60 v / lead, so F_max(v_new) = F_max(v) v / v_new
    (inverse of ``pv_value``, seed [1]). Draws the PV chart from one evaluated point.

    >>> max_load_at_speed(100.0, 0.05, 0.1)
    50.0
    """
    return max_load_n * speed_m_s / new_speed_m_s


@formula("v = lead x PV_lim 3 h / F", SEED + " (inverted)")
def max_rpm_for_pv(pv_limit_pa_m_s: float, load_n: float, thread_depth_m: float) -> float:
    """Highest speed the PV limit allows at this load, n = 60 PV_lim 3 h / F [rpm].

    >>> round(max_rpm_for_pv(1.0e5, 30.0, 0.001), 3)
    600.0
    """
    return 60.0 * pv_limit_pa_m_s * 3.0 * thread_depth_m / load_n
