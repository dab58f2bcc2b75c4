"""What to order: one line per candidate that a buyer can send for a quote, and the
basis it rests on (a maker's ordering-code scheme, a standard's designation, or neither).

Rules, each cited where it is used:

- ISO metric trapezoidal screws (a pitch given, 30° flank): the designation of ISO 2903
  clause 12 (also DIN 103): ``Tr d x P`` for one start, ``Tr d x lead (P pitch)`` for
  several (iso-trapezoidal.md: "Tr16x8(P4)"), with the tolerance class: 7e for the
  screw, 7H for the nut, the medium class ISO 2903 clause 9 recommends for the normal
  length of engagement (one of its seven recommended classes, 7H 8H 9H 7e 8e 8c 9c:
  ISO 2903-2:2025 scope, standards.iteh.ai).
- The seed's series (B, ZBX, KHD, VHD): the seed prints no part-number scheme, only
  "we can custom machine screws to your requirements (quote to your drawings)", "lengths
  can be specified up to 4 m, or up to 2.4 m with TFE coating" (End Machining) and
  "please fax for a quote"; so the line is a specification, not a maker's code.
- Ball screws: HIWIN's order code, explained in HIWIN GmbH's ballscrew catalogue
  (Ballscrews & Accessories, www.hiwin.de), section "HIWIN order code" (sec. 1.2 of the
  edition whose contents list it so; sec. 2.2.4, p. 95, of HIWIN GmbH's combined
  catalogue): [starts][R/L][nominal d]-[lead][K/T/B recirculation][circuits]-[nut
  type]-[thread length]-[total length]-[lead deviation per 300 mm], e.g.
  2R40-20K4-FSCDIN-800-1000-0,052 (starts "1" may be left out); the shaft alone
  1R40-10-800-1000-0,052, the nut alone R40-10K3-FSCDIN (the page as published:
  https://vettevideo.com/hiwin_catalogues/linear_guideways/hiwin_linear_guideways_95.html).
  The ball-filling letter (D, T, Q for two to four starts filled) has no printed example
  and is not written. The catalog's nut id is
  the code up to the nut type; the lengths are the buyer's drawing's. The part is a ball
  screw per ISO 3408 (formerly DIN 69051), its tolerance class (T7 rolled, T3 ground)
  the family's.
- A value the catalog only assumes (provenance kind ``assumed``, which a rating worked
  from an assumed input has too) is named after "Confirm with the maker:" with the value
  taken.

Lengths are written in mm, the unit of the standard's designation and of the seed's
catalog, whatever the page's display units.
"""

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import replace
from fractions import Fraction

from app.core.model import Provenance, ScrewSpec
from app.core.units import from_si

#: ISO 2903 clause 9: the medium tolerance class for the normal length of engagement.
SCREW_CLASS = "7e"
NUT_CLASS = "7H"
#: The flank half-angle of ISO 2901's basic profile (30° flank angle), degrees.
ISO_HALF_ANGLE_DEG = 15.0
#: The seed's families: one maker's series (catalog/common.toml, group ``seed``).
SEED_FAMILIES = frozenset({"B", "ZBX", "KHD", "VHD"})

#: Screw materials in a buyer's words (catalog material names; others as named).
MATERIALS = {
    "stainless-303": "303 stainless steel, rolled",
    "stainless-304": "1.4301 (304) stainless steel, rolled",
    "c45-steel": "C45 (1.0503) steel, rolled",
    "steel": "carbon steel",
}
#: Nut materials in a buyer's words (catalog nut materials; others as named).
NUTS = {
    "bronze": "bronze (CuSn7Zn4 / CuSn12)",
    "acetal": "acetal (POM)",
    "polyacetal": "polyacetal with lubricating additive",
    "PTFE-filled polymer": "PTFE-filled polymer",
}

#: The nut's shape: the catalog does not give it, so the buyer states it.
NUT_SHAPE = "flange or cylindrical: to state (the catalog does not give the nut's shape)"

