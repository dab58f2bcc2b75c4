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

