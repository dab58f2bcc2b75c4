"""ISO metric trapezoidal thread (ISO 2904 basic profile, DIN 103) from its pitch.

A standard screw's diameters follow from its nominal diameter d and pitch P, so the
catalog gives d and P and these functions give the rest (values with provenance
"standard"). Lengths in metres. Source: ISO 2904 basic and design profiles, as summarised
in iso-trapezoidal.md (flank angle 30 degrees).
"""

#: Crest clearance a_c [m] by the largest pitch [m] it applies to (ISO 2904).
CREST_CLEARANCE_BY_PITCH_M = ((0.0015, 0.00015), (0.005, 0.00025), (0.012, 0.0005), (0.044, 0.001))


def crest_clearance(pitch_m: float) -> float:
    """Crest clearance a_c [m] for a pitch P [m]: 0.15 mm for P = 1.5 mm, 0.25 mm for
    2-5 mm, 0.5 mm for 6-12 mm, 1 mm for 14-44 mm (ISO 2904).

    Valid for 1.5 mm <= P <= 44 mm; a pitch between two classes takes the next class up.

    >>> crest_clearance(0.0015), crest_clearance(0.004), crest_clearance(0.008)
    (0.00015, 0.00025, 0.0005)
    """
    for largest_pitch_m, clearance_m in CREST_CLEARANCE_BY_PITCH_M:
        if pitch_m <= largest_pitch_m + 1e-12:
            return clearance_m
    largest_m = CREST_CLEARANCE_BY_PITCH_M[-1][0]
    raise ValueError(f"pitch {pitch_m:g} m is above the ISO 2904 range (up to {largest_m:g} m)")


def pitch_diameter(nominal_diameter_m: float, pitch_m: float) -> float:
    """Pitch diameter d2 = d - 0.5 P [m] (ISO 2904).

    >>> round(pitch_diameter(0.008, 0.0015) * 1e3, 6)
    7.25
    """
    return nominal_diameter_m - 0.5 * pitch_m


def minor_diameter(nominal_diameter_m: float, pitch_m: float) -> float:
    """Screw minor (root) diameter d3 = d - 2 h3, h3 = 0.5 P + a_c [m] (ISO 2904).

    >>> round(minor_diameter(0.008, 0.0015) * 1e3, 6), round(minor_diameter(0.03, 0.006) * 1e3, 6)
    (6.2, 23.0)
    """
    return nominal_diameter_m - 2.0 * (0.5 * pitch_m + crest_clearance(pitch_m))


def flank_height(pitch_m: float) -> float:
    """Engaged flank height (thread overlap) H1 = 0.5 P [m] (ISO 2904 basic profile).

    >>> flank_height(0.004)
    0.002
    """
    return 0.5 * pitch_m
