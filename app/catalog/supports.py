"""The support-unit library (``supports.toml`` in any catalog directory): fixed-side
support units, the screw's thrust bearing, each with its maker's axial load ratings and
their provenance, validated with the catalog and held on the ``Catalog``.

A library unit becomes the application's thrust bearing at the edge (``with_support``,
called by ``app.contract.inputs``): its dynamic and static axial ratings, unless the user
gives those ratings directly.
"""

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from app.catalog.entry import Entry
from app.catalog.errors import CatalogError
from app.catalog.files import library_entries, merge_libraries
from app.catalog.models import Sourced
from app.core.model import Application

#: The library's file name; family loading skips it in every catalog directory.
SUPPORT_FILE = "supports.toml"
SCHEMA = 1
#: The ratings of a unit [N].
RATINGS = ("dynamic_axial_n", "static_axial_n")


class UnknownSupport(ValueError):
    """A support unit id the loaded library does not hold: a 422 on its input."""

    #: the API input that names the unit
    field = "support_id"


@dataclass(frozen=True, slots=True)
class SupportUnit:
    """One library support unit: its name and its axial ratings in N with provenance
    (``dynamic_axial_n``: the basic dynamic load rating Ca; ``static_axial_n``: the
    static rating the thrust-bearing check divides by its safety factor)."""

    id: str
    name: str
    values: Mapping[str, Sourced]

    def value(self, name: str) -> float:
        number: float = self.values[name].value
        return number


def _support(file: str, unit_id: str, data: Any) -> SupportUnit:
    if not isinstance(data, dict):
        raise CatalogError(file, f"supports.{unit_id}", "-", "must be a table")
    entry = Entry(file, f"supports.{unit_id}", data)
    entry.check_known(frozenset(RATINGS) | {"name"})
    if not isinstance(data.get("name"), str) or not data["name"].strip():
        raise entry.fail("name", "missing or not text")
    values = {name: Sourced(entry.number(name), "N", entry.prov(name)) for name in RATINGS}
    return SupportUnit(unit_id, data["name"], values)


def load_supports(path: Path, digest: Any = None) -> dict[str, SupportUnit]:
    """Every support unit of one library file, validated (its bytes feed ``digest``)."""
    name, units = library_entries(path, digest, "supports", SCHEMA)
    return {uid: _support(name, uid, data) for uid, data in units.items()}


def load_support_library(directories: Iterable[Path], digest: Any = None) -> dict[str, SupportUnit]:
    """The support units of every directory's library file, ids unique across them."""
    return merge_libraries(directories, SUPPORT_FILE, lambda p: load_supports(p, digest), "support")


def unknown_support_message(value: str, supports: Mapping[str, SupportUnit]) -> str:
    return f"unknown support unit '{value[:100]}'; the library has {', '.join(supports)}"


def check_support(value: str | None, supports: Mapping[str, SupportUnit] | None) -> str | None:
    """A support unit id of the library (or none): the 422 names the ids on offer.
    Without a library to hand (``supports`` None) the id is checked where the catalog is."""
    if value is not None and supports is not None and value not in supports:
        raise ValueError(unknown_support_message(value, supports))
    return value


def with_support(app: Application, supports: Mapping[str, SupportUnit]) -> Application:
    """``app`` with its library support unit's axial ratings, keeping any rating the user
    gave (raise UnknownSupport for an id ``supports`` lacks)."""
    if app.support_unit is None:
        return app
    unit = supports.get(app.support_unit)
    if unit is None:
        raise UnknownSupport(unknown_support_message(app.support_unit, supports))
    dynamic, static = app.support_dynamic_n, app.support_static_n
    return replace(
        app,
        support_dynamic_n=dynamic if dynamic is not None else unit.value("dynamic_axial_n"),
        support_static_n=static if static is not None else unit.value("static_axial_n"),
    )
