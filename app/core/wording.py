"""Words for the numbers and catalog values a verdict states: a catalog key in the
reader's words (``value_label``), and a utilisation, a margin or a share written with the
figures that keep a fail from reading as a pass (``percent``, ``times``, ``share``)."""

from collections.abc import Mapping

from app.core.model import PASS_UTILIZATION

#: Catalog values by their base name (no nut variant, no unit), in the reader's words.
VALUE_LABELS: Mapping[str, str] = {
    "allowed_wear": "allowed wear depth",
    "allowed_wear_to_flank_height": "allowed wear depth",
    "backlash": "backlash",
    "critical_speed_rule": "critical speed rule",
    "buckling_rule": "buckling rule",
    "bearing_pressure": "allowed contact pressure",
    "bearing_pv_limit": "nut PV limit",
    "density": "screw density",
    "design_contact_pressure": "design contact pressure",
    "design_load": "design load",
    "design_load_factor": "design load factor",
    "drag_torque": "nut drag torque",
    "dn_limit": "DN speed limit",
    "dry_friction_dynamic": "running friction run dry",
    "dry_friction_static": "static friction run dry",
    "dynamic_pressure": "flank pressure rating in motion",
    "dynamic_load": "dynamic load rating",
    "expansion_per_c": "screw thermal expansion",
    "friction_dynamic": "running friction",
    "friction_static": "static friction",
    "inertia_per_length": "screw inertia",
    "lead": "lead",
    "lead_accuracy": "lead accuracy",
    "life": "rated life",
    "max_length": "maximum length",
    "max_pressure": "maximum contact pressure",
    "max_sliding_speed": "maximum sliding speed",
    "motor_curve": "motor torque-speed curve",
    "motor_detent": "motor detent torque",
    "motor_holding": "motor holding torque",
    "motor_rms_torque": "motor rated torque",
    "nut_length": "nut length",
    "nut_length_to_d": "rated nut length",
    "oil_compatible": "oil compatibility",
    "lubricated_rating": "lubricated rating",
    "outer_diameter": "outer diameter",
    "outgassing": "outgassing",
    "pitch": "pitch",
    "pv_limit": "PV limit",
    "repeatability": "repeatability",
    "screw_expansion": "screw thermal expansion",
    "root_diameter": "root diameter",
    "root_diameter_ratio": "root diameter",
    "specific_wear_rate": "specific wear rate",
    "static_load": "static load rating",
    "support_dynamic": "support unit's dynamic load rating",
    "support_static": "support unit's static load rating",
    "temperature_range": "temperature range",
    "thermal_conductivity": "screw thermal conductivity",
    "thermal_conductivity_w_m_k": "screw thermal conductivity",
    "thread_half_angle": "flank angle",
    "traverse_speed": "traverse speed limit",
    "travel_deviation": "travel deviation by useful travel",
    "type": "nut type",
    "wear_rate": "specific wear rate",
    "yield_strength": "yield strength",
    "youngs_modulus": "Young's modulus",
    "youngs_modulus_gpa": "Young's modulus",
}
#: Unit endings of catalog keys (``pv_limit_mpa_m_s``), longest first.
UNIT_ENDINGS = ("_mm3_n_m", "_mpa_m_s", "_n_m", "_m_s", "_mpa", "_lbf", "_kgf", "_mm", "_n")
#: Nut variant endings of catalog keys (``friction_dynamic_tfe``).
VARIANT_ENDINGS = ("_uncoated", "_tfe", "_bronze", "_acetal", "_ptfe")


def value_label(key: str) -> str:
    """A catalog key in words: its variant and unit endings dropped, then named.

    >>> value_label("pv_limit_mpa_m_s"), value_label("dynamic_load_lbf")
    ('PV limit', 'dynamic load rating')
    >>> value_label("friction_static_bronze"), value_label("odd_new_key")
    ('static friction', 'odd new key')
    """
    base = key.removesuffix(v) if (v := _ending(key, VARIANT_ENDINGS)) else key
    if base in VALUE_LABELS:
        return VALUE_LABELS[base]
    unit = _ending(base, UNIT_ENDINGS)
    if unit and (name := base.removesuffix(unit)) in VALUE_LABELS:
        return VALUE_LABELS[name]
    return base.replace("_", " ")


def _ending(key: str, endings: tuple[str, ...]) -> str:
    """The first of ``endings`` (longest first) that ``key`` ends with, else ""."""
    if key.endswith(endings):
        return next(e for e in endings if key.endswith(e))
    return ""


def percent(utilization: float) -> str:
    """A utilisation as a percentage, with the decimals near 100 % that keep a pass
    below 100 % and a fail above it (99.96 % reads 99.96 %, never 100.0 %).

    >>> percent(0.5234), percent(0.9962), percent(1.0004), percent(0.99996), percent(1.0)
    ('52 %', '99.6 %', '100.04 %', '99.996 %', '100 %')
    """
    value = utilization * 100.0
    # at the limit within the rounding a check passes by (``PASS_UTILIZATION``): 100 %
    if not 99.5 <= value <= 100.5 or abs(utilization - 1.0) <= PASS_UTILIZATION - 1.0:
        return f"{value:.0f} %"
    digits = 1 if value < 100.0 else 2
    while float(f"{value:.{digits}f}") == 100.0:
        digits += 1
    return f"{value:.{digits}f} %"


def times(margin: float, digits: int = 2) -> str:
    """A margin (allowed over actual, at 1 or more it passes) with ``digits`` decimals and
    "×", and the decimals near 1 that keep a fail below 1 and a pass above it, as
    ``percent`` keeps a utilisation (0.997 reads 0.997×, never 1.00×).

    >>> times(3.14159), times(0.997), times(1.0004), times(0.99996), times(1.0 - 1e-12)
    ('3.14×', '0.997×', '1.0004×', '0.99996×', '1.00×')
    """
    # at the limit within the rounding a check passes by (``PASS_UTILIZATION``): 1.00×
    if abs(margin - 1.0) > PASS_UTILIZATION - 1.0:
        while float(f"{margin:.{digits}f}") == 1.0:
            digits += 1
    return f"{margin:.{digits}f}×"


def share(amount: float) -> str:
    """A margin or an excess as a share (0.2: 20 %), never rounded to 0 % unless it is
    nil within the pass rounding (``PASS_UTILIZATION``): 0.3 % over reads "0.3 %", not
    "0 %", beside a fail.

    >>> share(0.2), share(0.003), share(0.00004), share(1e-12)
    ('20 %', '0.3 %', '0.004 %', '0 %')
    """
    value = amount * 100.0
    if abs(amount) <= PASS_UTILIZATION - 1.0 or abs(value) >= 0.5:
        return f"{value:.0f} %"
    return f"{value:.1g} %"
