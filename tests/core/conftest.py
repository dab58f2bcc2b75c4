"""Shared pieces of the core tests: unit factors for the test edge and a reference screw.

The core is SI throughout; published examples are in inches, pounds, psi and ft/min, so the
tests convert at their own edge with these exact factors.
"""

import math
from dataclasses import replace

import pytest
from hypothesis import strategies as st

from app.catalog import Catalog
from app.core.model import FIXITY_ORDER, Application, ScrewSpec

IN = 0.0254  # m per inch (exact)
LBF = 4.4482216152605  # N per pound-force (exact)
PSI = 6894.757293168  # Pa per psi
FT_PER_MIN = 0.00508  # m/s per ft/min (exact)
PSI_FT_MIN = PSI * FT_PER_MIN  # Pa m/s per psi ft/min

STEEL_E, STEEL_RHO = 206e9, 7850.0  # engineering.md section 4, carbon steel
SS303_E, SS303_RHO = 193e9, 8000.0  # engineering.md section 4, 303 stainless

FIXITIES = FIXITY_ORDER

#: Acme 29-deg thread: cos of the 14.5 deg flank half-angle (engineering.md section 2)
COS_ACME = math.cos(math.radians(14.5))


@pytest.fixture(scope="session")
def zbx8000_l10(catalog: Catalog) -> ScrewSpec:
    """ZBX8000 (1/2 in), 10 mm lead, uncoated: a mid-catalog anti-backlash screw."""
    return catalog.by_id["ZBX8000-L10"]


@pytest.fixture(scope="session")
def b8000_l10(catalog: Catalog) -> ScrewSpec:
    """B8000 (1/2 in), 10 mm lead, uncoated: free-wheeling, no drag, no life rating."""
    return catalog.by_id["B8000-L10"]


def light_app(**changes: object) -> Application:
    """A light horizontal axis that every mid-size screw passes; tests change one thing."""
    base = Application(load_n=50.0, speed_m_s=0.05, length_m=0.5)
    return replace(base, **changes)  # type: ignore[arg-type]


#: Applications over every option the core reads, for property tests.
applications = st.builds(
    Application,
    load_n=st.floats(1.0, 3000.0),
    speed_m_s=st.floats(0.001, 1.0),
    length_m=st.floats(0.05, 4.5),
    accel_m_s2=st.floats(0.0, 10.0),
    moving_mass_kg=st.floats(0.0, 20.0),
    end_fixity=st.sampled_from(["fixed-free", "simple-simple", "fixed-simple", "fixed-fixed"]),
    orientation=st.sampled_from(["horizontal", "vertical"]),
    compression=st.booleans(),
    require_anti_backlash=st.booleans(),
    coating=st.sampled_from(["auto", "tfe", "none"]),
    oil_present=st.booleans(),
    ambient_c=st.floats(-20.0, 120.0),
    stroke_m=st.none() | st.floats(0.01, 2.0),
    cycles_per_day=st.none() | st.floats(1.0, 5000.0),
    required_life_years=st.none() | st.floats(0.1, 20.0),
    positioning_tolerance_m=st.none() | st.floats(1e-5, 2e-3),
    max_torque_nm=st.none() | st.floats(0.01, 5.0),
    lead_m=st.none() | st.sampled_from([0.002, 0.01, 0.0127, 0.025]),
)
