"""Monotonicity and invariance of every check over the whole catalog, screw by screw.

Each property compares the screening of one axis with that of the same axis made harder
(or easier) in one input, for every catalog screw at once (``screen_table``). They hold
where the physics says they must:

- a load that opposes the motion both ways on a horizontal axis (friction, cutting) only
  ever adds thrust, so more of it never lowers a thrust, a running or break-away torque,
  the PV, the wear thrust or the nut's heat, and never raises a life. A peak or RMS motor
  torque may fall: in a braking segment the opposing load helps the motor stop, and a
  self-locking thread brakes a heavier mass by its own friction (Shigley sec. 8-2, the
  lowering torque T_L). So the motor's own checks are left out of the pass/fail property
  (no motor here), and the torque property is the signed one, segment by segment;
- a faster move raises the screw speed, the PV, the nut's heat and the critical-speed
  utilisation, and never raises a life of a duty given in cycles a day;
- a longer screw never raises the critical speed or the buckling load; a stiffer end
  fixity never lowers either;
- a hotter ambient never passes a temperature or nut-heat check a cooler one fails; more
  required life or more cycles a day never passes a screw that failed;
- ``select`` and ``evaluate`` give the same numbers for the same screw.

The acceleration and the deceleration are above 0 here: 0 means the speed is reached at
once, with no inertia force counted (the input's help: "0 for constant speed").
"""

import math
from dataclasses import replace
from itertools import pairwise

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from app.core.evaluate import evaluate
from app.core.model import FIXITY_ORDER, Application
from app.core.quantities import NAMES, quantity
from app.core.screening import Screening, screen_table
from app.core.segments import moving_torques
from app.core.selection import select
from tests.builtin_catalog import builtin_catalog

RTOL = 1e-9
SETTINGS = settings(
    max_examples=25,
    derandomize=True,
    deadline=None,
    phases=(Phase.explicit, Phase.generate),
)
CATALOG = builtin_catalog()


@st.composite
def horizontal_axes(draw: st.DrawFn) -> Application:
    """A horizontal axis whose load opposes the motion both ways, with a stroke and a
    duty in cycles a day: loads 0-5 kN, speeds 5-500 mm/s, screws 0.1-2 m, ramps
    0.05-10 m/s^2, masses 0-50 kg, any end fixity, lubrication and ambient."""
    length = draw(st.floats(0.1, 2.0))
    return Application(
        load_n=draw(st.floats(0.0, 5000.0)),
        speed_m_s=draw(st.floats(0.005, 0.5)),
        length_m=length,
        accel_m_s2=draw(st.floats(0.05, 10.0)),
        decel_m_s2=draw(st.none() | st.floats(0.05, 10.0)),
        moving_mass_kg=draw(st.floats(0.0, 50.0)),
        guide_friction=draw(st.sampled_from([0.0, 0.003, 0.1])),
        load_direction=draw(st.sampled_from(["auto", "opposes"])),
        end_fixity=draw(st.sampled_from(FIXITY_ORDER)),
        lubrication=draw(st.sampled_from(["dry", "greased", "oiled"])),
        ambient_c=draw(st.floats(0.0, 60.0)),
        compression=draw(st.booleans()),
        stroke_m=length * draw(st.floats(0.05, 0.8)),
        dwell_s=draw(st.sampled_from([0.0, 0.5])),
        cycles_per_day=draw(st.floats(1.0, 2000.0)),
        required_life_years=draw(st.floats(0.5, 10.0)),
    )


def _screen(app: Application) -> Screening:
    return screen_table(app, CATALOG.index.table)


def _number(s: Screening, name: str) -> np.ndarray:
    return np.asarray(quantity(s.quantities, name), dtype=float)


def _never_lower(before: np.ndarray, after: np.ndarray) -> np.ndarray:
    """Where ``after`` is below ``before`` beyond rounding (both finite)."""
    finite = np.isfinite(before) & np.isfinite(after)
    return finite & (after < before - RTOL * np.abs(before) - 1e-12)


