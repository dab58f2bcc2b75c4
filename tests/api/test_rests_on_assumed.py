"""A pass says what it rests on where it is read: a limit worked from an assumed catalog
value is as uncertain as that value, and the verdict names it."""

from fastapi.testclient import TestClient

from tests.api.calls import evaluate


def test_a_pass_governed_by_the_seeds_design_load_rests_on_an_assumption(
    client: TestClient,
) -> None:
    """The seed's nuts print no design load: the catalog works it from an assumed 3 MPa
    contact pressure (catalog/README.md rule 4). A robust pass it governs (50 N at 2 mm/s
    on a greased VHD8000 nut, 8 %) hinges on no range, so only the rests-on sentence says so."""
    c = evaluate(
        client, "VHD8000-L2.5", load_n=50, speed_mm_s=2, length_mm=200, lubrication="greased"
    )
    assert c["passed"] and c["robust"] and c["governing_check"] == "design_load"
    assert c["provenance"]["design_load"]["kind"] == "assumed"
    assert c["governing_limit_provenance"] == "assumed"
    assert "Rests on assumed design load." in c["verdict"]["text"]


def test_an_unchecked_wear_life_in_the_watch_list_says_its_wear_rate_is_assumed(
    client: TestClient,
) -> None:
    """With a duty but no required life, the watch list gives the life at the duty. A
    PTFE nut's life is its wear at an assumed wear rate over an assumed 2 d nut: the
    years say so where they are read; a ball nut's L10 life (the maker's ratings) does
    not. The values behind the life and the accuracy the candidate shows are in its
    provenance though no check reads them (no required life, no tolerance given)."""
    duty = {"length_mm": 300, "stroke_mm": 100, "cycles_per_day": 1000}
    c = evaluate(client, "Tr8x1.5-304-ptfe", load_n=50, speed_mm_s=5, **duty)
    assert c["passed"] and c["life"]["model"] == "wear"
    assert c["provenance"]["wear_rate"]["kind"] == "assumed"
    assert c["provenance"]["backlash"]["kind"] == "assumed"
    text = c["verdict"]["text"]
    assert "at this duty (from assumed specific wear rate, nut length), not checked" in text
    ball = evaluate(client, "R16-10K3-FSCDIN", load_n=500, speed_mm_s=100, **duty)
    assert "at this duty, not checked (no required life given)" in ball["verdict"]["text"]
