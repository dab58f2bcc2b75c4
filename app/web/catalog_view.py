"""The catalog page's model: series grouped by family, each family with a compact table
comparing its sizes and, per series, every field with its provenance."""

from collections.abc import Iterable
from typing import Any

from app.catalog import Catalog
from app.contract.units import catalog_value
from app.report.present import series_dict

#: (catalog field, column heading) of a family's comparison table, in order.
KEY_FIELDS = (
    ("outer_diameter", "Outer diameter"),
    ("root_diameter", "Root diameter"),
    ("leads", "Leads"),
    ("design_load", "Design load"),
)
#: name ending of the fields that name a material ('screw_material'), shown in one column.
MATERIAL_SUFFIX = "_material"
#: field-name prefix whose suffixes name a series' nut variants ('friction_dynamic_tfe').
VARIANT_PREFIX = "friction_dynamic_"


def field_rows(series: dict[str, Any]) -> list[dict[str, str]]:
    """Every field of one series: name, display value and unit, provenance kind and source."""
    rows = []
    for name, field in series["fields"].items():
        text, unit = catalog_value(name, field["value"], field["unit"])
        rows.append({"name": name, "value": text, "unit": unit, **field["provenance"]})
    return rows


def variants(names: Iterable[str]) -> list[str]:
    """The nut variants of a series, from its variant-specific field names.

    >>> variants(["outer_diameter", "friction_dynamic_uncoated", "friction_dynamic_tfe"])
    ['uncoated', 'tfe']
    """
    return [n.removeprefix(VARIANT_PREFIX) for n in names if n.startswith(VARIANT_PREFIX)]


def key_cells(rows: list[dict[str, str]]) -> list[dict[str, str] | None]:
    """The comparison table's cells of one series, in KEY_FIELDS order; None where the
    series has no such field (no design load)."""
    by_name = {row["name"]: row for row in rows}
    return [by_name.get(name) for name, _ in KEY_FIELDS]


def material_cells(rows: list[dict[str, str]]) -> list[dict[str, str]]:
    """The series' material fields, each with its part ('nut') before its value.

    >>> material_cells([{"name": "screw_material", "value": "steel"}, {"name": "lead"}])
    [{'name': 'screw_material', 'value': 'steel', 'part': 'screw'}]
    """
    return [
        {**row, "part": row["name"].removesuffix(MATERIAL_SUFFIX).replace("_", " ")}
        for row in rows
        if row["name"].endswith(MATERIAL_SUFFIX)
    ]


def family_sections(catalog: Catalog) -> list[dict[str, Any]]:
    """One section per family in catalog order: its id and name, and its series, each
    with its fields, comparison cells and nut variants."""
    families: dict[str, dict[str, Any]] = {}
    for series in map(series_dict, catalog.series.values()):
        rows = field_rows(series)
        entry = {**series, "rows": rows, "cells": key_cells(rows)}
        entry["variants"] = variants(series["fields"])
        entry["materials"] = material_cells(rows)
        family = families.setdefault(
            series["family"],
            {"id": series["family"], "name": series["family_name"], "series": []},
        )
        family["series"].append(entry)
    return list(families.values())
