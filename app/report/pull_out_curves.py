"""Makers' published stepper pull-out curves as numbers, with the datasheet values the
stepper model needs, and the model's figure beside each point: the /validation page's
second table and ``tests/core/test_stepper.py`` read them. A curve the motor library
drives one of its motors by is read from the library (catalog/motors.toml,
``library_curve``): its points and datasheet values are kept there, with their provenance.

Each chart was read at its plotted points (markers, or the vertices of a vector chart)
from the maker's own document as kept in a public repository (named with its commit);
the axes calibrated on the chart's gridlines and the reading checked by overlaying the
points on the chart. Speeds in rpm (half step: 400 pulses a turn; 2000 microsteps: 2000),
torques in N m (charts in gf cm converted by the unit table). ``rms``: the chart prints
its drive current as an RMS value (Trinamic QSH4218-47-28-040: "coil current: 2.8A RMS");
every other chart prints a plain current ("1.0A / Phase", "CONSTANT CURRENT: 1.68A"),
read as the app reads a current by default, the sine's peak. For the Trinamic V1.03
charts at "1.0A / Phase" the later manual says RMS; their low-speed torque, 80-81 % of
the holding torque, sits with the peak reading (71 %) rather than the RMS one (100 %,
which the 2.8 A RMS motor does reach), and read as RMS the model would run up to 1.38
times them.
"""

from typing import NamedTuple

from app.catalog.motors import CURVE, MOTOR_FILE, load_motors
from app.core.formulas import stepper
from app.core.units import to_si
from app.paths import resource_dir

#: How far the model may lie from a published point, as the makers' curves scatter.
PULL_OUT_TOLERANCE = 0.15


class Curve(NamedTuple):
    """One published pull-out curve: the part, where the chart is, its drive, supply
    [V], current [A] (RMS-set or peak-set), winding resistance [ohm] and inductance [H],
    step angle [deg], holding torque [N m] and the points (rpm, N m)."""

    part: str
    source: str
    drive: str
    supply_v: float
    current_a: float
    rms: bool
    resistance_ohm: float
    inductance_h: float
    step_angle_deg: float
    holding_nm: float
    points: tuple[tuple[float, float], ...]

    @property
    def sine_drive(self) -> bool:
        """Run on a microstepping (sine) drive, the drive the model describes."""
        return "microstep" in self.drive

    @property
    def in_supply_range(self) -> bool:
        """The supply is in the model's range (``stepper.supply_in_range``)."""
        return stepper.supply_in_range(self.supply_v, self.current_a, self.resistance_ohm)

    def ratios(self) -> tuple[float, ...]:
        """The model's pull-out over the published torque at each point, the current read
        as the chart prints it (``stepper.microstep_pull_out_torque``)."""
        return tuple(
            stepper.microstep_pull_out_torque(rpm, *self.model_args, self.rms) / torque_nm
            for rpm, torque_nm in self.points
        )

    def within(self, ratios: tuple[float, ...] | None = None) -> bool:
        """Every point within ``PULL_OUT_TOLERANCE`` of the model (``ratios``: this curve's
        ``ratios()`` where already worked out)."""
        return all(abs(r - 1.0) <= PULL_OUT_TOLERANCE for r in ratios or self.ratios())

    @property
    def model_args(self) -> tuple[float, float, float, float, float, float]:
        return (
            self.supply_v,
            self.current_a,
            self.resistance_ohm,
            self.inductance_h,
            self.step_angle_deg,
            self.holding_nm,
        )


#: The built-in motor library: a curve it drives one of its motors by is kept there alone.
_LIBRARY = load_motors(resource_dir("catalog") / MOTOR_FILE)


