"""The output table's rows of the verdict: each check's utilization, the governing
check and the fix."""

from app.contract.reported.row import Reported

ROWS: tuple[Reported, ...] = (
    Reported(
        "utilization",
        help="Each check's demand over its capacity; above 1 fails.",
        unit="demand/capacity",
        csv=True,
    ),
    Reported(
        "verdict.utilization",
        "Governing utilization",
        "The governing check's demand over its capacity.",
        better="lower",
        cell="percent",
        compare=True,
    ),
    Reported(
        "governing_check",
        "Governing",
        "The check closest to its limit for this screw; “robust”: it passes at both ends "
        "of each assumed value's range; “limit assumed”: that limit rests on an assumed "
        "value (the catalog's or a library motor's).",
        cell="governing",
        column=True,
        ranks=("margin",),
        csv=True,
        type=str,
    ),
    Reported("verdict.governs_label", csv=True, type=str),
    Reported("fix", csv=True, type=str),
)
