"""Every HIWIN ball nut the catalog carries, line by line against the maker's printed table.

Source: HIWIN GmbH, Ballscrews & Accessories, catalogue BS-08-2-EN-1704-K (www.hiwin.de),
Table 4.4 (rolled flange single nut FSCDIN/FSIDIN, p. 35-36), Table 4.5 (rolled
cylindrical nut RSIT, p. 37) and Table 6.4 (ground DIN single nut FSC, p. 48-49). The
lines below are transcribed from that catalogue (a text copy of it is in the public
repository ArtemFilin1990/Mar, file ``12_Прочее_сопутствующее/Прочее/Ballscrews.md``).

The ratings are HIWIN GmbH's printed Newton figures, and the catalog takes them as
printed: a rating is never above what the maker publishes for the nut. Where HIWIN
Taiwan prints the same nut in kgf (Ballscrew Technical Information, S99TE) and that
figure times 9.80665 is the lower one, the catalog would have to take it; no copy of
those kgf tables for these nuts could be read, so none is applied here.

Rows that look out of line but are printed so (checked, not typing errors):
R15-05K4-FSCDIN (ds 13.9 for a 15 mm size; Cdyn 12,600 N, near R20-05K4's 13,400 N);
R63-10T6-FSIDIN (ds 63.1 above its 63 mm size; Cdyn 61,920 N below R50-10K6's
74,500 N; 61,920 N is 6,314 kgf x 9.80665 to 10 N, which looks like an exact kgf
conversion, not kgf x 10); R50-40K3-FSCDIN (ds 50.0 and dk 45.0 where R50-10K6 and R50-20K5 have
48.0/47.9 and 42.9). R50-40K3, R40-10K4, R40-20K3 and R40-40K2 have the same ratings
in HIWIN GmbH's earlier HIWIN Compact catalogue, sec. 2.1 (same repository,
``www.hiwin.de.md``).
"""

import pytest

from app.catalog import Catalog

#: Table 4.4: article -> (ds, P, L, dk [mm], Cdyn, C0 [N], max. axial play [mm]).
TABLE_4_4 = {
    "R12-05K4-FSCDIN": (11.7, 5, 33, 9.9, 5500, 12000, 0.02),
    "R12-10K3-FSCDIN": (11.8, 10, 43, 9.6, 5100, 10100, 0.02),
    "R15-05K4-FSCDIN": (13.9, 5, 38, 11.8, 12600, 21000, 0.04),
    "R16-05T3-FSIDIN": (15.5, 5, 40, 12.9, 6500, 11700, 0.04),
    "R16-10K3-FSCDIN": (14.7, 10, 45, 12.5, 9100, 19300, 0.04),
    "R16-16K3-FSCDIN": (15.0, 16, 61, 13.0, 7900, 17000, 0.04),
    "R16-20K2-FSCDIN": (14.0, 20, 56, 11.8, 5200, 10400, 0.04),
    "R20-05K4-FSCDIN": (19.6, 5, 40, 16.9, 13400, 32740, 0.04),
    "R20-10K3-FSCDIN": (19.3, 10, 48, 16.6, 10000, 23500, 0.04),
    "R20-20K2-FSCDIN": (19.7, 20, 57, 17.1, 6800, 15300, 0.04),
    "R25-05K4-FSCDIN": (24.9, 5, 43, 22.3, 14900, 41500, 0.04),
    "R25-10K4-FSCDIN": (24.5, 10, 61, 21.8, 16100, 44900, 0.04),
    "R25-25K2-FSCDIN": (24.7, 25, 70, 22.1, 7400, 19100, 0.04),
    "R32-05K6-FSCDIN": (31.7, 5, 48, 29.1, 23900, 81900, 0.04),
    "R32-10K5-FSCDIN": (31.8, 10, 77, 28.6, 31500, 80100, 0.04),
    "R32-20K3-FSCDIN": (31.8, 20, 88, 28.6, 17000, 48500, 0.04),
    "R32-32K2-FSCDIN": (31.9, 32, 88, 28.7, 11600, 31800, 0.04),
    "R40-05K6-FSCDIN": (39.4, 5, 50, 36.8, 25900, 100600, 0.04),
    "R40-10K4-FSCDIN": (37.8, 10, 70, 32.8, 45000, 123000, 0.04),
    "R40-20K3-FSCDIN": (37.8, 20, 88, 32.8, 34850, 90000, 0.07),
    "R40-40K2-FSCDIN": (37.9, 40, 102, 32.9, 23000, 58400, 0.07),
    "R50-05K6-FSCDIN": (49.4, 5, 50, 46.8, 28300, 127200, 0.07),
    "R50-10K6-FSCDIN": (48.0, 10, 90, 42.9, 74500, 250000, 0.07),
    "R50-20K5-FSCDIN": (47.9, 20, 132, 42.9, 67200, 217500, 0.07),
    "R50-40K3-FSCDIN": (50.0, 40, 149, 45.0, 39000, 123000, 0.07),
    "R63-10T6-FSIDIN": (63.1, 10, 120, 58.0, 61920, 214090, 0.07),
}
#: Table 4.5, the same columns.
TABLE_4_5 = {
    "R08-02.5T2-RSIT": (7.7, 2.5, 27.5, 6.1, 1300, 1750, 0.04),
    "R10-02.5T2-RSIT": (9.9, 2.5, 25.0, 8.1, 1780, 2630, 0.04),
    "R10-04T2-RSIT": (9.9, 4.0, 32.0, 7.7, 1980, 2820, 0.04),
    "R12-04B1-RSIT": (12.0, 4.0, 34.0, 9.5, 3000, 5700, 0.04),
}
#: Table 6.4: article -> (ds, P, ball diameter, L, dk [mm], Cdyn, C0 [N]). Some articles
#: are printed with two or three ball diameters (R25-20K3, R32-10K5, R50-20K4,
#: R63-20K5); the catalog carries the line given here.
TABLE_6_4 = {
    "R14-10K3-FSC": (14, 10, 3.175, 46, 10.72, 9200, 17900),
    "R15-10K3-FSC": (15, 10, 3.175, 44, 12.32, 9600, 19300),
    "R15-20K2-FSC": (15, 20, 3.175, 50, 12.32, 6300, 12560),
    "R16-16K2-FSC": (16, 16, 3.175, 47, 13.12, 6800, 13850),
    "R20-05K4-FSC": (20, 5, 3.175, 40, 17.32, 14900, 36400),
    "R20-10K3-FSC": (20, 10, 3.175, 47, 17.32, 11300, 26600),
    "R20-20K2-FSC": (20, 20, 3.175, 57, 17.32, 7600, 17300),
    "R25-05K4-FSC": (25, 5, 3.175, 43, 22.32, 16500, 46120),
    "R25-10K3-FSC": (25, 10, 3.175, 50, 22.32, 12600, 33700),
    "R25-20K3-FSC": (25, 20, 3.175, 80, 22.32, 12600, 34360),
    "R25-25K2-FSC": (25, 25, 3.175, 69, 22.32, 8400, 21700),
    "R32-05K4-FSC": (32, 5, 3.175, 38, 29.32, 18400, 59600),
    "R32-10K5-FSC": (32, 10, 3.969, 73, 28.74, 30800, 94500),
    "R32-20K3-FSC": (32, 20, 3.969, 87, 28.74, 19000, 54300),
    "R32-32K2-FSC": (32, 32, 3.969, 87, 28.74, 12800, 35300),
    "R32-40K2-FSC": (32, 40, 3.969, 94, 28.74, 12400, 34400),
    "R38-10K4-FSC": (38, 10, 6.35, 70, 32.91, 50500, 137900),
    "R38-20K4-FSC": (38, 20, 6.35, 108, 32.91, 49900, 136600),
    "R40-05K5-FSC": (40, 5, 3.175, 45, 37.32, 24700, 94900),
    "R40-10K5-FSC": (40, 10, 6.35, 83, 34.91, 63400, 184000),
    "R40-20K4-FSC": (40, 20, 6.35, 110, 34.91, 51300, 144400),
    "R40-40K2-FSC": (40, 40, 6.35, 101, 34.91, 26600, 69400),
    "R50-05K5-FSC": (50, 5, 3.175, 45, 47.32, 27000, 119400),
    "R50-10K5-FSC": (50, 10, 6.35, 80, 44.91, 70500, 233000),
    "R50-20K4-FSC": (50, 20, 6.35, 106, 44.91, 57200, 183400),
    "R63-10K5-FSC": (63, 10, 6.35, 84, 57.91, 77200, 291900),
    "R63-20K5-FSC": (63, 20, 6.35, 132, 57.91, 78500, 300200),
}
FAMILY_TABLE = {
    "HIWIN-ROLLED": ("Table 4.4", TABLE_4_4),
    "HIWIN-ROLLED-RSIT": ("Table 4.5", TABLE_4_5),
    "HIWIN-GROUND": ("Table 6.4", TABLE_6_4),
}


