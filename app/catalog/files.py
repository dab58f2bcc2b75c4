"""Catalog files on disk: finding them, reading them safely, and layering their tables.

Every fault of the file system or of the TOML shape (unreadable file, symlink loop,
invalid UTF-8, a table of the wrong type) becomes a ``CatalogError`` naming the file,
so the app stops with a message instead of a traceback.

Layering (catalog/README.md, "Layering"): a family file layers over one group, the
group named by its ``[family] extends``, or else the ``common.toml`` of its own
directory; a group may itself extend another group. Nothing is inherited otherwise,
except by files of the first layout (no ``schema`` key), which keep their old meaning:
they layer over the built-in seed group.
"""

import hashlib
import stat
import tomllib
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TypeVar

from app.catalog.errors import CatalogError

T = TypeVar("T")

SCHEMA = 2
#: Files without a ``schema`` key are the first layout (series files over the seed group).
FIRST_LAYOUT = 1
GROUP_FILE = "common.toml"
NESTED_TABLES = ("variants", "nut_types", "rules", "materials")
LAYER_TABLES = ("family", "defaults", *NESTED_TABLES)
GROUP_KEYS = frozenset({"schema", "catalog_version", "group", "provenance", *LAYER_TABLES})
FAMILY_KEYS = frozenset({"schema", "series", "provenance", *LAYER_TABLES})
#: A catalog file's size at most (the largest built-in file is under 10 kB).
MAX_FILE_BYTES = 1024 * 1024
#: Tables and arrays nested at most this deep (the built-in files nest 6 deep).
MAX_DEPTH = 16


@dataclass(frozen=True, slots=True)
class CatalogFile:
    """One parsed file: its name (as errors show it), its directory and its tables."""

    name: str
    directory: Path
    data: Mapping[str, Any]


@dataclass(frozen=True, slots=True)
class Layer:
    """The tables one file (or a file over its group) gives the families built on it."""

    file: str
    family: Mapping[str, Any] = field(default_factory=dict)
    defaults: Mapping[str, Any] = field(default_factory=dict)
    variants: Mapping[str, Mapping[str, Any]] = field(default_factory=dict)
    nut_types: Mapping[str, Mapping[str, Any]] = field(default_factory=dict)
    rules: Mapping[str, Mapping[str, Any]] = field(default_factory=dict)


def _toml_type(value: object) -> str:
    names = {bool: "a boolean", int: "an integer", float: "a float", str: "text", list: "an array"}
    return names.get(type(value), type(value).__name__)


def _reason(exc: OSError) -> str:
    return exc.strerror or str(exc)


def _read_regular(path: Path) -> bytes:
    """The bytes of a regular file (a link is followed) of at most ``MAX_FILE_BYTES``.

    A device (a link to /dev/zero would read until memory runs out) or a FIFO (opening it
    waits for a writer) is refused before it is opened; a file that grows past the limit
    while it is read is refused after one read past it.
    """
    try:
        info = path.stat()
        if not stat.S_ISREG(info.st_mode):
            raise CatalogError(path.name, "-", "-", "not a regular file")
        if info.st_size > MAX_FILE_BYTES:
            raise CatalogError(path.name, "-", "-", f"larger than {MAX_FILE_BYTES} bytes")
        with path.open("rb") as file:
            raw = file.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise CatalogError(path.name, "-", "-", f"cannot read the file: {_reason(exc)}") from exc
    if len(raw) > MAX_FILE_BYTES:
        raise CatalogError(path.name, "-", "-", f"larger than {MAX_FILE_BYTES} bytes")
    return raw


def depth(data: object, most: int = MAX_DEPTH) -> int:
    """How deeply tables and arrays nest in ``data`` (a plain value: 0), counted without
    recursion and only to one past ``most``: tomllib builds a table 500 levels deep from
    a kilobyte of dotted keys, deeper than Python's own stack would follow.

    >>> depth({"a": [1, {"b": 2}]}), depth(3), depth([[[[1]]]], most=2)
    (3, 0, 3)
    """
    deepest = 0
    stack: list[tuple[object, int]] = [(data, 0)]
    while stack:
        value, level = stack.pop()
        if isinstance(value, dict):
            value = list(value.values())
        if not isinstance(value, list):
            continue
        deepest = max(deepest, level + 1)
        if deepest > most:
            return deepest
        stack.extend((item, level + 1) for item in value)
    return deepest


def read_file(path: Path, digest: Any) -> CatalogFile:
    """Parse one file; its bytes feed the version digest so any edit shows in results."""
    raw = _read_regular(path)
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise CatalogError(path.name, "-", "-", f"not valid UTF-8 at byte {exc.start}") from exc
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CatalogError(path.name, "-", "-", f"invalid TOML: {exc}") from exc
    except RecursionError as exc:
        raise CatalogError(path.name, "-", "-", f"nested deeper than {MAX_DEPTH}") from exc
    if depth(data) > MAX_DEPTH:
        raise CatalogError(path.name, "-", "-", f"nested deeper than {MAX_DEPTH}")
    digest.update(raw)
    return CatalogFile(path.name, path.parent, data)


#: Keys that make a table a catalog value (a number, a min-max pair, a thread form).
VALUE_KEYS = frozenset({"value", "min", "max", "half_angle_deg"})


def _user_values(data: Any, file: str) -> Any:
    """``data`` with provenance "user" on every value table that names none."""
    if isinstance(data, list):
        return [_user_values(item, file) for item in data]
    if not isinstance(data, dict):
        return data
    out = {key: _user_values(value, file) for key, value in data.items()}
    if VALUE_KEYS & out.keys() and "provenance" not in out:
        out["provenance"] = "user"
        out.setdefault("source", f"user catalog file {file}")
    return out