SEED_BASIS = (
    "No ordering code: the seed prints no part-number scheme (End Machining: 'quote to "
    "your drawings'; 'please fax for a quote'), so this is a specification to quote, and "
    "the catalog id is not a maker's part number. Maker: not named in the seed; its axial "
    "take-up text and 50 lb preload example match Kerk Motion Products, now AMETEK Haydon "
    "Kerk (kerkmotion.com KerkTech anti-backlash overview; patent EP1084355B1), but no "
    "Kerk page lists the B, ZBX, KHD or VHD series, so the maker is inferred, not published."
)
ISO_BASIS = (
    "ISO 2904 / DIN 103 trapezoidal thread, designated as ISO 2903 clause 12 writes it "
    "(Tr d x P; several starts Tr d x lead (P pitch)); tolerance class 7e screw / 7H nut, "
    "the medium class ISO 2903 clause 9 recommends for a normal length of engagement. Any "
    "maker of trapezoidal screws can quote it; the catalog names no maker."
)
BALL_BASIS = (
    "HIWIN order code, as HIWIN GmbH's ballscrew catalogue (Ballscrews & Accessories, "
    "www.hiwin.de) explains it in its section 'HIWIN order code': thread direction and "
    "nominal diameter, lead, recirculation type and circuits, nut type (the catalog's nut "
    "id, from catalogue BS-08-2-EN-1704-K Tables 4.4, 4.5 and 6.4), then thread length, "
    "total length and lead deviation per 300 mm (the tolerance class). A ball screw per "
    "ISO 3408 (formerly DIN 69051)."
)
BALL_OTHER_BASIS = (
    "A ball-screw family of your own: the catalog names no maker's order code; the line is "
    "a specification per ISO 3408 (formerly DIN 69051)."
)
CUSTOM_BASIS = "Your own screw: no catalog series and no standard designation."
OTHER_BASIS = "A catalog series of your own: the catalog names no maker or ordering code."


def _mm(value_m: float) -> str:
    """A length [m] in mm, to six significant figures without float noise.

    >>> _mm(0.009525), _mm(0.5), _mm(0.0127)
    ('9.525', '500', '12.7')
    """
    return f"{from_si(value_m, 'mm'):.6g}"


def _inch_fraction(value_m: float) -> str | None:
    """A diameter [m] as a fraction of an inch when it is a whole number of sixteenths
    (the seed's size rule, catalog/README.md), else None.

    >>> _inch_fraction(0.009525), _inch_fraction(0.0127), _inch_fraction(0.016)
    ('3/8', '1/2', None)
    """
    sixteenths = from_si(value_m, "in") * 16
    if not math.isclose(sixteenths, round(sixteenths), rel_tol=1e-7):
        return None
    inches = Fraction(round(sixteenths), 16)
    return str(inches) if inches.denominator > 1 else f"{inches}"


def _length(length_m: float) -> str:
    """The screw's length as the app takes it (between the supports, the input's help)
    and its ends, which the seed machines to the buyer's drawing (End Machining)."""
    return f"{_mm(length_m)} mm between the supports plus the ends, end machining to drawing"


def iso_designation(spec: ScrewSpec) -> str | None:
    """The ISO 2903 clause 12 designation of the thread without its tolerance class,
    ``Tr16x4`` or ``Tr16x8(P4)``; None unless the screw is an ISO trapezoidal thread (a
    pitch given, a 30° flank, a whole number of starts)."""
    if spec.pitch_m is None or spec.pitch_m <= 0.0:
        return None
    if not math.isclose(math.degrees(spec.thread_half_angle_rad), ISO_HALF_ANGLE_DEG):
        return None
    starts = spec.lead_m / spec.pitch_m
    if not math.isclose(starts, round(starts)) or round(starts) < 1:
        return None
    d, pitch = _mm(spec.outer_diameter_m), _mm(spec.pitch_m)
    return f"Tr{d}x{pitch}" if round(starts) == 1 else f"Tr{d}x{_mm(spec.lead_m)}(P{pitch})"