def _wrong_way(s0: Screening, s1: Screening, up: tuple[str, ...], down: tuple[str, ...]) -> dict:
    """The numbers that moved the wrong way, by name, with the screws where they did."""
    wrong = {}
    for names, sign in ((up, 1.0), (down, -1.0)):
        for name in names:
            bad = _never_lower(sign * _number(s0, name), sign * _number(s1, name))
            if bad.any():
                wrong[name] = np.flatnonzero(bad)[:5].tolist()
    return wrong


def _newly_passed(s0: Screening, s1: Screening, checks: tuple[str, ...] = ()) -> dict:
    """The checks (all of them, and the verdict) a screw fails before and passes after."""
    out = {}
    for name in checks or tuple(s0.failed):
        if name in s0.failed and name in s1.failed:
            bad = s0.failed[name] & ~s1.failed[name]
            if bad.any():
                out[name] = np.flatnonzero(bad)[:5].tolist()
    if not checks and (~s0.passed & s1.passed).any():
        out["passed"] = np.flatnonzero(~s0.passed & s1.passed)[:5].tolist()
    return out


#: numbers a harder axis (more opposing load, mass, acceleration) never lowers
THRUST_UP = (
    "force_n",
    "peak_force_n",
    "pv_force_n",
    "pv_pa_m_s",
    "pressure_pa",
    "wear_force_n",
    "ball_load_n",
    "support_mean_load_n",
    "friction_power_w",
    "nut_temperature_rise_k",
    "total_nm",
    "breakaway_nm",
    "root_stress_pa",
)
#: lives it never raises
LIFE_DOWN = ("life_years_min", "life_years_max", "wear_life_years", "support_life_years")


@SETTINGS
@given(app=horizontal_axes(), more=st.floats(1.0, 2000.0))
def test_more_opposing_load_is_never_easier(app: Application, more: float):
    harder = replace(app, load_n=app.load_n + more)
    s0, s1 = _screen(app), _screen(harder)
    assert _wrong_way(s0, s1, THRUST_UP, LIFE_DOWN) == {}
    assert _newly_passed(s0, s1) == {}


@SETTINGS
@given(app=horizontal_axes(), more=st.floats(1.0, 2000.0))
def test_opposing_load_raises_every_segment_torque(app: Application, more: float):
    """The motor torque of every moving segment, with its sign, rises with a load that
    opposes the motion: by lead / (2 pi eta) where the motor drives the thread and by
    lead eta_b / (2 pi) where the mass drives it (Shigley sec. 8-2), on a thread that
    does not self-lock at running friction. One that does (eta_b < 0) needs the motor to
    push the load down the thread, T_L = F d_m / 2 tan(phi - lambda) > 0, which a smaller
    overhauling force lowers: there the signed torque falls, then rises past F = 0."""
    harder = replace(app, load_n=app.load_n + more)
    table = CATALOG.index.table
    free = table.backdrive_efficiency_signed >= 0.0
    for before, after in zip(
        moving_torques(app, table), moving_torques(harder, table), strict=True
    ):
        assert not (free & _never_lower(before[3], after[3])).any(), before[:2]


@SETTINGS
@given(app=horizontal_axes(), more=st.floats(0.1, 20.0))
def test_more_moving_mass_never_lowers_the_thrust(app: Application, more: float):
    harder = replace(app, moving_mass_kg=app.moving_mass_kg + more)
    up = ("force_n", "peak_force_n", "inertia_mass_nm", "inertia_kg_m2", "breakaway_nm")
    assert _wrong_way(_screen(app), _screen(harder), up, ()) == {}


