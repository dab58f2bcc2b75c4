"""The numbers of a screw of one's own, one row each, as the application's inputs are
(``InputField``, ``app.contract.fields``): the API's models (``CustomScrewIn``,
``MaterialIn`` in ``app.contract.screws``), the /custom page's fields and share links
(``app.web.screw_form``) and the core's SI values (``app.report.present.custom_screw``)
all read these rows, in this order (a field's checks read the fields before it).

The page and the API name a screw's number alike (``outer_diameter_mm``); ``core`` is the
name of the value in SI (``app.catalog.own.OwnGeometry``, the screw material's values).
"""

from app.contract.input_field import Default, InputField
from app.contract.units import Quantity

#: the page's group of the screw's numbers and of its own material's.
SCREW_GROUP = "Screw"
MATERIAL_GROUP = "Screw material"
#: the flank half-angle's unit: the core takes radians (``OwnGeometry``).
HALF_ANGLE_UNIT = "deg"


def _number(
    api: str,
    core: str,
    label: str,
    *,
    bounds: tuple[float, float],
    help: str = "",
    dimension: Quantity | None = None,
    unit: str = "",
    default: Default = None,
    required: bool = False,
    group: str = SCREW_GROUP,
) -> InputField:
    """One number of the screw, its API and page name alike."""
    return InputField(
        api=api,
        page=api,
        core=core,
        label=label,
        help=help,
        group=group,
        kind="number",
        required=required,
        default=default,
        bounds=bounds,
        dimension=dimension,
        unit=unit,
    )


#: the screw's geometry, friction, drag, inertia, nut PV limit and thread pitch (its
#: material and nut material, which are no numbers, are ``CustomScrewInputs``' own).
SCREW_FIELDS = (
    _number(
        "outer_diameter_mm",
        "outer_diameter_m",
        "Outer diameter",
        bounds=(0.1, 1000.0),
        dimension="length",
        required=True,
    ),
    _number(
        "root_diameter_mm",
        "root_diameter_m",
        "Root (minor) diameter",
        bounds=(0.05, 1000.0),
        help="Below the outer",
        dimension="length",
        required=True,
    ),
    _number("lead_mm", "lead_m", "Lead", bounds=(0.01, 1000.0), dimension="length", required=True),
    _number(
        "thread_half_angle_deg",
        "thread_half_angle_rad",
        "Flank half-angle",
        bounds=(0.0, 30.0),
        help="14.5 Acme, 15 trapezoidal",
        unit=HALF_ANGLE_UNIT,
        default=14.5,
    ),
    _number(
        "friction_dynamic",
        "friction_dynamic",
        "Running friction coefficient",
        bounds=(1e-3, 1.0),
        required=True,
    ),
    _number(
        "friction_static",
        "friction_static",
        "Static friction coefficient",
        bounds=(1e-3, 1.0),
        required=True,
    ),
    _number(
        "drag_torque_nm",
        "drag_torque_nm",
        "Nut drag torque",
        bounds=(0.0, 1e4),
        dimension="torque",
        default=0.0,
    ),
    _number(
        "inertia_kg_m2_per_m",
        "inertia_kg_m2_per_m",
        "Inertia per length",
        bounds=(1e-15, 1e3),
        help="Default: solid rod at the pitch diameter",
        dimension="inertia_per_length",
    ),
    _number(
        "pv_limit_mpa_m_s", "pv_limit_pa_m_s", "Nut PV limit", bounds=(1e-6, 1e3), dimension="pv"
    ),
    _number(
        "pitch_mm",
        "pitch_m",
        "Thread pitch",
        bounds=(0.01, 1000.0),
        help="The lead over the starts",
        dimension="length",
    ),
)

#: the user's own screw material (the named ones are the catalog's).
MATERIAL_FIELDS = (
    _number(
        "youngs_modulus_pa",
        "youngs_modulus_pa",
        "Young's modulus",
        bounds=(1e6, 1e13),
        unit="Pa",
        required=True,
        group=MATERIAL_GROUP,
    ),
    _number(
        "density_kg_m3",
        "density_kg_m3",
        "Density",
        bounds=(1.0, 1e5),
        dimension="density",
        required=True,
        group=MATERIAL_GROUP,
    ),
    _number(
        "yield_strength_pa",
        "yield_strength_pa",
        "Yield strength",
        bounds=(1e6, 1e10),
        help="Without it, Euler buckling only",
        unit="Pa",
        group=MATERIAL_GROUP,
    ),
    _number(
        "expansion_per_k",
        "expansion_per_k",
        "Thermal expansion",
        bounds=(1e-7, 1e-3),
        help="Per kelvin (aluminium about 23e-6); without it steel's, assumed",
        unit="1/K",
        group=MATERIAL_GROUP,
    ),
)
#: every row by its API (and page) name.
BY_NAME = {f.api: f for f in (*SCREW_FIELDS, *MATERIAL_FIELDS)}
#: the flank half-angle, typed in degrees (``HALF_ANGLE_UNIT``), which the core takes in
#: radians: the one number no factor of the unit table converts.
HALF_ANGLE = BY_NAME["thread_half_angle_deg"]
