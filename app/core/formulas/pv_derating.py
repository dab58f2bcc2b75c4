"""The nut's permissible PV at the ambient temperature and its lubrication [1, 2, 3, 4].

A polymer nut's PV limit is the PV whose friction heat lifts the nut from the ambient to
the material's highest temperature [1, 2]. igus publishes the permitted pv of its polymer
plain bearings as that heat balance [3]: friction heat mu p v per unit area, carried off
through the shaft and the bushing wall, equal to the conductances times
Delta T = T_a - T_u, the highest application temperature less the ambient. Every other term
is the same at any ambient, so the permitted PV at an ambient ``T_u`` is the rating (taken
at the reference ambient, 20 C: igus rates pv at 68 F [4]) times

    f_T = (T_max - T_ambient) / (T_max - T_ref)

a straight line from 1 at the reference to 0 at the material's highest temperature (the
catalog's, the same the temperature check reads). Below the reference no credit is taken
(f_T = 1). The line is taken at the ambient, not at the nut's running temperature: the
rise over the ambient is the PV's own heat, already inside the rating, and the nut heat
check judges that rise against the room left to the highest temperature.

A lubricant lowers the friction and with it the heat, so the nut carries more PV. igus's
factors on the permitted pv [3, Table 1.4]: dry 1, greased once at installation 1.3,
continuously greased 2, water 4, continuously oiled 5. Here: dry 1 (the rating's own
condition); greased 1.3 (a leadscrew nut greased at assembly and now and then, so the
once-greased factor; continuous greasing would earn 2); oiled 2, the general plastic
bearing figure "as much as 100 %" [5], below igus's 5 for its own materials.

References
----------
1. tribology-abc.com, calculator E3.11: the limiting PV of a sliding bearing is set by
   its maximum contact temperature (friction heat mu P V per unit area).
2. RBC Bearings, Fiberglide "Temperature Limit": at elevated temperatures the PV limit
   is decreased so the surface (environment plus friction heat) stays below 300 F.
3. igus, "iglide plastic bushings - p x v value and lubrication" (igus.com/info/
   plain-bearings-iglide-plastic-bushings-value-lubrication-ca): permitted p x v from
   K1, K2, wall thickness, length, mu, the shaft's and bushing's conductivities and
   Delta T = T_a - T_u; Table 1.4, adjustment of the permitted p x v by lubrication.
4. igus, iglide H and iglide T500 material data: permitted p x v values "in dry
   operation against a steel shaft, at 68 F" (iglide H: 39,000 psi fpm, upper long-term
   application temperature 392 F).
5. BNB Industries, plastic bearing technical information: lubrication can increase the
   capacity as much as 100 %.
"""

import numpy as np
import numpy.typing as npt

from app.core.formulas.declare import formula

#: The ambient PV ratings are taken at [C] (igus rates pv at 68 F = 20 C).
REFERENCE_C = 20.0
#: The permissible PV's factor for each lubrication, with its provenance.
LUBRICATION_FACTORS: dict[str, tuple[float, str, str]] = {
    "dry": (1.0, "vendor", "polymer nut PV ratings are for dry running: igus, CSB"),
    "greased": (
        1.3,
        "vendor",
        "igus, p x v value and lubrication, Table 1.4: greased at installation 1.3; "
        "continuously greased 2.0",
    ),
    "oiled": (
        2.0,
        "vendor",
        "BNB Industries: lubrication can increase the capacity as much as 100 %; "
        "igus Table 1.4 gives its own materials 5 continuously oiled",
    ),
}

FloatArray = npt.NDArray[np.float64]


@formula(
    "f_T = clip((T_max - T_ambient) / (T_max - T_ref), 0, 1)",
    "igus, iglide p x v value: permitted pv proportional to T_a - T_u; rated at 68 F",
)
def temperature_factor(ambient_c: float, max_c: float, reference_c: float = REFERENCE_C) -> float:
    """The share of the rated PV a polymer nut keeps at the ambient ``ambient_c`` [C]: 1
    up to the reference ambient, then a straight line to 0 at the material's highest
    operating temperature ``max_c`` [C]. Valid for ``max_c`` above the reference.

    iglide H (igus): 39,000 psi fpm at 68 F, highest long-term 392 F; at 212 F (100 C)
    the permitted pv is 39,000 (392 - 212) / (392 - 68) = 21,667 psi fpm, 5/9 of it:

    >>> round(temperature_factor(100.0, 200.0), 4), round((392 - 212) / (392 - 68), 4)
    (0.5556, 0.5556)
    >>> temperature_factor(15.0, 93.0), temperature_factor(120.0, 93.0)
    (1.0, 0.0)
    """
    if ambient_c <= reference_c:
        return 1.0
    return max(0.0, (max_c - ambient_c) / (max_c - reference_c))


def temperature_factors(ambient_c: float, max_c: FloatArray) -> FloatArray:
    """``temperature_factor`` at one ambient [C] for many materials' highest temperatures
    ``max_c`` [C]; 1 where a highest temperature is unknown (NaN) or not above the
    reference. At an ambient up to the reference every factor is 1 (the clipped share
    is at least 1 there), so none is worked out.

    >>> temperature_factors(56.5, np.array([93.0, np.nan, 10.0])).tolist()
    [0.5, 1.0, 1.0]
    >>> temperature_factors(20.0, np.array([93.0, np.nan])).tolist()
    [1.0, 1.0]
    """
    if ambient_c <= REFERENCE_C:
        return np.ones(len(max_c))
    span = max_c - REFERENCE_C
    with np.errstate(invalid="ignore", divide="ignore"):
        share = np.clip((max_c - ambient_c) / span, 0.0, 1.0)
    return np.where(np.isfinite(share) & (span > 0), share, 1.0)
