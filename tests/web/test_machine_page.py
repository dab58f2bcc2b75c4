"""The machine page: stacked axes sized together from their selector links."""

import re
from urllib.parse import urlencode

from fastapi.testclient import TestClient

from app.web.machine import link_query
from tests import machine_axes

#: the axes' selector links, the first a whole link and the second its query alone
Z = "/?" + machine_axes.page_query(machine_axes.Z)
X = machine_axes.page_query(machine_axes.X)
AXES = {"name1": "Z", "link1": Z, "frame1": "0.3", "motor1": "0.4", "name2": "X", "link2": X}


def rows(html: str) -> list[list[str]]:
    """The machine table's rows as cell texts."""
    body = html.split('<table class="machine">')[1].split("</table>")[0].split("<tbody>")[1]
    return [
        [re.sub(r"\s+", " ", re.sub("<[^>]+>", " ", cell)).strip() for cell in cells]
        for cells in (
            re.findall(r"<t[hd][^>]*>(.*?)</t[hd]>", row, re.S) for row in body.split("<tr")[1:]
        )
    ]


def test_the_page_sizes_each_axis_with_the_axes_above(client: TestClient) -> None:
    page = client.get("/machine?" + urlencode(AXES))
    assert page.status_code == 200
    z, x = rows(page.text)
    body = {
        "axes": [
            {"name": "Z", "inputs": machine_axes.Z, "frame_kg": 0.3, "motor_kg": 0.4},
            {"name": "X", "inputs": machine_axes.X},
        ]
    }
    api = client.post("/api/v1/machine", json=body).json()["axes"]
    assert f"{api[1]['carried_kg']:.4g}" == x[3] and f"{api[1]['sized_mass_kg']:.4g}" == x[4]
    assert api[0]["chosen"]["id"] in z[1] and "governs" in page.text


def test_choosing_another_screw_above_changes_the_axis_below(client: TestClient) -> None:
    first = client.get("/machine?" + urlencode(AXES)).text
    options = re.findall(r'<option value="([^"]+)"', first.split('id="choice1"')[1])
    other = options[-1]
    second = client.get("/machine?" + urlencode({**AXES, "choice1": other})).text
    assert f'<option value="{other}" selected>' in second
    assert rows(first)[1][3] != rows(second)[1][3]  # what X carries from Z


def test_the_machine_link_keeps_the_choices(client: TestClient) -> None:
    page = client.get("/machine?" + urlencode(AXES)).text
    link = re.search(r'class="share-link" href="([^"]+)"', page)
    assert link is not None
    again = client.get(link.group(1).replace("&amp;", "&"))
    assert again.status_code == 200 and rows(again.text) == rows(page)
    assert "choice1=" in link.group(1) and "choice2=" in link.group(1)


def test_a_bad_axis_is_said_at_its_field(client: TestClient) -> None:
    bad = client.get("/machine?" + urlencode({**AXES, "link2": X.replace("speed=100", "speed=-1")}))
    assert bad.status_code == 422 and 'id="e-link2"' in bad.text and "speed" in bad.text
    odd = client.get("/machine?" + urlencode({**AXES, "frame1": "heavy"}))
    assert odd.status_code == 422 and 'id="e-frame1"' in odd.text
    gone = client.get("/machine?" + urlencode({**AXES, "choice1": "Tr99x1-gold"}))
    assert gone.status_code == 422 and 'id="e-choice1"' in gone.text
    assert client.get("/machine").status_code == 200


def test_a_link_is_read_whole_or_as_its_query() -> None:
    assert link_query("https://example.org/?load=1&speed=2") == {"load": "1", "speed": "2"}
    assert link_query(" load=1 ") == {"load": "1"}


