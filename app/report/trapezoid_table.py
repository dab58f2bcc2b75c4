"""A distributor's table of ISO metric trapezoidal screws, Tr 10 x 2 to Tr 20 x 20 (P5):
the printed lead angle and the efficiency at thread friction 0.1 and 0.2, against the
core's geometry (ISO 2904 pitch diameter, lead angle) and efficiency formulas.

The table's efficiencies are those of the square-thread form, tan l / tan(l + atan f): the
15 degree flank of the trapezoidal thread, which raises the normal force and so the
friction by 1 / cos 15 deg, is not in them. The core's square-thread formula gives every
row within 1 %; the flank form that the app's selection uses gives 1 to 3.5 % less, so the
app asks the motor for more torque than the table would.
"""

import math
from dataclasses import dataclass

from app.core.formulas import efficiency, geometry, trapezoidal
from app.core.units import to_si

SOURCE = (
    "Transdev, Trapezoidal Screw Specifications, columns lead angle and efficiency at "
    "f = 0.1 and 0.2 "
    "(http://www.transdev.co.uk/hardware/trapizoidal-screws-nuts/trapizoidal-screw-specifications/)"
)
#: the flank half-angle of the ISO metric trapezoidal thread (30 degrees included).
FLANK_HALF_ANGLE_DEG = 15.0
MM = to_si(1.0, "mm")


@dataclass(frozen=True, slots=True)
class Row:
    """One size as printed: nominal diameter, pitch and lead [m], the lead angle in degrees
    and minutes, the efficiency at f = 0.1 and at f = 0.2."""

    name: str
    nominal_m: float
    pitch_m: float
    lead_m: float
    angle_deg: int
    angle_min: int
    efficiency_f01: float
    efficiency_f02: float

    @property
    def published_angle_deg(self) -> float:
        """The printed lead angle in decimal degrees."""
        return self.angle_deg + self.angle_min / 60.0


# fmt: off
ROWS: tuple[Row, ...] = (
    Row("Tr 10 x 2", 10 * MM, 2 * MM, 2 * MM, 4, 2, 0.41, 0.26),
    Row("Tr 10 x 3", 10 * MM, 3 * MM, 3 * MM, 6, 25, 0.52, 0.35),
    Row("Tr 10 x 4 (P2)", 10 * MM, 2 * MM, 4 * MM, 8, 3, 0.58, 0.40),
    Row("Tr 12 x 3", 12 * MM, 3 * MM, 3 * MM, 5, 12, 0.47, 0.31),
    Row("Tr 12 x 6 (P3)", 12 * MM, 3 * MM, 6 * MM, 10, 19, 0.63, 0.46),
    Row("Tr 14 x 3", 14 * MM, 3 * MM, 3 * MM, 4, 22, 0.43, 0.27),
    Row("Tr 14 x 4", 14 * MM, 4 * MM, 4 * MM, 6, 3, 0.51, 0.34),
    Row("Tr 14 x 6 (P3)", 14 * MM, 3 * MM, 6 * MM, 8, 41, 0.59, 0.42),
    Row("Tr 16 x 4", 16 * MM, 4 * MM, 4 * MM, 5, 12, 0.47, 0.31),
    Row("Tr 16 x 8 (P4)", 16 * MM, 4 * MM, 8 * MM, 10, 19, 0.63, 0.46),
    Row("Tr 18 x 4", 18 * MM, 4 * MM, 4 * MM, 4, 33, 0.44, 0.28),
    Row("Tr 18 x 8 (P4)", 18 * MM, 4 * MM, 8 * MM, 9, 2, 0.60, 0.43),
    Row("Tr 20 x 4", 20 * MM, 4 * MM, 4 * MM, 4, 3, 0.41, 0.26),
    Row("Tr 20 x 8 (P4)", 20 * MM, 4 * MM, 8 * MM, 8, 3, 0.58, 0.40),
    Row("Tr 20 x 20 (P5)", 20 * MM, 5 * MM, 20 * MM, 20, 0, 0.76, 0.60),
)
# fmt: on
BY_NAME = {row.name: row for row in ROWS}


def tan_lead(row: Row) -> float:
    """tan of the lead angle on the basic pitch diameter d2 = d - P / 2 (ISO 2904)."""
    return geometry.tan_lead_angle(
        row.lead_m, trapezoidal.pitch_diameter(row.nominal_m, row.pitch_m)
    )


def lead_angle_deg(row: Row) -> float:
    """The core's lead angle of the size [deg]."""
    return math.degrees(math.atan(tan_lead(row)))


def table_efficiency(row: Row, friction: float) -> float:
    """The core's square-thread efficiency, the table's own form."""
    return efficiency.square_thread_efficiency(tan_lead(row), friction)


def flank_efficiency(row: Row, friction: float) -> float:
    """The core's efficiency with the 15 degree flank, the form the selection uses."""
    cos_flank = math.cos(math.radians(FLANK_HALF_ANGLE_DEG))
    return efficiency.forward_efficiency(tan_lead(row), friction, cos_flank)
