"""The nut's permissible PV at its running temperature and lubrication [1, 2, 3].

A polymer nut's PV limit is the PV whose friction heat the nut can shed without its
contact passing the material's highest temperature [1, 2]; makers rate it at room
temperature, and the pressure a polymer takes falls as it warms. Here the permissible PV
falls in a straight line from the rating at the reference temperature (23 C, the
temperature polymer bearing ratings are tested at [3]) to zero at the nut material's
highest operating temperature (the catalog's, the same the temperature check reads), at
the nut's steady temperature from the heat balance (ambient plus the friction rise). The
straight line is an assumed shape between those two cited ends; the rise is counted in
the temperature and again in the PV, so the derating errs to the safe side.

A lubricant lowers the friction and with it the heat, so the nut carries more PV:
"Lubrication can increase the capacity as much as 100 %" [4]. Dry (the rating's own
condition) is 1, oiled 2 (that upper figure: a continuous film also carries heat away),
greased 1.5 (assumed, between them).

References
----------
1. tribology-abc.com, calculator E3.11: the limiting PV of a sliding bearing is set by
   its maximum contact temperature (friction heat mu P V per unit area).
2. RBC Bearings, Fiberglide "Temperature Limit": at elevated temperatures the PV limit
   is decreased so the surface (environment plus friction heat) stays below 300 F.
3. CSB plastic plain bearings, material tables: properties at 23 C unless stated.
4. BNB Industries, plastic bearing technical information: lubrication can increase the
   capacity as much as 100 %.
"""

from app.core.formulas.declare import formula

#: The temperature PV ratings hold at [C] (CSB material tables: 23 C).
REFERENCE_C = 23.0
#: The permissible PV's factor for each lubrication, with its provenance.
LUBRICATION_FACTORS: dict[str, tuple[float, str, str]] = {
    "dry": (1.0, "vendor", "polymer nut PV ratings are for dry running (CSB, ITS026)"),
    "greased": (1.5, "assumed", "between dry and oiled; no published factor found"),
    "oiled": (
        2.0,
        "vendor",
        "BNB Industries: lubrication can increase the capacity as much as 100 %",
    ),
}


@formula(
    "f_T = 1 if T <= T_ref else max(0, (T_max - T) / (T_max - T_ref))",
    "limiting PV set by the contact temperature (tribology-abc E3.11; RBC Fiberglide); "
    "ratings at 23 C (CSB)",
)
def temperature_factor(nut_c: float, max_c: float, reference_c: float = REFERENCE_C) -> float:
    """The share of the rated PV the nut keeps at ``nut_c`` [C]: 1 up to the reference
    temperature, then a straight line to 0 at the material's highest operating
    temperature ``max_c`` [C]. Valid for ``max_c`` above the reference.

    A polyacetal nut (93 C highest) running at 58 C keeps (93 - 58) / (93 - 23) = 0.5:

    >>> temperature_factor(58.0, 93.0)
    0.5
    >>> temperature_factor(20.0, 93.0), temperature_factor(120.0, 93.0)
    (1.0, 0.0)
    """
    if nut_c <= reference_c:
        return 1.0
    return max(0.0, (max_c - nut_c) / (max_c - reference_c))
