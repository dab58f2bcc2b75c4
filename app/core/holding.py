"""Holding the load at rest for many candidates at once: whether the thread self-locks with
margin, the torque a brake (or the motor) must hold otherwise, and the power-off hold's
margins.
"""

from typing import Any, Literal

import numpy as np

from app.core import motion
from app.core.formulas import (
    efficiency,
)
from app.core.model import Application, holds
from app.core.table import Array, CandidateTable, filled


def holding(app: Application, t: CandidateTable, force_n: float) -> dict[str, Any]:
    """Holding the load ``force_n`` at standstill (``motion.steady_load``: friction holds
    nothing). The thread counts as self-locking only with static friction reduced by
    ``app.self_locking_friction_factor``; otherwise a brake (or the motor) must hold the
    larger of the seed's value (forward efficiency, running friction) and the physical one
    at that same distrusted friction (back-drive efficiency at f mu_s), times the holding
    safety factor of what holds it (``brake_factor``); a brake fitted to hold it, times a
    brake's (``brake_to_fit_nm``: at least the service factor, whatever holds it now)."""
    mu_margin = t.friction_static * app.self_locking_friction_factor
    locks = mu_margin >= t.self_locking_friction
    seed = efficiency.holding_torque(force_n, t.lead_m, t.efficiency)
    physics = efficiency.holding_torque(force_n, t.lead_m, t.backdrive_efficiency)
    distrusted = efficiency.holding_torque(
        force_n,
        t.lead_m,
        efficiency.backdrive_efficiency(t.tan_lead_angle, mu_margin, t.cos_half_angle),
    )
    unlocked = np.maximum(seed, distrusted)
    brake = np.where(locks, 0.0, unlocked)
    factor = brake_factor(app)
    max_lock = efficiency.max_self_locking_lead(t.pitch_diameter_m, mu_margin, t.cos_half_angle)
    return {
        **hold_margins(app, t, max_lock, unlocked * factor),
        "holding_seed_nm": np.where(locks, 0.0, seed),
        "holding_physics_nm": physics,
        "holding_distrusted_nm": distrusted,
        "brake_nm": brake,
        "brake_needed_nm": brake * factor,
        "brake_to_fit_nm": brake * brake_factor(app, brake=True),
        "locks_with_margin": locks.astype(np.float64),
        "max_self_locking_lead_with_margin_m": max_lock,
    }


def unpowered_holder(app: Application) -> Literal["brake", "detent"] | None:
    """What holds the load with the power off besides the thread: the brake, where the
    holding torque given is a brake's, else a stepper's detent torque where one is given
    (its energised holding torque does not count); None: nothing."""
    if app.holding_source == "brake" and app.brake_torque_nm is not None:
        return "brake"
    return None if app.detent_torque_nm is None else "detent"


def unpowered_torque(app: Application) -> float | None:
    """The torque of what holds with the power off besides the thread (``unpowered_holder``)
    [N m]; None: nothing."""
    holder = unpowered_holder(app)
    return app.brake_torque_nm if holder == "brake" else app.detent_torque_nm


def hold_margins(
    app: Application, t: CandidateTable, max_lock_m: Array, needed_nm: Array
) -> dict[str, Any]:
    """The power-off hold's margins (``efficiency.hold_margin``): the thread's alone, and
    the hold's: the thread's where it holds (``holds``), else the unpowered torque's
    (``unpowered_torque``) over ``needed_nm`` where one is given, else the thread's: the
    margin of what holds, or would (the larger of the two read as the thread's 240× where
    a brake gave it, or as a 0.48× brake's 0.92×), and ``hold_by_thread`` which it is (1:
    the thread), which ``Record.holds_by`` names. NaN where holding with the power off is
    not required or no load is held."""
    nan = filled(len(t), np.nan)
    if not (app.hold_power_off and motion.holds_a_load(app)):
        return {"hold_thread_margin": nan, "hold_margin": nan, "hold_by_thread": nan}
    torque_nm = unpowered_torque(app)
    device = nan if torque_nm is None else filled(len(t), torque_nm)
    needed = np.where(needed_nm > 0.0, needed_nm, np.nan)
    thread = efficiency.hold_margin(max_lock_m, t.lead_m, nan, 1.0)
    unpowered = efficiency.hold_margin(nan, t.lead_m, device, needed)
    by_thread = holds(thread) | np.isnan(unpowered)
    return {
        "hold_thread_margin": thread,
        "hold_margin": np.where(by_thread, thread, unpowered),
        "hold_by_thread": by_thread.astype(np.float64),
    }


#: The service factor on the torque a brake holds where no holding factor is given: a
#: brake holds by friction, and wears. Machine Design ("Mechatronics Q & A: Hold It
#: Steady", 21 Nov 2007) gives 1.5 as the usual factor for a brake holding a ball or lead
#: screw, and 1.5 to 3 for brakes in general.
BRAKE_SERVICE_FACTOR = 1.5


def brake_factor(app: Application, brake: bool | None = None) -> float:
    """The safety factor on a holding torque: the one given, else the torque factor, and
    for a brake at least its service factor (``BRAKE_SERVICE_FACTOR``). ``brake``: whether
    a brake holds (a brake to fit: True); None: whether the given torque that holds is a
    brake's (``unpowered_holder``; a detent or an energised motor holds by no friction
    that wears)."""
    if app.brake_safety_factor is not None:
        return app.brake_safety_factor
    if unpowered_holder(app) == "brake" if brake is None else brake:
        return max(app.torque_safety_factor, BRAKE_SERVICE_FACTOR)
    return app.torque_safety_factor
