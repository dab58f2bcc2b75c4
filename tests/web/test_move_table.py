"""The selector's table of moves: rows added and removed by a plain GET, values in display
units that a share link carries exactly to the API, errors at their cells, and a long
cycle within the server's query limits.

HTML is read through CSS selectors (BeautifulSoup)."""

from urllib.parse import parse_qsl, urlencode, urlsplit

from bs4 import BeautifulSoup, Tag
from fastapi.testclient import TestClient

from app.contract.cycle import MAX_MOVES
from app.server.settings import Settings

AXIS = {"load": "10", "speed": "250", "length": "500"}
#: a pick-and-place cycle: out 300 mm with a part, back empty, each with a dwell
TEXT = "300:250:2500:2500:0.2:2.5:10:opposes;-300:250:2500:2500:0.2:0.5:10:opposes"
INCH = 25.4  # mm, exactly (NIST SP 811)


def page(client: TestClient, params: dict[str, str]) -> BeautifulSoup:
    response = client.get("/?" + urlencode(params))
    assert response.status_code == 200, response.text[:500]
    return BeautifulSoup(response.text, "html.parser")


def cells(html: BeautifulSoup) -> list[dict[str, str]]:
    """The table's rows: column key -> the cell's value (a select's chosen option)."""
    rows: list[dict[str, str]] = []
    for tr in html.select("#moves-table tbody tr"):
        row = {}
        for control in tr.select("input, select"):
            key = str(control["name"]).split("_", 1)[1]
            if control.name == "select":
                chosen = control.select_one("option[selected]") or control.select_one("option")
                assert isinstance(chosen, Tag)
                row[key] = str(chosen["value"])
            else:
                row[key] = str(control.get("value", ""))
        rows.append(row)
    return rows


def form_query(html: BeautifulSoup) -> list[tuple[str, str]]:
    """What a browser submits for the selector form as drawn (no button pressed)."""
    pairs = []
    form = html.select_one("#selector")
    assert form is not None
    for control in form.select("input[name], select[name], textarea[name]"):
        name = str(control["name"])
        if control.name == "select":
            chosen = control.select_one("option[selected]") or control.select_one("option")
            assert isinstance(chosen, Tag)
            pairs.append((name, str(chosen["value"])))
        elif control.get("type") == "checkbox":
            if control.has_attr("checked"):
                pairs.append((name, str(control["value"])))
        elif control.name == "textarea":
            pairs.append((name, control.text))
        else:
            pairs.append((name, str(control.get("value", ""))))
    return pairs


def share_moves(html: BeautifulSoup) -> str:
    link = html.select_one("a.share-link, #share-link, a[href^='/?']")
    assert link is not None
    return dict(parse_qsl(urlsplit(str(link["href"])).query))["moves"]


TYPED = {
    **AXIS,
    "m0_dist": "300",
    "m0_speed": "250",
    "m0_accel": "2500",
    "m0_mass": "2.5",
    "m0_dir": "opposes",
    "m1_dist": "-300",
    "m1_speed": "250",
    "m1_accel": "2500",
}


def test_a_move_is_added_by_a_plain_get(client: TestClient) -> None:
    html = page(client, {**TYPED, "add_move": "1"})
    rows = cells(html)
    assert len(rows) == 3
    assert rows[0]["dist"] == "300" and rows[1]["dist"] == "-300"
    assert rows[2] == {key: "" for key in rows[2]}  # its direction too: the axis's
    new = html.select_one("#f-m2_dist")
    assert new is not None and new.has_attr("autofocus")
    # the empty new row is no move: no error at it, and the result is the two moves'
    assert not any(span.text.strip() for span in html.select("#moves-table .error"))
    assert share_moves(html) == share_moves(page(client, TYPED))


