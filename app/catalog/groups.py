"""Groups: a maker's shared tables (``common.toml``), and the layer each family builds on."""

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from app.catalog.entry import Entry
from app.catalog.errors import CatalogError
from app.catalog.files import (
    FIRST_LAYOUT,
    GROUP_KEYS,
    CatalogFile,
    Layer,
    check_shape,
    layer_of,
    over,
    table,
)

GROUP_FIELDS = frozenset({"id", "name", "extends"})
#: The group that files of the first layout (no ``schema`` key) layer over, as they did.
SEED_GROUP = "seed"
#: Keys of ``[family]`` that only a family file may set: a group names no family.
FAMILY_ONLY = ("id", "name", "extends")


@dataclass(frozen=True, slots=True)
class Group:
    """One ``common.toml``: its id, the group it extends (if any) and its own tables."""

    id: str
    extends: str | None
    directory: Path
    layer: Layer


def read_group(source: CatalogFile) -> Group:
    """Check a group file's shape and read its ``[group]`` table.

    A first-layout ``common.toml`` has no ``[group]``: it is its directory's group over
    the seed group, which is what it meant before groups were named.
    """
    first_layout = check_shape(source, GROUP_KEYS) == FIRST_LAYOUT
    entry = Entry(source.name, "group", table(source.data, "group", source.name))
    entry.check_known(GROUP_FIELDS)
    layer = layer_of(source)
    for key in FAMILY_ONLY:
        if key in layer.family:
            raise CatalogError(source.name, "family", key, "set by each family file, not a group")
    if first_layout and not entry.has("id"):
        return Group(str(source.directory), SEED_GROUP, source.directory, layer)
    extends = entry.plain_text("extends") if entry.has("extends") else None
    return Group(entry.plain_text("id"), extends, source.directory, layer)


class Groups:
    """Every group of the loaded directories, resolved on demand along ``extends``."""

    def __init__(self, groups: list[Group]) -> None:
        self.by_id: dict[str, Group] = {}
        self.by_directory: dict[Path, str] = {}
        for group in groups:
            if group.id in self.by_id:
                raise CatalogError(group.layer.file, "group", "id", f"duplicate group '{group.id}'")
            self.by_id[group.id] = group
            self.by_directory[group.directory] = group.id

    def resolve(self, group_id: str, file: str, chain: tuple[str, ...] = ()) -> Layer:
        """The group's tables over those of every group it extends, nearest last."""
        if group_id not in self.by_id:
            known = ", ".join(sorted(self.by_id)) or "none"
            raise CatalogError(file, "family", "extends", f"no group '{group_id}' (known: {known})")
        if group_id in chain:
            raise CatalogError(file, "group", "extends", f"extends itself via {' -> '.join(chain)}")
        group = self.by_id[group_id]
        if group.extends is None:
            return group.layer
        return over(self.resolve(group.extends, group.layer.file, (*chain, group_id)), group.layer)

    def base_of(self, source: CatalogFile, family: Mapping[str, object], schema: int) -> Layer:
        """The layer a family file builds on: the group it names, else its directory's;
        a first-layout file with neither builds on the seed group, as it always did."""
        named = family.get("extends")
        if named is None and schema == FIRST_LAYOUT:
            named = self.by_directory.get(source.directory, SEED_GROUP)
        if named is not None:
            if not isinstance(named, str):
                raise CatalogError(source.name, "family", "extends", "must be a group id (text)")
            return self.resolve(named, source.name)
        own = self.by_directory.get(source.directory)
        return Layer(source.name) if own is None else self.resolve(own, source.name)
