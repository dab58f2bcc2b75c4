"""A HIWIN ball screw's column against HIWIN's own buckling rule (BS-08-2-EN-1704-K, sec.
3.7.4: F_k = 4.072e5 f_k d_k^4 / l_s^2 [N, mm], f_k 0.5 fixed-supported, permissible
F_kmax = 0.5 F_k, F 3.25 and F 3.26), run through the core with the built-in catalog."""

import pytest

from app.catalog import Catalog
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.units import from_si


def test_hiwin_r20_05_column_is_within_hiwins_permissible_load(catalog: Catalog) -> None:
    """R20-05K4-FSCDIN (d_k 16.9 mm) over 1000 mm, fixed-supported: HIWIN's F_k = 4.072e5
    x 0.5 x 16.9^4 / 1000^2 = 16,608 N and F_kmax = 8,304 N. The core, Euler with C45's
    207 GPa, rates 16,361 N and allows half, 8,181 N: 1.5 % below HIWIN's, unchanged by
    the makers' rule (HIWIN's own is the higher)."""
    screw = catalog.by_id["R20-05K4-FSCDIN"]
    assert screw.buckling_rule == "HIWIN F 3.25"
    app = Application(load_n=100.0, speed_m_s=0.05, length_m=1.0, end_fixity="fixed-simple")
    column = evaluate(app, screw).buckling
    d_k, l_s = from_si(screw.root_diameter_m, "mm"), 1000.0
    f_k = 4.072e5 * 0.5 * d_k**4 / l_s**2
    assert (f_k, 0.5 * f_k) == pytest.approx((16608.0, 8304.0), rel=1e-3)
    assert column.critical_load_n == pytest.approx(16361.0, rel=1e-3)
    assert column.allowed_load_n == pytest.approx(8181.0, rel=1e-3)
    assert column.allowed_load_n <= 0.5 * f_k
