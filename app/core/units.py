"""The unit table: every unit the app reads or shows, by its exact factor to the core's.

The core computes in one unit of each dimension (``app.core.phrase.Quantity``) and never
converts; the table sits at the bottom of the layers so that every edge reads the same
rows: the catalog's files (``app.catalog``), the API and the page (``app.contract.units``,
which adds the API's unit system and the page's display units). ``to_si``/``from_si``
convert one value by one float multiplication.

References
----------
1. NIST SP 811 (2008), Guide for the Use of the International System of Units, appendix
   B.8: 1 in = 0.0254 m, 1 ft = 0.3048 m, 1 lb = 0.45359237 kg, standard acceleration of
   gravity g_n = 9.80665 m/s², 1 kgf = g_n N, 1 lbf = 4.4482216152605 N (lb x g_n),
   1 psi = 1 lbf/in², 1 ozf in = 1/16 lbf in, 1 oz = 1/16 lb, all exact; appendix B.9:
   t/°C = (t/°F - 32)/1.8, and a difference of 1 °F is 5/9 K.
"""

from dataclasses import dataclass
from fractions import Fraction

from app.core.phrase import Quantity

#: one inch [m], exactly (NIST SP 811 B.8).
_IN = Fraction("0.0254")
#: one foot [m], 12 in.
_FT = 12 * _IN
#: one avoirdupois pound [kg], exactly.
_LB = Fraction("0.45359237")
#: standard acceleration of gravity [m/s²], exactly.
_G_N = Fraction("9.80665")
#: one pound-force [N]: the pound's weight at g_n.
_LBF = _LB * _G_N
_PSI = _LBF / _IN**2
_MM = Fraction(1, 1000)
_MEGA = Fraction(10**6)
_PER_MINUTE = Fraction(1, 60)


@dataclass(frozen=True, slots=True)
class Unit:
    """One unit: its symbol, the dimension it measures, its ``exact`` factor to the core's
    unit of that dimension, and the float factors each way (``si``: a value in this unit
    times ``si`` is the core's value; ``from_si`` the other way), each the correctly
    rounded float of the exact one. A temperature scale has an ``offset`` too: the core's
    value at this unit's zero (°F: -160/9 °C), so the core's value is value x exact +
    offset. ``text`` is how the unit is written, where the symbol (the table's key) must
    differ from another's ('°F rise', written Δ°F).

    A temperature difference (a rise, a room to a limit) is its own dimension,
    ``temperature_rise``: K, or Δ°F (5/9 K) on the page in inches, never offset: 1 K is a
    difference of 1 °C and of 1.8 °F (NIST SP 811 B.9)."""

    symbol: str
    dimension: Quantity
    exact: Fraction
    si: float
    from_si: float
    offset: Fraction
    text: str


def _unit(
    symbol: str,
    dimension: Quantity,
    exact: Fraction | int,
    offset: Fraction = Fraction(0),
    text: str = "",
) -> Unit:
    value = Fraction(exact)
    return Unit(symbol, dimension, value, float(value), float(1 / value), offset, text or symbol)


