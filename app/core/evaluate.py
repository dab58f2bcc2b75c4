"""Evaluate one screw: every number, every check, every fix."""

import math

import numpy as np

from app.core.checks.base import Reach
from app.core.model import Application, AxisProvenance, ScrewSpec
from app.core.quantities import axial_load
from app.core.record import Candidate, records
from app.core.screening import screen_table
from app.core.table import CandidateTable

__all__ = ["axial_load", "evaluate"]


def evaluate(
    app: Application,
    screw: ScrewSpec | CandidateTable,
    reach: Reach | None = None,
    axis: AxisProvenance | None = None,
) -> Candidate:
    """Compute torque, speeds, loads, PV, life, accuracy and all checks for one screw, or
    for the one screw of a table (a catalog's row, ``CatalogIndex.row``); ``reach`` is
    what the catalog offers, for the fixes (unbounded by default); ``axis`` the
    provenance of the axis's values the checks' capacities are (typed in by default)."""
    table = screw if isinstance(screw, CandidateTable) else CandidateTable.build([screw])
    screw = table.screws[0]
    if min(table.efficiency[0], table.efficiency_static[0]) <= 0.0:
        raise ValueError(
            f"{screw.id}: lead angle {math.degrees(table.lead_angle_rad[0]):.1f} deg is too "
            f"steep to drive against friction {screw.friction_dynamic:g}"
        )
    return records(app, screen_table(app, table, np.arange(1), reach), [0], axis=axis)[0]
