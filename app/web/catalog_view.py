"""The catalog pages' model: series grouped by family, each family with a compact table
comparing its sizes (/catalog), and one series with every field and its provenance
(/catalog/{series_id})."""

from collections.abc import Callable, Iterable
from typing import Any
from urllib.parse import quote

from app.catalog import Catalog, Series
from app.contract.units import catalog_value
from app.report.present import series_dict

#: (catalog field, column heading) of a family's comparison table, in order.
KEY_FIELDS = (
    ("outer_diameter", "Outer diameter"),
    ("root_diameter", "Root diameter"),
    ("leads", "Leads"),
    ("design_load", "Design load"),
)
#: the comparison table's fields by name
KEY_NAMES = frozenset(name for name, _ in KEY_FIELDS)
#: name ending of the fields that name a material ('screw_material'), shown in one column.
MATERIAL_SUFFIX = "_material"
#: field-name prefix whose suffixes name a series' nut variants ('friction_dynamic_tfe').
VARIANT_PREFIX = "friction_dynamic_"


def field_rows(
    series: dict[str, Any], keep: Callable[[str], bool] = lambda name: True
) -> list[dict[str, str]]:
    """Every field of one series (or those whose name ``keep`` keeps): name, display value
    and unit, provenance kind and source."""
    rows = []
    for name, field in series["fields"].items():
        if not keep(name):
            continue
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


def in_summary(name: str) -> bool:
    """Whether field ``name`` shows in the family's comparison table (a key field or a
    material).

    >>> in_summary("leads"), in_summary("nut_material"), in_summary("friction_static")
    (True, True, False)
    """
    return name in KEY_NAMES or name.endswith(MATERIAL_SUFFIX)


def series_url(series_id: str) -> str:
    """The page of every value of series ``series_id`` (``series_page``).

    >>> series_url("HIWIN-GROUND R16")
    '/catalog/HIWIN-GROUND%20R16'
    """
    return "/catalog/" + quote(series_id, safe="")


def series_anchor(series_id: str) -> str:
    """The HTML id of series ``series_id``'s ``<details>`` on /catalog: the id with each run
    of whitespace as one "_" (an HTML id holds no whitespace).

    >>> series_anchor("HIWIN-GROUND R16")
    'HIWIN-GROUND_R16'
    """
    return "_".join(series_id.split())


def series_summary(series: Series) -> dict[str, Any]:
    """One series as its family's comparison table shows it: its data (``series_dict``),
    its cells, nut variants and materials (only these fields are converted for display:
    converting all of every series took most of the catalog page's rendering)."""
    data = series_dict(series)
    rows = field_rows(data, in_summary)
    return {
        **data,
        "cells": key_cells(rows),
        "variants": variants(data["fields"]),
        "materials": material_cells(rows),
        "url": series_url(series.id),
        "anchor": series_anchor(series.id),
    }


def series_view(series: Series) -> dict[str, Any]:
    """One series with every field as a row (its page, /catalog/{series_id})."""
    data = series_dict(series)
    return {**data, "rows": field_rows(data)}


def family_sections(catalog: Catalog) -> list[dict[str, Any]]:
    """One section per family in catalog order: its id and name, and its series, each
    with its comparison cells, nut variants and materials."""
    families: dict[str, dict[str, Any]] = {}
    for entry in map(series_summary, catalog.series.values()):
        family = families.setdefault(
            entry["family"],
            {"id": entry["family"], "name": entry["family_name"], "series": []},
        )
        family["series"].append(entry)
    return list(families.values())