#: The values a maker can confirm: provenance key, what it is, and the value taken.
CONFIRMABLE: tuple[tuple[str, str, Callable[[ScrewSpec], str | None]], ...] = (
    ("lead", "that this lead is made in this size", lambda s: f"{_mm(s.lead_m)} mm"),
    (
        "thread_half_angle",
        "the thread form",
        lambda s: f"{2 * math.degrees(s.thread_half_angle_rad):.3g}° flank angle",
    ),
    ("root_diameter", "the root diameter", lambda s: f"{from_si(s.root_diameter_m, 'mm'):.3g} mm"),
    (
        "design_load",
        "the nut's design load",
        lambda s: None if s.design_load_n is None else f"{s.design_load_n:.3g} N",
    ),
    (
        "pv_limit",
        "the nut's PV limit",
        lambda s: (
            None
            if s.pv_limit_pa_m_s is None
            else f"{from_si(s.pv_limit_pa_m_s, 'MPa m/s'):.3g} MPa m/s"
        ),
    ),
    (
        "bearing_pv_limit",
        "the nut's PV limit",
        lambda s: (
            None
            if s.nut_pv_limit_pa_m_s is None
            else f"{from_si(s.nut_pv_limit_pa_m_s, 'MPa m/s'):.3g} MPa m/s"
        ),
    ),
    (
        "max_pressure",
        "the nut's allowable contact pressure",
        lambda s: (
            None if s.max_pressure_pa is None else f"{from_si(s.max_pressure_pa, 'MPa'):.3g} MPa"
        ),
    ),
    (
        "max_sliding_speed",
        "the nut's maximum sliding speed",
        lambda s: None if s.max_sliding_speed_m_s is None else f"{s.max_sliding_speed_m_s:.3g} m/s",
    ),
    (
        "nut_length",
        "the nut length",
        lambda s: None if s.nut_length_m is None else f"{_mm(s.nut_length_m)} mm",
    ),
    ("friction_static", "the static friction coefficient", lambda s: f"{s.friction_static:g}"),
    ("friction_dynamic", "the running friction coefficient", lambda s: f"{s.friction_dynamic:g}"),
    (
        "backlash",
        "the axial play",
        lambda s: (
            None
            if s.backlash_min_m is None or s.backlash_max_m is None
            else f"{_mm(s.backlash_min_m)}-{_mm(s.backlash_max_m)} mm"
        ),
    ),
    (
        "wear_rate",
        "the nut's wear rate",
        lambda s: (
            None
            if s.wear_rate_m2_n is None
            else f"{from_si(s.wear_rate_m2_n, 'mm³/(N m)'):.2g} mm³/(N m)"
        ),
    ),
)


def _assumed(spec: ScrewSpec, key: str) -> bool:
    """Whether the catalog only assumes value ``key``: its provenance kind is ``assumed``
    (a value worked from an assumed one, as the seed's design load from its assumed
    contact pressure, is assumed too)."""
    provenance = spec.provenance.get(key)
    return provenance is not None and provenance.kind == "assumed"


def to_confirm(spec: ScrewSpec) -> list[str]:
    """What to confirm with the maker: each confirmable value the catalog assumes, with
    the value taken ("the root diameter (taken as 7.43 mm)"), in ``CONFIRMABLE`` order."""
    out = []
    for key, what, value in CONFIRMABLE:
        taken = value(spec)
        if taken is not None and _assumed(spec, key):
            out.append(f"{what} (taken as {taken})")
    return out


def _nut_words(spec: ScrewSpec) -> str:
    return NUTS.get(spec.nut_material, spec.nut_material or "material to state")


def _screw_words(spec: ScrewSpec) -> str:
    return MATERIALS.get(spec.material_name, spec.material_name or "material to state")


def _iso_line(spec: ScrewSpec, thread: str, length_m: float) -> str:
    """ISO 2903 clause 12: screw class 7e, nut class 7H (medium, normal engagement)."""
    nut_length = "" if spec.nut_length_m is None else f", at least {_mm(spec.nut_length_m)} mm long"
    return (
        f"Trapezoidal leadscrew {thread}-{SCREW_CLASS} right-hand, {_screw_words(spec)}, "
        f"{_length(length_m)}; nut {thread}-{NUT_CLASS}, {_nut_words(spec)}{nut_length}, "
        f"{NUT_SHAPE}."
    )


