"""The output table's rows of the screw and nut: the catalog's id, kind and ratings,
and the thread's geometry."""

from app.contract.reported.row import Formula, Reported
from app.contract.source import From
from app.core.formulas import geometry

NUT: tuple[Reported, ...] = (
    Reported(
        "id",
        "Screw",
        "Catalog id; the tags say whether the screw is TFE coated and the nut takes up the "
        "play (anti-backlash), or that it is a ball screw (preloaded or not).",
        cell="screw",
        column=True,
        csv=True,
        type=str,
    ),
    Reported("series", csv=True, type=str),
    Reported(
        "screw_type",
        "Type",
        "'lead': a sliding nut (PV, flank pressure, wear); 'ball': a rolling ball nut "
        "(L10 life, static load, DN speed; it always back-drives).",
        cell="text",
        column=True,
        csv=True,
        compare=True,
        views=("row", "summary", "csv"),
        source=From("screw.screw_type"),
        type=str,
    ),
    Reported(
        "dynamic_load_n",
        "Ca",
        "A ball nut's basic dynamic load rating: the axial load at which 90 % of nuts run "
        "10^6 revolutions (the maker's table; empty for a leadscrew).",
        quantity="force",
        better="higher",
        csv=True,
        compare=True,
        views=("row", "csv"),
        source=From("screw.dynamic_load_n", "force"),
    ),
    Reported(
        "static_load_n",
        "C0a",
        "A ball nut's basic static load rating: the axial load that dents the ball track "
        "by 0.0001 of the ball diameter (the maker's table; empty for a leadscrew).",
        quantity="force",
        better="higher",
        csv=True,
        compare=True,
        views=("row", "csv"),
        source=From("screw.static_load_n", "force"),
    ),
    Reported("anti_backlash", csv=True, type=bool),
    Reported(
        "nut_material",
        "Nut material",
        "The nut's material, as the catalog names it.",
        cell="text",
        compare=True,
        type=str,
    ),
)


GEOMETRY: tuple[Reported, ...] = (
    Reported(
        "outer_diameter_mm",
        "OD",
        "Outer (major) diameter of the thread.",
        quantity="length",
        column=True,
        ranks=("size",),
        csv=True,
        compare=True,
    ),
    Reported("root_diameter_mm", quantity="length", csv=True),
    Reported("pitch_diameter_mm", formula=Formula(geometry.pitch_diameter)),
    Reported(
        "lead_mm",
        "Lead",
        "Travel of the nut per turn of the screw.",
        quantity="length",
        column=True,
        css="lead",
        csv=True,
        compare=True,
    ),
    Reported("lead_angle_deg", formula=Formula(geometry.lead_angle)),
    Reported("coated", csv=True, type=bool),
)
