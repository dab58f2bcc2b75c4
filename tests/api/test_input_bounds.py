"""A bound an input is refused by is written so that the value it names is accepted: the
most cycles a day a cycle allows is rounded down. 300 mm out and back at 60 mm/s with
1000 mm/s² ramps: each move 300 / 60 + 60 / 1000 = 5.06 s, the cycle 10.12 s, at most
86400 / 10.12 = 8537.549... cycles a day; it was written 8537.55, which is refused."""

from fastapi.testclient import TestClient

AXIS = "/api/v1/select?load_n=60&speed_mm_s=60&length_mm=400&stroke_mm=300"


def test_the_most_cycles_a_day_is_written_down_and_accepted(client: TestClient) -> None:
    (detail,) = client.get(f"{AXIS}&cycles_per_day=9000").json()["detail"]
    assert detail["field"] == "cycles_per_day"
    assert detail["message"].startswith("must be at most 8537.54:")
    assert client.get(f"{AXIS}&cycles_per_day=8537.54").status_code == 200
    assert client.get(f"{AXIS}&cycles_per_day=8537.55").status_code == 422