def test_a_move_is_removed_by_a_plain_get(client: TestClient) -> None:
    three = {**TYPED, "m2_dist": "50", "m2_speed": "10", "m2_accel": "100"}
    html = page(client, {**three, "remove_move": "0"})
    assert [r["dist"] for r in cells(html)] == ["-300", "50"]
    # the focus stays in the table: on the row now in the removed one's place
    assert [str(e["id"]) for e in html.select("[autofocus]")] == ["f-m0_dist"]
    last = page(client, {**AXIS, "m0_dist": "1", "remove_move": "0"})
    assert not cells(last)
    assert [str(e["name"]) for e in last.select("[autofocus]")] == ["add_move"]


def test_a_link_fills_the_table_in_display_units(client: TestClient) -> None:
    rows = cells(page(client, {**AXIS, "moves": TEXT, "length_unit": "in"}))
    assert float(rows[0]["dist"]) * INCH == 300.0
    assert float(rows[1]["speed"]) * INCH == 250.0
    assert rows[0]["dwell"] == "0.2" and rows[1]["mass"] == "0.5"
    assert [r["dir"] for r in rows] == ["opposes", "opposes"]


def test_the_table_round_trips_through_its_link_to_the_api(client: TestClient) -> None:
    """Typed in inches, the link carries the moves in mm exactly: the link's page, its
    form submitted again, and the API given the link's moves all give the same answer."""
    typed = {
        **AXIS,
        "length_unit": "in",
        "m0_dist": "11.811",
        "m0_speed": "9.84",
        "m0_accel": "98.4",
        "m0_dwell": "0.2",
        "m0_mass": "2.5",
        "m1_dist": "-11.811",
        "m1_speed": "9.84",
        "m1_accel": "98.4",
        "m1_decel": "50",
    }
    first = page(client, {**typed, "length": "20", "speed": "10"})
    moves = share_moves(first)
    again = page(client, dict(form_query(page(client, dict(parse_qsl(urlsplit(
        str(first.select_one("a[href^='/?']")["href"])).query))))))  # fmt: skip
    assert share_moves(again) == moves
    link = dict(parse_qsl(urlsplit(str(first.select_one("a[href^='/?']")["href"])).query))
    exported = client.get("/export.json", params=link).json()
    axis = {"load_n": 10, "speed_mm_s": 254, "length_mm": 508}  # 10 in/s, 20 in
    api = client.get("/api/v1/select", params={**axis, "moves": moves, "detail": "full"}).json()
    assert exported["candidates"] and exported["candidates"] == api["candidates"]
    assert exported["inputs"]["moves"] == api["inputs"]["moves"]
    assert api["inputs"]["moves"][0]["distance_mm"] == 11.811 * INCH


def test_errors_are_said_at_their_cells(client: TestClient) -> None:
    bad = {**TYPED, "m1_speed": "fast", "m0_accel": "-5"}
    html = page(client, bad)
    assert html.select_one("#e-m1_speed").text == "Enter a number."
    assert html.select_one("#f-m1_speed")["aria-invalid"] == "true"
    refused = page(client, {**TYPED, "m0_accel": "-5"})
    assert refused.select_one("#e-m0_accel").text == "Must be at least 0 mm/s²."
    assert refused.select_one("#e-m0_dist").text == ""
    # the one whole-cycle fault, that it does not end where it starts, is said at the table
    open_cycle = page(client, {**TYPED, "m1_dist": "-200"})
    assert "start" in open_cycle.select_one("#e-moves").text
    assert not open_cycle.select(".results-table, #results table.candidates")


def test_an_htmx_edit_redraws_the_table_out_of_band(client: TestClient) -> None:
    response = client.get(
        "/?" + urlencode({**TYPED, "add_move": "1"}), headers={"HX-Request": "true"}
    )
    html = BeautifulSoup(response.text, "html.parser")
    table = html.select_one("#moves-table")
    assert table is not None and table["hx-swap-oob"] == "true"
    assert len(table.select("tbody tr")) == 3
    typing = client.get(
        "/?" + urlencode({**TYPED, "m1_speed": "x"}), headers={"HX-Request": "true"}
    )
    spans = BeautifulSoup(typing.text, "html.parser")
    assert spans.select_one("#moves-table") is None
    # a cell's error travels, as a field's does, in the one out-of-band list of errors
    listed = spans.select_one("#field-errors[hx-swap-oob] [data-error-for=m1_speed]")
    assert listed is not None and listed.text == "Enter a number."