def _series_line(spec: ScrewSpec, length_m: float) -> str:
    """The seed's series: its size (series number = sixteenths of an inch, derived), lead,
    coating and nut (seed: Physical properties, TFE Coating, End Machining)."""
    inch = _inch_fraction(spec.outer_diameter_m)
    size = (
        f"{inch} in ({_mm(spec.outer_diameter_m)} mm)"
        if inch
        else f"{_mm(spec.outer_diameter_m)} mm"
    )
    kind = "anti-backlash (axial take-up)" if spec.anti_backlash else "free-wheeling"
    coating = "TFE coated" if spec.coated else "uncoated"
    return (
        f"{spec.series_id} leadscrew assembly: screw {size} OD, lead {_mm(spec.lead_m)} mm, "
        f"{_screw_words(spec)}, {coating}, {_length(length_m)}; nut {kind}, "
        f"{_nut_words(spec)}, {NUT_SHAPE}."
    )


def _custom_line(spec: ScrewSpec, length_m: float) -> str:
    """A screw of the user's own: its geometry, and its pitch and starts where given (the
    flank pressure, the lead angle and the torque are worked on d2 = d - 0.5 P); its nut
    in the material and length the nut checks rated, where a nut material is given."""
    flank = 2 * math.degrees(spec.thread_half_angle_rad)
    pitch = ""
    if spec.pitch_m:
        starts = round(spec.lead_m / spec.pitch_m)
        pitch = f", pitch {_mm(spec.pitch_m)} mm ({starts} start{'s' if starts > 1 else ''})"
    if spec.nut_material:
        length = "" if spec.nut_length_m is None else f", at least {_mm(spec.nut_length_m)} mm long"
        nut = f"nut to match, {_nut_words(spec)}{length}, shape to state"
    else:
        nut = "nut to match: material and shape to state"
    return (
        f"Leadscrew to your geometry: outer diameter {_mm(spec.outer_diameter_m)} mm, root "
        f"diameter {_mm(spec.root_diameter_m)} mm, lead {_mm(spec.lead_m)} mm{pitch}, "
        f"{flank:.3g}° flank angle, {_screw_words(spec)}, {_length(length_m)}; {nut}."
    )


#: A HIWIN nut code (module docstring): thread direction, nominal diameter, lead,
#: recirculation type and number of circuits, nut shape and type.
HIWIN_NUT = re.compile(r"([RL])(\d+(?:\.\d+)?)-(\d+(?:\.\d+)?)([KTB])(\d+)-([A-Z]+)")


def _hiwin_size(value_mm: float) -> str:
    """A diameter or lead [mm] as HIWIN's codes write it: two digits before the point.

    >>> _hiwin_size(8.0), _hiwin_size(2.5), _hiwin_size(40.0)
    ('08', '02.5', '40')
    """
    whole, _, fraction = f"{value_mm:g}".partition(".")
    return whole.zfill(2) + ("." + fraction if fraction else "")


def _hiwin_lengths(
    thread_mm: float | None, total_mm: float | None, deviation_mm: float | None
) -> str:
    """The shaft's part of a HIWIN code: thread length, total length [mm] (a placeholder
    where the buyer's drawing gives it) and the lead deviation per 300 mm [mm], with a
    decimal comma."""
    thread = "<thread length>" if thread_mm is None else f"{thread_mm:g}"
    total = "<total length>" if total_mm is None else f"{total_mm:g}"
    deviation = "" if deviation_mm is None else "-" + f"{deviation_mm:.6g}".replace(".", ",")
    return f"{thread}-{total}{deviation}"


def hiwin_nut_code(
    hand: str, nominal_mm: float, lead_mm: float, recirculation: str, circuits: int, nut: str
) -> str:
    """HIWIN's code of a nut without the shaft (module docstring): ``hand`` R or L,
    nominal diameter and lead [mm], recirculation K (cassette), T (internal) or B
    (external) and the number of circuits, nut shape and type (e.g. FSCDIN)."""
    return f"{hand}{_hiwin_size(nominal_mm)}-{_hiwin_size(lead_mm)}{recirculation}{circuits}-{nut}"


