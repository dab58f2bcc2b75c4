"""A nut rated lubricated (a bronze nut) that the axis runs dry is worked at its friction
run dry; a nut rated dry (a polymer nut) that the axis greases or oils holds at its
friction eased by the lubricant.

A bronze nut's catalog friction is an oiled nut's (steel on bronze with machine oil,
Shigley Table 8-5); run dry it rubs harder, and the catalog gives that friction beside it
(``ScrewSpec.dry_friction_dynamic``, ``dry_friction_static``, with their range and
provenance). Its wear rate is a lubricated nut's too, and none is given run dry: run dry,
its wear is not rated (a dry steel-on-copper-alloy contact wears orders of magnitude
faster: Archard's unlubricated coefficients), so a life required of it is not met.

A polymer nut's catalog friction is a dry nut's: oiled or greased, it is credited more PV
because the lubricant lowers its friction (``pv_derating.LUBRICATION_FACTORS``), and it
holds a load at rest at its static friction lowered as much (``eased_hold``).

``as_run`` is the one place that decides which friction a candidate runs at (run dry it
starts at the dry static friction but holds at no more than the oiled one, as the nut may
be oiled later): the screening reads its table through it, so the torque, efficiency,
heat, root stress, holding, the motor, the charts and the robustness all follow, and a
candidate's screw as shown (``screw_as_run``) carries the values it runs at and their
provenance.
"""

from dataclasses import replace

import numpy as np

from app.core.axis_free import friction_columns
from app.core.formulas import geometry, pv_derating
from app.core.model import Application, Provenance, ScrewSpec, at_values
from app.core.table import Array, CandidateTable, Mask, column

#: The ScrewSpec fields a nut run dry takes its friction from, by the field they replace.
DRY = {"friction_dynamic": "dry_friction_dynamic", "friction_static": "dry_friction_static"}


def runs_dry(app: Application, table: CandidateTable) -> Mask:
    """The rows ``app`` runs at their friction run dry: a nut rated lubricated that the
    axis runs dry (``Application.lubrication_counted``: dry, or greased or oiled in a
    vacuum, where oil and grease evaporate), given a friction run dry."""
    if app.lubrication_counted != "dry":
        return np.zeros(len(table), dtype=bool)
    given = ~np.isnan(table.dry_friction_dynamic) & ~np.isnan(table.dry_friction_static)
    return table.lubricated_rating & given


def lubricant_eases(app: Application, table: CandidateTable) -> Mask:
    """The rows whose holding friction the axis's lubricant lowers: a sliding nut rated
    dry (not ``lubricated_rating``) that the axis greases or oils (vacuum or not: what
    oil or grease is there lowers the friction while it lasts)."""
    if not app.lubricated:
        return np.zeros(len(table), dtype=bool)
    return ~table.lubricated_rating & ~table.ball


def eased_hold(app: Application, friction_static: Array) -> Array:
    """The static friction a nut rated dry holds at when ``app`` greases or oils it: its
    own over the lubrication's PV factor (``pv_derating.LUBRICATION_FACTORS``: the PV a
    lubricant adds is the friction heat it takes away, so the friction falls as much)."""
    factor = pv_derating.LUBRICATION_FACTORS[app.lubrication][0]
    eased: Array = friction_static / factor
    return eased


def as_run(app: Application, table: CandidateTable) -> CandidateTable:
    """``table`` with each row's friction as ``app`` runs its nut (``runs_dry``): the
    friction run dry, or the catalog's, the holding friction eased by a lubricant on a
    nut rated dry (``lubricant_eases``), and every column that follows from friction
    formed again for the rows that change (``axis_free.friction_columns``); the table
    itself when none does. A robustness variant's row keeps its end: one at an end of
    the dry friction's range runs at that end."""
    dry, eased = runs_dry(app, table), lubricant_eases(app, table)
    rows = ((dry != table.runs_dry) | (eased != table.lubricant_eased)).nonzero()[0]
    if not rows.size:
        return table
    screws = [table.screws[i] for i in rows.tolist()]
    to_dry = dry[rows]
    oiled_s = column([s.friction_static for s in screws])
    mu_s = np.where(to_dry, table.dry_friction_static[rows], oiled_s)
    mu_d = np.where(
        to_dry, table.dry_friction_dynamic[rows], column([s.friction_dynamic for s in screws])
    )
    d_p = table.pitch_diameter_m[rows]
    # tan of the lead angle as the table's build takes it (not tan(arctan(...)))
    tan_l = geometry.tan_lead_angle(table.lead_m[rows], d_p)
    # run dry it starts at the dry static friction, but holds at no more than the oiled
    hold = np.minimum(mu_s, oiled_s)
    hold = np.where(eased[rows], eased_hold(app, hold), hold)
    formed = friction_columns(
        tan_l, table.cos_half_angle[rows], d_p, mu_s, mu_d, table.ball[rows], hold
    )
    # a nut rated lubricated has no wear rate run dry: its rate is a lubricated nut's
    rated = column([s.wear_rate_m2_n for s in screws])
    formed["wear_rate_m2_n"] = np.where(to_dry, np.nan, rated)
    changed = {}
    for name, values in formed.items():
        changed[name] = getattr(table, name).copy()
        changed[name][rows] = values
    return replace(table, runs_dry=dry, lubricant_eased=eased, **changed)


def run_dry(screw: ScrewSpec) -> ScrewSpec:
    """``screw`` at its friction run dry, with that friction's provenance."""
    provenance = dict(screw.provenance)
    changes = {}
    for name, dry in DRY.items():
        changes[name] = getattr(screw, dry)
        if dry in provenance:
            provenance[name] = provenance[dry]
    return at_values(screw, changes | {"provenance": provenance})


def screw_as_run(table: CandidateTable, k: int) -> ScrewSpec:
    """The screw of row ``k`` as ``table`` runs it: at its friction run dry where the row
    is, at its holding friction eased by the lubricant where the row is (``as_run``),
    which its values' provenance then names."""
    screw = table.screws[k]
    if table.runs_dry[k]:
        return run_dry(screw)
    if table.lubricant_eased[k]:
        return _eased(screw, float(table.friction_static[k]))
    return screw


def _eased(screw: ScrewSpec, hold: float) -> ScrewSpec:
    """``screw`` holding at the static friction ``hold``, eased by the axis's lubricant
    (``eased_hold``), an assumed value worked from its dry one."""
    dry = screw.provenance.get("friction_static")
    given = f"{dry.kind}: {dry.source}" if dry is not None else "the catalog's"
    source = (
        f"its static friction rated dry, {screw.friction_static:g} ({given}), lowered by its "
        f"lubricant to {hold:.3g} by the factor the lubricant raises its PV by (the "
        "friction heat the lubricant takes away)"
    )
    provenance = {**screw.provenance, "friction_static": Provenance("assumed", source)}
    return at_values(screw, {"friction_static": hold, "provenance": provenance})