def _nuts(catalog: Catalog, family: str) -> dict:
    return {s.id: s for s in catalog.screws if s.family_id == family}


@pytest.mark.parametrize("family", sorted(FAMILY_TABLE))
def test_each_nut_is_its_line_of_the_makers_table(catalog: Catalog, family: str) -> None:
    """Every row of the family is a line of its table, every column as printed, and the
    family carries every line transcribed here (a row added or dropped needs its line)."""
    table_name, table = FAMILY_TABLE[family]
    nuts = _nuts(catalog, family)
    assert set(nuts) == set(table)
    for nut, line in table.items():
        s = nuts[nut]
        if family == "HIWIN-GROUND":
            ds, lead, ball, length, dk, cdyn, c0 = line
            assert s.ball_diameter_m == pytest.approx(ball / 1e3), nut
            assert s.backlash_max_m == 0.0, nut
        else:
            ds, lead, length, dk, cdyn, c0, play = line
            assert s.ball_diameter_m is None, nut
            assert s.backlash_max_m == pytest.approx(play / 1e3), nut
        assert s.outer_diameter_m == pytest.approx(ds / 1e3), nut
        assert s.lead_m == pytest.approx(lead / 1e3), nut
        assert s.nut_length_m == pytest.approx(length / 1e3), nut
        assert s.root_diameter_m == pytest.approx(dk / 1e3), nut
        assert (s.dynamic_load_n, s.static_load_n) == (cdyn, c0), nut
        assert s.pitch_circle_diameter_m == pytest.approx(int(nut[1:3]) / 1e3), nut
        for name in ("dynamic_load", "static_load", "outer_diameter", "root_diameter"):
            source = s.provenance[name].source
            assert s.provenance[name].kind == "vendor"
            assert table_name in source and "BS-08-2-EN-1704-K" in source, (nut, name)


def test_no_rating_is_above_the_makers_printed_newtons(catalog: Catalog) -> None:
    """The property the selector relies on: Cdyn and C0 at most HIWIN's printed N."""
    for family, (_, table) in FAMILY_TABLE.items():
        for nut, s in _nuts(catalog, family).items():
            cdyn, c0 = table[nut][-2:] if family == "HIWIN-GROUND" else table[nut][4:6]
            assert s.dynamic_load_n <= cdyn and s.static_load_n <= c0, nut
