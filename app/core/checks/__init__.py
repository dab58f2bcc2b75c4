"""The check registry: every check, listed once, in the order results list them.

Screening, evaluation, the formulas table, the API's check list and the page iterate
``REGISTRY`` in its order. Adding a check is adding its module here, one line in
``REGISTRY`` and its test (a module of this package that is not listed fails the tests).
"""

from app.core.checks.accuracy import Accuracy
from app.core.checks.anti_backlash import AntiBacklash
from app.core.checks.back_driving import BackDriving
from app.core.checks.ball_life import BallLife
from app.core.checks.ball_load import BallLoad
from app.core.checks.ball_speed import BallSpeed
from app.core.checks.ball_static import BallStatic
from app.core.checks.base import Check
from app.core.checks.bearing_pressure import BearingPressure
from app.core.checks.buckling import ColumnBuckling
from app.core.checks.critical_speed import CriticalSpeed
from app.core.checks.design_load import DesignLoad
from app.core.checks.holding import Holding
from app.core.checks.inertia_ratio import InertiaRatio
from app.core.checks.length import Length
from app.core.checks.life import Life
from app.core.checks.lubrication import Lubrication
from app.core.checks.max_sliding_speed import MaxSlidingSpeed
from app.core.checks.motor_curve import MotorCurve
from app.core.checks.motor_rms import MotorRms
from app.core.checks.motor_speed import MotorSpeed
from app.core.checks.motor_supply import MotorSupply
from app.core.checks.nut_heat import NutHeat
from app.core.checks.oil import OilCompatibility
from app.core.checks.power_off import HoldingPowerOff
from app.core.checks.preload_release import PreloadRelease
from app.core.checks.pv import NutPV
from app.core.checks.root_stress import RootStress
from app.core.checks.step_rate import StepRate
from app.core.checks.step_resolution import StepResolution
from app.core.checks.stroke_travel import StrokeTravel
from app.core.checks.support_life import SupportLife
from app.core.checks.support_static import SupportStatic
from app.core.checks.temperature import Temperature
from app.core.checks.torque import DriveTorque
from app.core.checks.traverse_speed import TraverseSpeed
from app.core.checks.vacuum import Vacuum
from app.core.checks.wear_life import WearLife

#: Every check, in the order results list them: the motor's, the screw's, the nut's,
#: the catalog's limits, then back-driving and the advice.
REGISTRY: tuple[Check, ...] = (
    DriveTorque(),
    MotorCurve(),
    MotorRms(),
    MotorSpeed(),
    MotorSupply(),
    InertiaRatio(),
    StepRate(),
    CriticalSpeed(),
    ColumnBuckling(),
    RootStress(),
    SupportStatic(),
    NutPV(),
    BearingPressure(),
    MaxSlidingSpeed(),
    TraverseSpeed(),
    BallSpeed(),
    DesignLoad(),
    BallStatic(),
    Length(),
    StrokeTravel(),
    OilCompatibility(),
    Lubrication(),
    Temperature(),
    NutHeat(),
    BackDriving(),
    Holding(),
    HoldingPowerOff(),
    AntiBacklash(),
    PreloadRelease(),
    Life(),
    BallLife(),
    BallLoad(),
    SupportLife(),
    WearLife(),
    Accuracy(),
    StepResolution(),
    Vacuum(),
)
BY_NAME: dict[str, Check] = {c.name: c for c in REGISTRY}

__all__ = ["BY_NAME", "REGISTRY", "Check"]
