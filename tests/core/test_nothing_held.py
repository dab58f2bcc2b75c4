"""An axis that leaves nothing on the nut at rest has nothing to hold with the power off."""

from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.core.model import Application
from app.core.selection import select

HORIZONTAL = Application(
    load_n=0.0, speed_m_s=0.05, length_m=0.5, load_direction="fixed", hold_power_off=True
)
VERTICAL = Application(
    load_n=30.0,
    speed_m_s=0.05,
    length_m=0.5,
    orientation="vertical",
    load_direction="opposes",
    hold_power_off=True,
)


@pytest.mark.parametrize("app", [HORIZONTAL, VERTICAL], ids=["fixed-0-N", "vertical-no-mass"])
def test_nothing_held_rejects_no_screw_for_back_driving(catalog: Catalog, app: Application) -> None:
    """A horizontal axis whose fixed load is 0 N, and a vertical one moving no mass
    against a load that opposes its motion (friction holds nothing at rest), leave 0 N on
    the nut at rest: no screw fails for back-driving (639 did), as none does for the same
    axis without the power-off hold. With 1 kg on the vertical one, its weight is held and
    the back-driving check judges again."""
    held = select(app, catalog.index)
    free = select(replace(app, hold_power_off=False), catalog.index)
    assert "back_driving" not in held.failed_by_check
    assert held.passed == free.passed
    weighed = select(replace(VERTICAL, moving_mass_kg=1.0), catalog.index)
    assert weighed.failed_by_check.get("back_driving", 0) > 0