def test_an_axis_without_a_move_or_duty_is_sized_with_its_figures_marked_not_worked_out(
    client: TestClient,
) -> None:
    """A selector link with the axis alone (no stroke, acceleration or duty): the compact
    answer leaves out its RMS torque, life and cycle work, and the page shows "–" for
    them (it answered 500: the template formatted the absent RMS torque)."""
    plain = {"name1": "Z", "link1": "/?load=10&speed=10&length=300"}
    page = client.get("/machine?" + urlencode(plain))
    assert page.status_code == 200
    (z,) = rows(page.text)
    api = client.post(
        "/api/v1/machine",
        json={
            "axes": [{"name": "Z", "inputs": {"load_n": 10, "speed_mm_s": 10, "length_mm": 300}}]
        },
    ).json()["axes"][0]
    assert "rms_nm" not in api["chosen"]["torque"] and "years" not in api["chosen"].get("life", {})
    assert z[8] == f"{api['chosen']['torque']['peak_motor_nm']:.4g}"
    assert z[9:12] == ["–", "–", "–"]


def test_a_parameter_the_machine_page_does_not_read_is_named(client: TestClient) -> None:
    page = client.get("/machine?" + urlencode({**AXES, "frame_mass1": "3"}))
    assert page.status_code == 422
    assert "Unknown parameter &#39;frame_mass1&#39;: it is not read." in page.text
    assert '<table class="machine">' not in page.text


def test_an_axis_below_one_with_no_screw_says_its_mass_leaves_that_screw_out(
    client: TestClient,
) -> None:
    """Z with nothing passing (3,000 N at 500 mm/s on a 3 m B-series screw): X is sized
    with Z's moving mass, frame and motor, and says that Z's screw is not in it."""
    z = "/?load=3000&speed=500&length=3000&family=B"
    page = client.get("/machine?" + urlencode({**AXES, "link1": z}))
    assert page.status_code == 200
    _, x = rows(page.text)
    assert x[3].endswith("without the screw of Z (none passes there)")
    assert "Sized without the screw of Z, whose mass is not known" in x[-1]
    impossible = {"load_n": 3000, "speed_mm_s": 500, "length_mm": 3000}
    body = {
        "axes": [
            {"name": "Z", "inputs": {**impossible, "family": "B"}},
            {"name": "X", "inputs": machine_axes.X},
        ]
    }
    api = client.post("/api/v1/machine", json=body).json()["axes"]
    assert api[0]["chosen"] is None and [a["uncounted"] for a in api] == [[], ["Z"]]


def test_two_axes_of_one_name_are_said_on_the_form(client: TestClient) -> None:
    """The machine names its governing axis by its name: two axes called Z are refused
    with the form's error, not sized (nor a server error)."""
    page = client.get("/machine?" + urlencode({**AXES, "name2": "Z"}))
    assert page.status_code == 422
    assert 'id="e-form"' in page.text and "each axis needs a name of its own" in page.text
    nan = client.get("/machine?" + urlencode({**AXES, "frame1": "nan"}))
    assert nan.status_code == 422 and 'id="e-frame1"' in nan.text


def test_a_vertical_axis_below_says_it_carries_the_load_standing_on_it(
    client: TestClient,
) -> None:
    """Z (vertical, 100 N acting as a weight) on a vertical lift: the lift's row says Z's
    load stands in its load, and gives the 0.1 N of Z's m a it leaves out."""
    z = "/?" + machine_axes.page_query({**machine_axes.Z, "load_n": 100})
    own = {k: v for k, v in machine_axes.Z.items() if k != "lead_mm"}
    lift = machine_axes.page_query({**own, "moving_mass_kg": 0.2})
    page = client.get(
        "/machine?" + urlencode({"name1": "Z", "link1": z, "name2": "L", "link2": lift})
    )
    assert page.status_code == 200
    text = re.sub(r"\s+", " ", re.sub("<[^>]+>", " ", page.text))
    assert "Z above is vertical as this axis: its standing load, 100 N down, is in this" in text
    assert "up to 0.1 N beyond its weight and that load to this nut" in text


def test_an_axis_linked_with_bare_moves_is_sized(client: TestClient) -> None:
    """The selector's share link of a two-move cycle with its mass and load left to the
    axis (empty cells): the page sized it (it answered 500)."""
    link = "/?load=0&speed=30&length=400&moves=200:30:1000:::::;-200:30:1000:::::"
    page = client.get("/machine?" + urlencode({"name1": "X", "link1": link}))
    assert page.status_code == 200
    assert len(rows(page.text)) == 1
