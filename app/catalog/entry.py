"""Typed reading of one catalog entry: every value is a table with its provenance.

An ``Entry`` wraps the merged data of one entry (a series, a variant, a material, a
family declaration) and names the file, the entry and the field in every error, so a
user fixing a data file is told exactly where to look.
"""

import math
from collections.abc import Iterable, Mapping
from typing import Any, TypeGuard

from app.catalog.errors import CatalogError
from app.catalog.models import Sourced
from app.core.model import Provenance
from app.core.units import SI_UNITS, UNITS, to_si

#: Where a catalog value comes from, each kind in words: what the guide and the catalog
#: pages' legend say of it.
PROVENANCE_MEANINGS = {
    "seed": "Printed in the leadscrew maker's catalog the app's data started from.",
    "handbook": "From an engineering handbook or textbook, such as a material's modulus.",
    "standard": "From a published standard, such as a thread form's dimensions.",
    "vendor": "From another maker's catalog or data sheet.",
    "derived": "Computed from other catalog values by the rule its source states, as a "
    "motor's torque-speed curve drawn by the motor model from its datasheet values.",
    "assumed": "Not published: an engineering assumption to confirm with the maker.",
    "user": "From a catalog file supplied at start-up, or from your own input.",
}
PROVENANCE_KINDS = tuple(PROVENANCE_MEANINGS)


def _is_number(value: object) -> TypeGuard[int | float]:
    """A TOML integer or float (TOML booleans are Python ints: not numbers here)."""
    return isinstance(value, int | float) and not isinstance(value, bool)


