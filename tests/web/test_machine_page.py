"""The machine page: stacked axes sized together from their selector links."""

import re
from urllib.parse import urlencode

from fastapi.testclient import TestClient

from app.web.machine import link_query

Z = (
    "/?load=0&moving_mass_kg=0.5&speed=10&length=250&accel=200&orientation=vertical"
    "&stroke=200&lead=8&motor=17hs19-2004s1&brake_torque=0.1"
)
X = "load=0&moving_mass_kg=0.8&speed=100&length=400&accel=1000&stroke=300&motor=17hs19-2004s1"
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
    z_in = {
        "load_n": 0,
        "moving_mass_kg": 0.5,
        "speed_mm_s": 10,
        "length_mm": 250,
        "accel_mm_s2": 200,
        "orientation": "vertical",
        "stroke_mm": 200,
        "lead_mm": 8,
        "motor": "17hs19-2004s1",
        "brake_torque_nm": 0.1,
    }
    x_in = {
        "load_n": 0,
        "moving_mass_kg": 0.8,
        "speed_mm_s": 100,
        "length_mm": 400,
        "accel_mm_s2": 1000,
        "stroke_mm": 300,
        "motor": "17hs19-2004s1",
    }
    body = {
        "axes": [
            {"name": "Z", "inputs": z_in, "frame_kg": 0.3, "motor_kg": 0.4},
            {"name": "X", "inputs": x_in},
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