def library_curve(motor_id: str, part: str, source: str, drive: str, rms: bool = False) -> Curve:
    """The published curve of the built-in library's motor ``motor_id``, its points
    (rpm, N m) and the datasheet values the model needs, all as catalog/motors.toml keeps
    them with their provenance (``rms``: the chart prints its current as an RMS value)."""
    value = {name: held.value for name, held in _LIBRARY[motor_id].values.items()}
    points = tuple((float(rpm), float(torque_nm)) for rpm, torque_nm in value[CURVE])
    return Curve(
        part,
        source,
        drive,
        value["supply_v"],
        value["phase_current_a"],
        rms,
        value["resistance_ohm"],
        value["inductance_mh"],  # held in H, as every library value is in SI
        value["step_angle_deg"],
        value["holding_torque_nm"],
        points,
    )


def _from_gf_cm(*points: tuple[float, float]) -> tuple[tuple[float, float], ...]:
    """A chart's points (rpm, gf cm) in N m, to 4 decimals (the unit table's gf cm)."""
    return tuple((rpm, round(to_si(torque, "gf cm"), 4)) for rpm, torque in points)


APM = (
    "STEPPERONLINE datasheet and torque-curve PDFs in jmpz63/APM, Projects/Moveo_Bridge/"
    "Onboarding/04_Hardware_Firmware_Network_Architecture/joint_datasheets/ (commit 411985f)"
)

SO_23HS32_48V = library_curve(
    "23hs32-4004s",
    "STEPPERONLINE 23HS32-4004S at 48 V",
    APM + ", joint2: 2.40 N m, 4.00 A, 0.65 ohm, 3.2 mH",
    "Leadshine DM542T, 2000 microsteps, peak 4.2 A",
)
#: The same motor and drive at 36 V (the point at 90 rpm lies under the 48 V marker).
SO_23HS32_36V = SO_23HS32_48V._replace(
    part="STEPPERONLINE 23HS32-4004S at 36 V",
    source=SO_23HS32_48V.source + " (the 36 V point at 90 rpm lies under the 48 V marker)",
    supply_v=36.0,
    points=((210.0, 1.772), (300.0, 1.639), (390.0, 1.392), (510.0, 1.228), (600.0, 1.027)),
)