class Entry:
    """Reads typed fields of one merged entry, naming the place on error."""

    def __init__(self, file: str, entry: str, data: Mapping[str, Any]) -> None:
        self.file, self.entry, self.data = file, entry, data

    def fail(self, name: str, reason: str) -> CatalogError:
        return CatalogError(self.file, self.entry, name, reason)

    def has(self, name: str) -> bool:
        return name in self.data

    def leaf(self, name: str) -> Mapping[str, Any]:
        """The raw value table of ``name``, after checking its provenance and source."""
        if name not in self.data:
            raise self.fail(name, "missing")
        raw = self.data[name]
        if not isinstance(raw, Mapping):
            raise self.fail(name, "must be a table {value = ..., provenance = ..., source = ...}")
        kind = raw.get("provenance")
        if kind not in PROVENANCE_KINDS:
            raise self.fail(name, f"provenance must be one of {', '.join(PROVENANCE_KINDS)}")
        source = raw.get("source")
        if kind not in ("seed", "user") and not (isinstance(source, str) and source.strip()):
            raise self.fail(name, f"a '{kind}' value needs a source or rule")
        if "range" in raw:
            self._check_range(name, raw)
        return raw

    def _check_range(self, name: str, raw: Mapping[str, Any]) -> None:
        """``range = [low, high]`` beside a number: finite, low <= value <= high."""
        span, value = raw["range"], raw.get("value")
        ok = (
            isinstance(span, list)
            and len(span) == 2
            and all(_is_number(x) and math.isfinite(x) for x in span)
        )
        if not ok or not _is_number(value):
            raise self.fail(name, "'range' must be [low, high], two numbers beside a number value")
        if not span[0] <= value <= span[1]:
            raise self.fail(
                name, f"'value' {value:g} lies outside its range {span[0]:g}-{span[1]:g}"
            )

    def ends(self, name: str) -> tuple[float, float] | None:
        """The (low, high) of a value given with a ``range``, else None."""
        if not self.has(name) or "range" not in self.leaf(name):
            return None
        low, high = self.leaf(name)["range"]
        return float(low), float(high)

    def at(self, name: str, value: float) -> "Entry":
        """The same entry with ``name``'s value replaced (to recompute what derives from it)."""
        return Entry(
            self.file, self.entry, {**self.data, name: {**self.leaf(name), "value": value}}
        )

    def prov(self, name: str) -> Provenance:
        raw = self.leaf(name)
        default = "seed pages" if raw["provenance"] == "seed" else "the user's own value"
        return Provenance(raw["provenance"], str(raw.get("source", default)))

    def number(
        self, name: str, key: str = "value", *, positive: bool = True, allow_zero: bool = False
    ) -> float:
        raw = self.leaf(name)
        value = raw.get(key)
        if not _is_number(value):
            raise self.fail(name, f"'{key}' must be a number")
        value = float(value)
        if not math.isfinite(value):
            raise self.fail(name, f"'{key}' must be finite")
        if positive and (value < 0 or (value == 0 and not allow_zero)):
            raise self.fail(
                name, f"'{key}' must be {'>= 0' if allow_zero else '> 0'}, got {value:g}"
            )
        return value

    def range(self, name: str, *, positive: bool = True) -> tuple[float, float]:
        """A min-max pair; temperatures pass ``positive=False`` (below 0 C is a range)."""
        low = self.number(name, "min", positive=positive, allow_zero=True)
        high = self.number(name, "max", positive=positive, allow_zero=True)
        if low > high:
            raise self.fail(name, f"min {low:g} is above max {high:g}")
        return low, high

    def text(self, name: str, choices: Iterable[str] | None = None, key: str = "value") -> str:
        value = self.leaf(name).get(key)
        if not isinstance(value, str):
            raise self.fail(name, f"'{key}' must be text")
        if choices is not None and value not in choices:
            raise self.fail(name, f"must be one of {', '.join(choices)}, got '{value}'")
        return value

    def flag(self, name: str) -> bool:
        value = self.leaf(name).get("value")
        if not isinstance(value, bool):
            raise self.fail(name, "'value' must be true or false")
        return value

    def texts(self, name: str) -> list[str]:
        value = self.leaf(name).get("value")
        if not isinstance(value, list) or not value or not all(isinstance(v, str) for v in value):
            raise self.fail(name, "'value' must be a non-empty list of text")
        return list(value)

    def rows(self, name: str, width: int) -> tuple[tuple[float, ...], ...]:
        """A table of rows of ``width`` finite numbers >= 0 (outgassing, speed bands)."""
        value = self.leaf(name).get("value")
        ok = isinstance(value, list) and all(
            isinstance(row, list)
            and len(row) == width
            and all(_is_number(x) and math.isfinite(x) and x >= 0 for x in row)
            for row in value
        )
        if not ok or not isinstance(value, list):
            raise self.fail(name, f"'value' must be a list of rows of {width} numbers >= 0")
        return tuple(tuple(float(x) for x in row) for row in value)

    def numbers(self, name: str) -> list[float]:
        value = self.leaf(name).get("value")
        if not isinstance(value, list) or not value:
            raise self.fail(name, "'value' must be a non-empty list of numbers")
        out = []
        for item in value:
            if not _is_number(item):
                raise self.fail(name, "every item must be a number")
            if not (math.isfinite(item) and item > 0):
                raise self.fail(name, f"every item must be finite and > 0, got {item}")
            out.append(float(item))
        return out

    def whole_numbers(self, name: str, most: int) -> list[int]:
        """A non-empty list of distinct whole numbers from 1 to ``most`` (thread starts)."""
        value = self.leaf(name).get("value")
        ok = (
            isinstance(value, list)
            and value
            and all(isinstance(v, int) and not isinstance(v, bool) for v in value)
            and all(1 <= v <= most for v in value)
        )
        if not ok or not isinstance(value, list):
            raise self.fail(name, f"'value' must be a non-empty list of whole numbers 1 to {most}")
        if len(set(value)) != len(value):
            raise self.fail(name, "a number is listed twice")
        return list(value)

    def plain_text(self, name: str, default: str | None = None) -> str:
        """A plain-text key (an id, a suffix): no provenance, it names rather than measures."""
        value = self.data.get(name, default)
        if not isinstance(value, str):
            raise self.fail(name, "missing or not text")
        return value

    def plain_flag(self, name: str) -> bool:
        """A plain true/false key that classifies (coated, anti-backlash)."""
        value = self.data.get(name)
        if not isinstance(value, bool):
            raise self.fail(name, "missing or not true/false")
        return value

    def check_known(self, known: frozenset[str]) -> None:
        """Every field of the entry is one the loader reads (catches misspelt names)."""
        for name in self.data:
            if name not in known:
                raise self.fail(name, "unknown field (see catalog/README.md for the fields)")


def sourced(entry: Entry, name: str, unit: str = "") -> Sourced:
    """A catalog number given in ``unit``, in SI with its SI unit."""
    si_unit = SI_UNITS[UNITS[unit].dimension]
    return Sourced(to_si(entry.number(name), unit), si_unit, entry.prov(name))


def optional(entry: Entry, values: Mapping[str, tuple[str, str]]) -> dict[str, Sourced]:
    """The numbers of ``values`` (field name -> (catalog key, unit)) the entry gives, in SI."""
    return {
        name: sourced(entry, key, unit) for name, (key, unit) in values.items() if entry.has(key)
    }
