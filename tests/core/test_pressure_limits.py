"""The nut pressure limits the PV chart draws (app.core.sweep.pressure_limits): the
pressure each nut's material allows against the sliding speed, from the limits the
checks use, with each nut's operating pressure and speed."""

import math

import numpy as np
import pytest

from app.catalog import Catalog
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.sweep import PressureLimit, pressure_limits

APP = Application(load_n=100.0, speed_m_s=0.05, length_m=0.5)
#: ISO nuts judged on their flanks (bronze: a pressure-speed table; PTFE: p_max and PV)
#: and a seed nut judged by its PV limit.
IDS = ("Tr8x4(P2)-bronze", "Tr10x4(P2)-ptfe", "B8000-L10-TFE")


@pytest.mark.parametrize("screw_id", IDS)
def test_the_curve_at_the_operating_speed_is_the_checks_limit(
    catalog: Catalog, screw_id: str
) -> None:
    """Drawn at the operating speed alone (span 1), the allowed pressure is the check's:
    its utilization is the operating pressure over the allowed one (F over p_allow A on
    the flanks; PV over PV_lim for the seed's nut, p v / (p_allow v))."""
    (line,) = pressure_limits(APP, catalog.index, [screw_id], 1.0, 1)
    assert line.speeds_m_s == (pytest.approx(line.speed_m_s, rel=1e-12),)
    check = next(c for c in evaluate(APP, catalog.by_id[screw_id]).checks if c.name == line.check)
    assert check.utilization == pytest.approx(line.pressure_pa / line.allowed_pa[0], rel=1e-9)


def test_the_bronze_curve_reads_shigleys_table(catalog: Catalog) -> None:
    """Steel on bronze, Shigley Table 8-4 (after Rothbart), low end of each range as the
    catalog takes it (catalog/iso-trapezoidal/common.toml): 1600 psi (11 MPa) to 10
    ft/min (0.05 m/s), 800 psi (5.5 MPa) at 20-40 ft/min (0.1-0.2 m/s), 150 psi (1 MPa)
    from 50 ft/min (0.25 m/s)."""
    (line,) = pressure_limits(APP, catalog.index, ["Tr8x4(P2)-bronze"], 10.0, 41)
    assert line.check == "bearing_pressure"
    table = [(0.0, 0.05, 11.0e6), (0.1, 0.2, 5.5e6), (0.25, 100.0, 1.0e6)]
    seen = 0
    for speed, allowed in zip(line.speeds_m_s, line.allowed_pa, strict=True):
        for low, high, pressure in table:
            if low <= speed <= high:
                assert allowed == pytest.approx(pressure, rel=1e-9), speed
                seen += 1
    assert seen >= 20  # most points fall in a flat part of the table


def test_the_seed_nuts_curve_is_its_pv_limit_over_the_speed(catalog: Catalog) -> None:
    """p = PV_lim / v: pressure times speed is the PV check's limit all along."""
    (line,) = pressure_limits(APP, catalog.index, ["B8000-L10-TFE"], 10.0, 41)
    pv = next(c for c in evaluate(APP, catalog.by_id["B8000-L10-TFE"]).checks if c.name == "pv")
    assert line.check == "pv"
    for speed, allowed in zip(line.speeds_m_s, line.allowed_pa, strict=True):
        assert speed * allowed == pytest.approx(pv.limit, rel=1e-9)


def test_nuts_share_the_speeds_so_one_material_draws_one_curve(catalog: Catalog) -> None:
    """Two bronze nuts at different sliding speeds allow the same pressure at each of the
    shared speeds, which run from the slowest operating speed / 10 to the fastest x 10."""
    lines = pressure_limits(APP, catalog.index, ["Tr8x4(P2)-bronze", "Tr10x4(P2)-bronze"], 10, 9)
    first, second = lines
    assert first.speed_m_s != pytest.approx(second.speed_m_s)
    assert first.speeds_m_s == second.speeds_m_s
    assert first.allowed_pa == second.allowed_pa
    slow, fast = sorted(line.speed_m_s for line in lines)
    assert first.speeds_m_s[0] == pytest.approx(slow / 10)
    assert first.speeds_m_s[-1] == pytest.approx(fast * 10)


def drawn(line: PressureLimit, speed_m_s: float) -> float:
    """The allowed pressure the chart shows at ``speed_m_s``: its points joined by
    straight lines on its log-log axes."""
    logs = np.log(line.speeds_m_s), np.log(line.allowed_pa)
    return float(np.exp(np.interp(math.log(speed_m_s), *logs)))


def test_the_line_as_drawn_never_rises_above_the_checks_limit(catalog: Catalog) -> None:
    """Three bronze nuts at 20 mm/s (Tr14x3 at 400 rpm, Tr18x4 and Tr20x4 at 300 rpm)
    share one curve, drawn from 1/10 of the slowest sliding speed to 10 times the
    fastest. Tr18x4-bronze slides at 0.2521 m/s, just past the corner of Shigley's table
    where the allowed pressure falls from 5.5 MPa (0.2 m/s) to 1 MPa (0.25 m/s) and
    stays: the bearing-pressure check allows 1 MPa. Drawn at 41 speeds alone, the
    straight line between the two nearest, 0.2376 m/s (2.12 MPa) and 0.2673 m/s (1 MPa),
    passed 1.45 MPa at its operating speed (Tr14x3-bronze's: 1.12 MPa), a margin 1.45
    times the check's. With the table's corners and the operating speeds among its
    points, the line at each operating speed is the check's limit, and it is nowhere
    above the limit on a fine grid of speeds."""
    app = Application(load_n=150.0, speed_m_s=0.02, length_m=0.6)
    ids = ["Tr14x3-bronze", "Tr18x4-bronze", "Tr20x4-bronze"]
    lines = pressure_limits(app, catalog.index, ids, 10.0, 41)
    assert lines[1].speed_m_s == pytest.approx(0.2521, abs=5e-5)
    for line in lines:
        checks = evaluate(app, catalog.by_id[line.id]).checks
        check = next(c for c in checks if c.name == "bearing_pressure")
        assert drawn(line, line.speed_m_s) == pytest.approx(1.0e6)
        assert line.pressure_pa / drawn(line, line.speed_m_s) == pytest.approx(check.utilization)
    fine = pressure_limits(app, catalog.index, ids, 10.0, 4001)[0]
    for speed, allowed in zip(fine.speeds_m_s, fine.allowed_pa, strict=True):
        assert drawn(lines[0], speed) <= allowed * (1 + 1e-9), speed