CURVES = (
    SO_23HS32_48V,
    SO_23HS32_36V,
    Curve(
        "STEPPERONLINE 14HS17-0504S",
        APM + ", joint5: 0.23 N m, 0.50 A, 15 ohm, 26 mH; chart '0.5A/PHASE 20V CONSTANT "
        "CURRENT HALF STEP', gf cm",
        "half step, constant current 0.5 A",
        20.0,
        0.5,
        False,
        15.0,
        0.026,
        1.8,
        0.23,
        _from_gf_cm(
            (60, 1500),
            (90, 1700),
            (120, 1800),
            (150, 1800),
            (180, 1700),
            (210, 1600),
            (240, 1550),
            (270, 1500),
            (300, 1300),
            (330, 1200),
            (375, 1100),
            (420, 900),
            (450, 700),
        ),
    ),
    Curve(
        "STEPPERONLINE 17HS24-0644S",
        APM + ", joint1: 0.65 N m, 14.5 ohm, 35 mH (datasheet 0.60 A, chart '0.64A/P 24V "
        "HALF STEP'), g cm",
        "half step, 0.64 A",
        24.0,
        0.64,
        False,
        14.5,
        0.035,
        1.8,
        0.65,
        _from_gf_cm(
            (60, 5190),
            (90, 5090),
            (120, 4400),
            (150, 3800),
            (180, 3100),
            (210, 2510),
            (240, 1910),
            (270, 1510),
            (300, 1110),
            (330, 910),
            (360, 720),
            (390, 560),
            (420, 320),
        ),
    ),
    library_curve(
        "sy35st36-1004a",
        "Changzhou Songyang SY35ST36-1004A",
        "pichim/PM2_PES_Board_Example, docs/datasheets/SY35ST36-1004A.pdf (commit c256c7f); "
        "chart 'Pull out torque curve: VOLTAGE: 24VDC, CONSTANT CURRENT: 1.0A, HALF STEP'",
        "half step, 1.0 A",
    ),
    Curve(
        "Changzhou Songyang SY42STH38-1684A",
        "pichim/PM2_PES_Board_Example, docs/datasheets/SY42STH38-1684A.pdf (commit c256c7f); "
        "chart 'PULL out turque curve : VOLTAGE: 24VDC CONSTANT CURRENT : 1.68A HALF STEP'",
        "half step, 1.68 A",
        24.0,
        1.68,
        False,
        1.65,
        0.0032,
        1.8,
        0.36,
        (
            (30.0, 0.2606),
            (75.0, 0.2894),
            (105.0, 0.3),
            (135.0, 0.2803),
            (180.0, 0.2406),
            (270.0, 0.2406),
            (360.0, 0.225),
            (450.0, 0.2219),
            (600.0, 0.1953),
            (750.0, 0.1844),
        ),
    ),
    library_curve(
        "sy42sth47-1684b",
        "Changzhou Songyang SY42STH47-1684B",
        "rkoeppl/ueberramps, SY42STH47-1684B.pdf (commit bbc956f); chart 'Pull out torque "
        "curve: VOLTAGE: 24VDC, CONSTANT CURRENT: 1.68A, HALF STEP'",
        "half step, 1.68 A",
    ),
    Curve(
        "Trinamic (ADI) QSH4218-35-10-027",
        "SyedSiddiqShakir/powtech_laser_stepper, QSH4218_manual.pdf (commit 681e0c9), "
        "Figure 4.1, p. 6; "
        "chart 'Testing conditions: VM: 24V; 1.0A / Phase Driver: M325, half step'",
        "half step, 1.0 A",
        24.0,
        1.0,
        False,
        5.3,
        0.0066,
        1.8,
        0.27,
        (
            (75.3, 0.22),
            (150.0, 0.2),
            (225.0, 0.196),
            (300.1, 0.2),
            (374.7, 0.19),
            (450.0, 0.19),
            (599.8, 0.1641),
            (749.9, 0.1441),
            (900.0, 0.1199),
        ),
    ),
    Curve(
        "Trinamic (ADI) QSH4218-41-10-035",
        "SyedSiddiqShakir/powtech_laser_stepper, QSH4218_manual.pdf (commit 681e0c9), "
        "Figure 4.2, p. 6; "
        "chart 'Testing conditions: VM: 24V; 1.0A / Phase Driver: M325, half step'",
        "half step, 1.0 A",
        24.0,
        1.0,
        False,
        4.5,
        0.0075,
        1.8,
        0.35,
        (
            (75.0, 0.281),
            (150.0, 0.2988),
            (300.8, 0.2725),
            (450.0, 0.235),
            (600.0, 0.1776),
            (750.0, 0.1299),
            (900.0, 0.1097),
            (1050.0, 0.1009),
            (1200.0, 0.0928),
            (1349.2, 0.0778),
            (1499.2, 0.0568),
        ),
    ),
    library_curve(
        "qsh4218-47-28-040",
        "Trinamic (ADI) QSH4218-47-28-040",
        "thomasarmel/arduino_polytech_2019_2020, datasheets/QSH4218_manual.pdf (commit 1437bba), "
        "Figure 5.4, p. 8; "
        "chart 'Testing conditions: driver supply voltage: +24V DC, coil current: 2.8A RMS, "
        "half step operation'",
        "half step, 2.8 A RMS",
        rms=True,
    ),
    library_curve(
        "qsh4218-51-10-049",
        "Trinamic (ADI) QSH4218-51-10-049",
        "SyedSiddiqShakir/powtech_laser_stepper, QSH4218_manual.pdf (commit 681e0c9), "
        "Figure 4.3, p. 7; "
        "chart 'Testing conditions: VM: 24V; 1.0A / Phase Driver: M325, half step'",
        "half step, 1.0 A",
    ),
)