def as_user(data: Mapping[str, Any], file: str) -> dict[str, Any]:
    """A user's file with provenance "user" on every value that names none, so a user's
    own numbers show as theirs (catalog/README.md, "Your own catalog"). A value that
    names its provenance keeps it; the file-wide ``provenance`` key itself is no value.
    """
    return {key: _user_values(value, file) for key, value in data.items() if key != "provenance"}


def _entries(directory: Path) -> list[Path]:
    try:
        return sorted(directory.iterdir())
    except OSError as exc:
        raise CatalogError(str(directory), "-", "-", f"cannot list: {_reason(exc)}") from exc


def _resolved(directory: Path) -> Path:
    try:
        return directory.resolve(strict=True)
    except (OSError, RuntimeError) as exc:
        raise CatalogError(str(directory), "-", "-", f"cannot follow: {exc}") from exc


def catalog_dirs(roots: Iterable[Path]) -> list[Path]:
    """Each root and its immediate subdirectories (a maker's group of family files).

    A directory reached twice (a symlink pointing back up, or a root given twice) is an
    error rather than a second copy of every series.
    """
    seen: dict[Path, Path] = {}
    out = []
    for root in roots:
        if not root.is_dir():
            raise CatalogError(str(root), "-", "-", "catalog directory not found")
        subdirs = [p for p in _entries(root) if p.is_dir() and not p.name.startswith(".")]
        for directory in (root, *subdirs):
            real = _resolved(directory)
            if real in seen:
                raise CatalogError(
                    str(directory), "-", "-", f"reaches {seen[real]} again (a symlink loop?)"
                )
            seen[real] = directory
            out.append(directory)
    return out


def toml_files(directory: Path) -> list[Path]:
    """The ``*.toml`` entries of a directory; a dangling or looping link is kept so that
    reading it reports the fault instead of skipping the file silently."""
    return [p for p in _entries(directory) if p.suffix == ".toml" and not p.is_dir()]


def table(data: Mapping[str, Any], key: str, file: str, entry: str = "-") -> dict[str, Any]:
    """``data[key]`` as a table ({} when absent), or a CatalogError naming it."""
    value = data.get(key, {})
    if not isinstance(value, dict):
        raise CatalogError(file, entry, key, f"must be a table, got {_toml_type(value)}")
    return value


def nested(data: Mapping[str, Any], key: str, file: str) -> dict[str, dict[str, Any]]:
    """A table of tables such as ``[variants.NAME]``, each checked to be a table."""
    outer = table(data, key, file)
    for name in outer:
        table(outer, name, file, key)
    return outer


def check_shape(source: CatalogFile, known: frozenset[str]) -> int:
    """The file's layout version, after checking its top-level keys."""
    for key in source.data:
        if key not in known:
            raise CatalogError(source.name, "-", key, "unknown top-level key or table")
    schema = source.data.get("schema", FIRST_LAYOUT)
    if schema not in (FIRST_LAYOUT, SCHEMA):
        raise CatalogError(source.name, "-", "schema", f"must be {SCHEMA}; got {schema!r}")
    return int(schema)


def layer_of(source: CatalogFile) -> Layer:
    """The layering tables of one file, each checked to be a table."""
    data, name = source.data, source.name
    return Layer(
        file=name,
        family=table(data, "family", name),
        defaults=table(data, "defaults", name),
        variants=nested(data, "variants", name),
        nut_types=nested(data, "nut_types", name),
        rules=nested(data, "rules", name),
    )


def _merge_nested(
    base: Mapping[str, Mapping[str, Any]], top: Mapping[str, Mapping[str, Any]]
) -> dict[str, Mapping[str, Any]]:
    return {key: {**base.get(key, {}), **top.get(key, {})} for key in {**base, **top}}


def over(base: Layer, top: Layer) -> Layer:
    """``top`` layered over ``base``: per key, and per field inside variants, nut types and
    rules, so a family can change one value of a group's variant."""
    return Layer(
        file=top.file,
        family={**base.family, **top.family},
        defaults={**base.defaults, **top.defaults},
        variants=_merge_nested(base.variants, top.variants),
        nut_types=_merge_nested(base.nut_types, top.nut_types),
        rules=_merge_nested(base.rules, top.rules),
    )


def library_entries(path: Path, digest: Any, table: str, schema: int) -> tuple[str, dict[str, Any]]:
    """A library file's name and its ``[table.ID]`` entries (motors, support units), its
    bytes fed to ``digest`` (a new SHA-256 when None); refused unless it declares
    ``schema`` and holds only that table, with at least one entry."""
    source = read_file(path, digest if digest is not None else hashlib.sha256())
    if source.data.get("schema") != schema:
        raise CatalogError(source.name, "-", "schema", f"must be {schema}")
    unknown = set(source.data) - {"schema", table}
    if unknown:
        raise CatalogError(source.name, "-", sorted(unknown)[0], "unknown key")
    entries = source.data.get(table)
    if not isinstance(entries, dict) or not entries:
        raise CatalogError(source.name, "-", table, f"no [{table}.ID] entries")
    return source.name, entries


def merge_libraries(
    directories: Iterable[Path], filename: str, load: Callable[[Path], dict[str, T]], what: str
) -> dict[str, T]:
    """The entries of every directory's library file ``filename`` read by ``load``, ids
    unique across directories (a duplicate names its file and id)."""
    out: dict[str, T] = {}
    for directory in directories:
        path = directory / filename
        if not path.exists():
            continue
        for key, value in load(path).items():
            if key in out:
                raise CatalogError(str(path), f"{what}s.{key}", "-", f"duplicate {what} id")
            out[key] = value
    return out
