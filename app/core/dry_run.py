"""A nut rated lubricated (a bronze nut) that the axis runs dry is worked at its friction
run dry.

A bronze nut's catalog friction is an oiled nut's (steel on bronze with machine oil,
Shigley Table 8-5); run dry it rubs harder, and the catalog gives that friction beside it
(``ScrewSpec.dry_friction_dynamic``, ``dry_friction_static``, with their range and
provenance). ``as_run`` is the one place that decides which friction a candidate runs at
(it starts at the dry static friction but holds at no more than the oiled one, as the nut
may be oiled later):
the screening reads its table through it, so the torque, efficiency, heat, root stress,
holding, the motor, the charts and the robustness all follow, and a candidate's screw as
shown (``screw_as_run``) carries the dry values and their provenance.
"""

from dataclasses import replace

import numpy as np

from app.core.axis_free import friction_columns
from app.core.formulas import geometry
from app.core.model import Application, ScrewSpec, at_values
from app.core.table import CandidateTable, Mask, column

#: The ScrewSpec fields a nut run dry takes its friction from, by the field they replace.
DRY = {"friction_dynamic": "dry_friction_dynamic", "friction_static": "dry_friction_static"}


def runs_dry(app: Application, table: CandidateTable) -> Mask:
    """The rows ``app`` runs at their friction run dry: a nut rated lubricated that the
    axis runs dry (not ``Application.lubricated``), given a friction run dry."""
    if app.lubricated:
        return np.zeros(len(table), dtype=bool)
    given = ~np.isnan(table.dry_friction_dynamic) & ~np.isnan(table.dry_friction_static)
    return table.lubricated_rating & given


def as_run(app: Application, table: CandidateTable) -> CandidateTable:
    """``table`` with each row's friction as ``app`` runs its nut (``runs_dry``): the
    friction run dry, or the catalog's, and every column that follows from friction
    formed again for the rows that change (``axis_free.friction_columns``); the table
    itself when none does. A robustness variant's row keeps its end: one at an end of
    the dry friction's range runs at that end."""
    dry = runs_dry(app, table)
    rows = (dry != table.runs_dry).nonzero()[0]
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
    formed = friction_columns(
        tan_l, table.cos_half_angle[rows], d_p, mu_s, mu_d, table.ball[rows], hold
    )
    changed = {}
    for name, values in formed.items():
        changed[name] = getattr(table, name).copy()
        changed[name][rows] = values
    return replace(table, runs_dry=dry, **changed)


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
    is (``as_run``), which its values' provenance then names."""
    screw = table.screws[k]
    return run_dry(screw) if table.runs_dry[k] else screw
