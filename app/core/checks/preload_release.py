"""Ball screw: an anti-backlash (preloaded) nut keeps no play only while the thrust stays
below its preload's release force."""

import numpy as np

from app.core.checks.base import (
    MARGIN_NOTE,
    Application,
    Array,
    CandidateTable,
    Check,
    Mapping,
    Measure,
    Quantities,
    Reach,
    ScrewSpec,
    load_input,
    most,
)
from app.core.formulas import ballscrew
from app.core.phrase import Amount, Phrase


class PreloadRelease(Check):
    name = "preload_release"
    why_none = (
        "the peak thrust releases every preloaded ball nut's preload: a larger nut (its "
        "preload a share of its rating), a double nut with a heavier preload, or a "
        "leadscrew's anti-backlash nut"
    )
    label = "Preload held (no play)"
    description = (
        "Where the axis must have no backlash, a preloaded ball nut's peak thrust against "
        "the force that releases its preload, 2^(3/2) F_pr: beyond it the unloaded side of "
        "the nut goes slack and the nut has play. Applies to preloaded ball nuts."
    )
    quantity = "force"
    formula = "F = F_peak; F_lim = 2 ** 1.5 * F_pr"
    source = (
        "HIWIN BS-08-2-EN-1704-K, sec. 3.7.2 F 3.7 (the preload counts below "
        "F_lim = 2^(3/2) F_pr); Steinmeyer: at 2.83 times the preload the tensioning nut "
        "is released completely"
    )
    sources = ("preload",)
    capacity_sources = ("preload",)

    def applies(self, app: Application) -> bool:
        return app.require_anti_backlash

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(t.ball & t.anti_backlash, q.axis.peak_force_n, _release(t))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {"F_peak": q.axis.peak_force_n, "F_pr": np.nan_to_num(t.preload_n)}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "below" if passed else "at or above"
        return Phrase(
            "Peak thrust {f} " + verb + " the force that releases the nut's preload "
            "F_lim = 2^(3/2) x {fpr} = {flim}"
            + ("." if passed else ": the nut's unloaded side goes slack, and it has play."),
            {
                "f": Amount(r.axis.peak_force_n, "force"),
                "fpr": Amount(s.preload_n or 0.0, "force"),
                "flim": Amount(_release_of(s), "force"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "Reduce the peak thrust to at most {cap}, or choose a larger nut (its preload a "
            "share of its rating) or a double nut with a heavier preload." + MARGIN_NOTE,
            {"cap": most(_release_of(s), "force")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return load_input(app, _release_of(s))


def _release(t: CandidateTable) -> Array:
    """Each nut's preload release force [N] (0 without a preload: play at any thrust)."""
    release: Array = ballscrew.preload_release_force(np.nan_to_num(t.preload_n))
    return release


def _release_of(s: ScrewSpec) -> float:
    """``_release`` of one screw [N]."""
    return float(ballscrew.preload_release_force(s.preload_n or 0.0))