def hiwin_order_code(
    nut_code: str,
    thread_mm: float | None,
    total_mm: float | None,
    deviation_mm: float | None,
    starts: int | None = None,
) -> str:
    """HIWIN's code of a ball screw, shaft and nut (module docstring): the number of
    thread starts (None leaves out the single start, as HIWIN allows), the nut's code,
    thread and total length [mm] and the lead deviation per 300 mm [mm]."""
    return f"{starts or ''}{nut_code}-{_hiwin_lengths(thread_mm, total_mm, deviation_mm)}"


def hiwin_shaft_code(
    hand: str,
    nominal_mm: float,
    lead_mm: float,
    thread_mm: float | None,
    total_mm: float | None,
    deviation_mm: float | None,
    starts: int | None = None,
) -> str:
    """HIWIN's code of a ball-screw shaft without the nut (module docstring)."""
    size = f"{hand}{_hiwin_size(nominal_mm)}-{_hiwin_size(lead_mm)}"
    return f"{starts or ''}{size}-{_hiwin_lengths(thread_mm, total_mm, deviation_mm)}"


def _nominal_diameter_mm(code: str, outer_m: float) -> str:
    """A ball screw's nominal diameter [mm] from its maker's code, else its outer
    diameter [m] in mm.

    >>> _nominal_diameter_mm("R20-10K3-FSCDIN", 0.0193)
    '20'
    >>> _nominal_diameter_mm("R08-02.5T2-RSIT", 0.0077)
    '8'
    >>> _nominal_diameter_mm("MY16-05", 0.0155)
    '15.5'
    """
    found = re.match(r"[RL](\d+(?:\.\d+)?)-", code)
    return f"{float(found.group(1)):g}" if found else _mm(outer_m)


def _preload_words(spec: ScrewSpec) -> str:
    """A ball nut's play or preload as the family gives it."""
    if not spec.preload_n:
        play = f"axial play at most {_mm(spec.backlash_max_m)} mm, " if spec.backlash_max_m else ""
        return f"{play}no preload"
    share = (
        ""
        if not spec.dynamic_load_n
        else f", {100 * spec.preload_n / spec.dynamic_load_n:.3g} % of Ca"
    )
    return f"preloaded ({spec.preload_n:.3g} N{share})"


def _ball_confirm(spec: ScrewSpec) -> list[str]:
    """What to confirm with the maker of a ball screw: each assumed value it rests on."""
    out = []
    if spec.preload_n and _assumed(spec, "preload"):
        out.append(
            f"the preload (taken as {spec.preload_n:.3g} N, the largest a single nut allows; "
            "the drag torque is computed at it)"
        )
    if spec.temperature_max_c is not None and _assumed(spec, "temperature_range"):
        out.append(
            f"the operating temperature range (taken as {spec.temperature_min_c:g} to "
            f"{spec.temperature_max_c:g} °C)"
        )
    return out


def _ball_line(spec: ScrewSpec, length_m: float) -> str:
    """A ball screw: the maker's order code (HIWIN's, module docstring) with the lengths
    to state, then the part in words: ISO 3408, nominal diameter x lead, rolled or ground,
    tolerance class and lead deviation, nut and preload, lengths and end machining."""
    e300 = spec.travel_variation_300mm_m
    code = ""
    if spec.family_id.startswith("HIWIN"):
        deviation = None if e300 is None else from_si(e300, "mm")
        code = f"HIWIN {hiwin_order_code(spec.id, None, None, deviation)} (HIWIN order code); "
    grade = spec.accuracy_grade or "to state"
    nominal = _nominal_diameter_mm(spec.id, spec.outer_diameter_m)
    steel = _screw_words(spec).removesuffix(", rolled")
    deviation_words = "" if e300 is None else f", lead deviation {_mm(e300)} mm per 300 mm"
    nut_length = "" if spec.nut_length_m is None else f", {_mm(spec.nut_length_m)} mm long"
    return (
        f"{code}ball screw per ISO 3408 (DIN 69051), nominal diameter "
        f"{nominal} x lead {_mm(spec.lead_m)} mm, {spec.variant}, "
        f"tolerance class {grade}{deviation_words}, {steel}; nut "
        f"{spec.id.rsplit('-', 1)[-1]}{nut_length}, {_preload_words(spec)}; threaded length "
        f"to cover the stroke plus the nut, {_length(length_m)}."
    )