@SETTINGS
@given(app=horizontal_axes(), factor=st.floats(1.01, 3.0))
def test_faster_is_never_easier(app: Application, factor: float):
    faster = replace(app, speed_m_s=app.speed_m_s * factor)
    s0, s1 = _screen(app), _screen(faster)
    up = ("rpm", "pv_rpm", "pv_pa_m_s", "peak_rpm", "heat_speed_m_s", "friction_power_w")
    assert _wrong_way(s0, s1, (*up, "nut_temperature_rise_k"), LIFE_DOWN) == {}
    for name in ("critical_speed", "pv", "nut_heat", "ball_speed", "max_sliding_speed"):
        u0, u1 = s0.utilization.get(name), s1.utilization.get(name)
        if u0 is not None and u1 is not None:
            assert not _never_lower(u0, u1).any(), name
    assert _newly_passed(s0, s1, ("critical_speed", "pv", "nut_heat", "life")) == {}


@SETTINGS
@given(app=horizontal_axes(), factor=st.floats(1.01, 1.5))
def test_longer_screw_never_raises_the_column_limits(app: Application, factor: float):
    longer = replace(app, length_m=app.length_m * factor)
    limits = ("critical_rpm", "allowed_rpm", "critical_load_n", "allowed_load_n")
    assert _wrong_way(_screen(app), _screen(longer), (), limits) == {}


@SETTINGS
@given(app=horizontal_axes())
def test_stiffer_ends_never_lower_the_column_limits(app: Application):
    limits = ("critical_rpm", "allowed_rpm", "critical_load_n", "allowed_load_n")
    screened = [_screen(replace(app, end_fixity=f)) for f in FIXITY_ORDER]
    for s0, s1 in pairwise(screened):
        assert _wrong_way(s0, s1, limits, ()) == {}
        assert not (s0.passed & ~s1.passed).any()


@SETTINGS
@given(app=horizontal_axes(), hotter=st.floats(1.0, 60.0))
def test_hotter_never_passes_a_temperature_check(app: Application, hotter: float):
    """The nut-heat check does not judge a nut whose ambient is above its rating: the
    temperature check fails that one (``nut_heat.headroom``), so the two are read
    together."""
    warm = replace(app, ambient_c=app.ambient_c + hotter)
    s0, s1 = _screen(app), _screen(warm)
    assert _newly_passed(s0, s1, ("pv",)) == {}
    hot = [s.failed["temperature"] | s.failed["nut_heat"] for s in (s0, s1)]
    assert not (hot[0] & ~hot[1]).any()


@SETTINGS
@given(app=horizontal_axes(), factor=st.floats(1.01, 3.0))
def test_more_life_or_cycles_never_passes_a_screw(app: Application, factor: float):
    s0 = _screen(app)
    longer = replace(app, required_life_years=(app.required_life_years or 1.0) * factor)
    busier = replace(app, cycles_per_day=min(5000.0, (app.cycles_per_day or 1.0) * factor))
    for harder in (longer, busier):
        s1 = _screen(harder)
        assert _newly_passed(s0, s1) == {}
        assert _wrong_way(s0, s1, ("nut_temperature_rise_k",), ()) == {}


@settings(max_examples=6, derandomize=True, deadline=None, phases=(Phase.explicit, Phase.generate))
@given(app=horizontal_axes())
def test_select_and_evaluate_agree(app: Application):
    """The numbers of a screw ranked among all others are those of it evaluated alone."""
    chosen = select(replace(app, limit=15), CATALOG.index)
    for c in [*chosen.candidates, *chosen.rejected]:
        alone = evaluate(app, CATALOG.by_id[c.screw.id], CATALOG.index.table.reach)
        for name in NAMES:
            x, y = float(quantity(c.quantities, name)), float(quantity(alone.quantities, name))
            assert x == pytest.approx(y, rel=RTOL, nan_ok=True) or (math.isnan(x) and math.isnan(y))
        assert c.passed == alone.passed
        assert c.max_utilization == pytest.approx(alone.max_utilization, rel=RTOL)