#: every unit the app reads or shows: symbol -> unit. The core's own unit of each
#: dimension comes first, with factor 1.
UNITS: dict[str, Unit] = {
    u.symbol: u
    for u in (
        _unit("N", "force", 1),
        _unit("lbf", "force", _LBF),
        _unit("kgf", "force", _G_N),
        _unit("m", "length", 1),
        _unit("mm", "length", _MM),
        _unit("in", "length", _IN),
        _unit("km", "length", 1000),
        _unit("million cm", "length", 10**4),
        _unit("m travelled", "travel", 1, text="m"),
        _unit("km travelled", "travel", 1000, text="km"),
        _unit("mi", "travel", Fraction(1609344, 1000)),
        _unit("m/s", "speed", 1),
        _unit("mm/s", "speed", _MM),
        _unit("in/s", "speed", _IN),
        _unit("ft/min", "speed", _FT * _PER_MINUTE),
        _unit("m/s²", "accel", 1),
        _unit("mm/s²", "accel", _MM),
        _unit("in/s²", "accel", _IN),
        _unit("g", "accel", _G_N),
        _unit("N m", "torque", 1),
        _unit("oz in", "torque", _LBF / 16 * _IN),
        _unit("gf cm", "torque", _G_N / 100_000),
        _unit("lb in", "torque", _LBF * _IN),
        _unit("kg", "mass", 1),
        _unit("lb", "mass", _LB),
        _unit("kg m²", "inertia", 1),
        _unit("g cm²", "inertia", Fraction(1, 10**7)),
        _unit("kg cm²", "inertia", Fraction(1, 10**4)),
        _unit("oz in²", "inertia", _LB / 16 * _IN**2),
        _unit("lb in²", "inertia", _LB * _IN**2),
        _unit("kg m²/m", "inertia_per_length", 1),
        _unit("kg m²/in", "inertia_per_length", 1 / _IN),
        _unit("kg/m³", "density", 1),
        _unit("rpm", "rpm", 1),
        _unit("Pa m/s", "pv", 1),
        _unit("MPa m/s", "pv", _MEGA),
        _unit("psi ft/min", "pv", _PSI * _FT * _PER_MINUTE),
        _unit("Pa", "pressure", 1),
        _unit("MPa", "pressure", _MEGA),
        _unit("GPa", "pressure", 1000 * _MEGA),
        _unit("psi", "pressure", _PSI),
        _unit("1/K", "expansion", 1),
        _unit("µm/(m K)", "expansion", 1 / _MEGA),
        _unit("m/m", "strain", 1),
        _unit("mm/m", "strain", _MM),
        _unit("mm/300 mm", "strain", _MM / Fraction("0.3")),
        _unit("s", "time", 1),
        _unit("years", "years", 1),
        _unit("°C", "temperature", 1),
        _unit("°F", "temperature", Fraction(5, 9), Fraction(-160, 9)),
        _unit("K", "temperature_rise", 1),
        _unit("°F rise", "temperature_rise", Fraction(5, 9), text="Δ°F"),
        _unit("", "factor", 1),
        _unit("Hz", "frequency", 1),
        _unit("H", "inductance", 1),
        _unit("V", "voltage", 1),
        _unit("W", "power", 1),
        _unit("J", "energy", 1),
        _unit("W/(m K)", "conductivity", 1),
        _unit("mH", "inductance", _MM),
        _unit("m³/(N m)", "wear_rate", 1),
        _unit("mm³/(N m)", "wear_rate", _MM**3),
        # RTP's wear factor: W [in³] = K F [lbf] V [ft/min] T [h], sliding 60 V T ft
        _unit("in³ min/(ft lbf h)", "wear_rate", _IN**3 / (_LBF * _FT) * _PER_MINUTE),
    )
}
#: dimension -> the core's unit of it (the one with factor 1).
SI_UNITS: dict[Quantity, str] = {u.dimension: u.symbol for u in UNITS.values() if u.exact == 1}


def to_si(value: float, unit: str) -> float:
    """A value in ``unit`` in the core's unit of its dimension: value x factor + the
    scale's offset (a temperature's: 212 °F is 100 °C).

    >>> to_si(10.0, "mm"), to_si(2.0, "MPa"), round(to_si(212.0, "°F"), 12)
    (0.01, 2000000.0, 100.0)
    """
    u = UNITS[unit]
    return value * u.si + float(u.offset) if u.offset else value * u.si


def from_si(value: float, unit: str) -> float:
    """A value in the core's unit in ``unit``: (value - the scale's offset) / factor (a
    temperature's: 100 °C is 212 °F).

    >>> from_si(0.0254, "in"), from_si(2e6, "MPa m/s"), round(from_si(100.0, "°F"), 12)
    (1.0, 2.0, 212.0)
    """
    u = UNITS[unit]
    return (value - float(u.offset)) * u.from_si if u.offset else value * u.from_si