def as_rated(
    spec: ScrewSpec, nut_length_m: float, provenance: Mapping[str, Provenance]
) -> ScrewSpec:
    """``spec`` with the nut length its nut checks were worked at, ``nut_length_m`` [m]
    (the application's where it gives one, else the catalog's; NaN where no check reads
    a nut length, a thread without a pitch), and that length's ``provenance``: a line
    that ordered the catalog's nut where the checks rated a longer one would buy a nut
    that carries less than the numbers say."""
    if spec.nut_length_m is None or not math.isfinite(nut_length_m):
        return spec
    length_provenance = provenance.get("nut_length", spec.provenance.get("nut_length"))
    if length_provenance is None:
        return spec
    rated = {**spec.provenance, "nut_length": length_provenance}
    return replace(spec, nut_length_m=nut_length_m, provenance=rated)


def ordering_line(spec: ScrewSpec, length_m: float) -> str:
    """The line a buyer sends for a quote of ``spec`` at screw length ``length_m`` [m]:
    the ISO 2903 designation with its tolerance class for an ISO trapezoidal screw, else a
    specification (size, lead, screw and nut materials, nut type, length, "end machining
    to drawing"); then what to confirm with the maker where the catalog assumes a value
    (``to_confirm``). No maker publishes an ordering-code scheme for the catalog's series
    (module docstring), so no maker's code is given.

    >>> from app.core.model import Provenance
    >>> spec = ScrewSpec(
    ...     id="Tr16x8(P4)-bronze", series_id="Tr16-P4", series_name="Tr16 P4",
    ...     anti_backlash=False, coated=False, outer_diameter_m=0.016,
    ...     root_diameter_m=0.0115, lead_m=0.008, thread_half_angle_rad=math.radians(15),
    ...     friction_static=0.16, friction_dynamic=0.13, youngs_modulus_pa=207e9,
    ...     density_kg_m3=7800.0, screw_expansion_per_k=11.7e-6, inertia_kg_m2_per_m=2.9e-5,
    ...     material_name="c45-steel", nut_material="bronze", family_id="TR-C45",
    ...     pitch_m=0.004, nut_length_m=0.032,
    ...     provenance={"nut_length": Provenance("assumed", "2 x d")})
    >>> print(ordering_line(spec, 0.5))  # doctest: +NORMALIZE_WHITESPACE
    Trapezoidal leadscrew Tr16x8(P4)-7e right-hand, C45 (1.0503) steel, rolled, 500 mm
    between the supports plus the ends, end machining to drawing; nut Tr16x8(P4)-7H,
    bronze (CuSn7Zn4 / CuSn12), at least 32 mm long, flange or cylindrical: to state (the
    catalog does not give the nut's shape). Confirm with the maker: the nut length (taken as 32 mm).
    """
    thread = iso_designation(spec)
    if spec.screw_type == "ball":
        confirm = _ball_confirm(spec)
        line = _ball_line(spec, length_m)
        return f"{line} Confirm with the maker: {'; '.join(confirm)}." if confirm else line
    if spec.series_id == "custom":
        line = _custom_line(spec, length_m)
    elif thread is not None:
        line = _iso_line(spec, thread, length_m)
    else:
        line = _series_line(spec, length_m)
    confirm = to_confirm(spec)
    return f"{line} Confirm with the maker: {'; '.join(confirm)}." if confirm else line


def ordering_basis(spec: ScrewSpec) -> str:
    """What the ordering line rests on: the standard and its clauses for an ISO screw,
    the seed's want of a part-number scheme and what is public of its maker for the
    seed's series, else that the catalog names no maker."""
    if spec.screw_type == "ball":
        return BALL_BASIS if spec.family_id.startswith("HIWIN") else BALL_OTHER_BASIS
    if spec.series_id == "custom":
        return CUSTOM_BASIS
    if iso_designation(spec) is not None:
        return ISO_BASIS
    return SEED_BASIS if spec.family_id in SEED_FAMILIES else OTHER_BASIS