def twenty_moves() -> str:
    return ";".join(
        f"{d}:250.5:2500.25:2400.75:0.25:2.5:12.5:opposes" for d in [312.5, -312.5] * 10
    )


def test_a_twenty_move_cycle_fits_the_servers_query_limits(client: TestClient) -> None:
    """Both the share link and the form a browser submits for 20 moves (8 cells a row);
    the form of the most moves a cycle may have stays within the parameter count."""
    limits = Settings()
    html = page(client, {**AXIS, "moves": twenty_moves()})
    assert len(cells(html)) == 20
    link = str(html.select_one("a[href^='/?']")["href"])
    assert len(urlsplit(link).query) < limits.max_query_chars / 2
    assert link.count("&") + 1 < 10
    form = form_query(html)
    assert len(urlencode(form)) < limits.max_query_chars
    assert len(form) + 1 < limits.max_query_params
    resubmitted = page(client, dict(form))
    assert share_moves(resubmitted) == share_moves(html)
    per_row = sum(1 for name, _ in form if name.startswith("m0_"))
    assert len(form) + (MAX_MOVES - 20) * per_row + 1 <= limits.max_query_params


def test_cells_and_buttons_are_known_parameters(client: TestClient) -> None:
    html = page(client, {**TYPED, "m0_colour": "red"})
    assert "m0_colour" in html.text
    assert "Unknown parameter 'm1_dist'" not in html.text


def test_the_custom_screws_page_reads_the_table_too(client: TestClient) -> None:
    screw = {"outer_diameter_mm": "10", "root_diameter_mm": "8", "lead_mm": "2",
             "friction_dynamic": "0.15", "friction_static": "0.2"}  # fmt: skip
    cells_only = {k: v for k, v in TYPED.items() if k.startswith("m")}
    params = {**screw, "load": "10", "speed": "250", "length": "500", **cells_only}
    html = BeautifulSoup(client.get("/custom?" + urlencode(params)).text, "html.parser")
    link = html.select_one("a.share-link")
    assert link is not None
    moves = dict(parse_qsl(urlsplit(str(link["href"])).query))["moves"]
    # an empty deceleration is the acceleration; an empty dwell and load the axis's
    assert moves.startswith("300:250:2500:::2.5::opposes;-300:")
    bad = {**params, "m1_accel": "-1"}
    refused = BeautifulSoup(client.get("/custom?" + urlencode(bad)).text, "html.parser")
    assert refused.select_one("#e-m1_accel").text == "Must be at least 0 mm/s²."


def test_a_change_of_units_converts_the_cells_exactly(client: TestClient) -> None:
    """Typed in mm and shown in inches: each cell the shortest text that reads back to the
    same value in mm, so switching back gives the typed numbers, and the link is unchanged."""
    typed = {**TYPED, "from_length_unit": "mm"}
    inches = page(client, {**typed, "length_unit": "in"})
    rows = cells(inches)
    assert float(rows[0]["dist"]) * INCH == 300.0 and float(rows[1]["speed"]) * INCH == 250.0
    assert rows[0]["mass"] == "2.5"  # a mass follows the force unit, N here
    back = page(client, {**{k: v for k, v in TYPED.items() if not k.startswith("m")},
                         **{f"m{i}_{k}": v for i, row in enumerate(rows) for k, v in row.items()},
                         "from_length_unit": "in", "length": str(500 / INCH)})  # fmt: skip
    assert [r["dist"] for r in cells(back)] == ["300", "-300"]
    assert cells(back)[0]["speed"] == "250"
    fragment = client.get(
        "/?" + urlencode({**typed, "length_unit": "in"}), headers={"HX-Request": "true"}
    )
    table = BeautifulSoup(fragment.text, "html.parser").select_one("#moves-table")
    assert table is not None and table["hx-swap-oob"] == "true"
