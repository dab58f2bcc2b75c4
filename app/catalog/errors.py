"""The one error the catalog raises: it names the file, the entry and the field."""


class CatalogError(ValueError):
    """A catalog file that cannot be used; the message names file, entry and field.

    File-level faults (unreadable file, bad TOML, a table of the wrong type) have no
    entry or field yet and name "-" there, so every message has the same shape.
    """

    def __init__(self, file: str, entry: str, field_name: str, reason: str) -> None:
        self.file, self.entry, self.field, self.reason = file, entry, field_name, reason
        super().__init__(f"{file}: entry '{entry}': field '{field_name}': {reason}")
