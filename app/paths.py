"""Where templates, static files and the built-in catalog live.

In a source checkout they sit beside ``app/``; in an installed wheel they are packaged
inside it (``app/templates``, ``app/static``, ``app/catalog_data``).

>>> resource_dir("templates").name
'templates'

"""

from pathlib import Path

#: the ``app`` package's folder (this module sits in it)
_PACKAGE = Path(__file__).resolve().parent
_INSTALLED = {"templates": "templates", "static": "static", "catalog": "catalog_data"}


def resource_dir(name: str) -> Path:
    """Directory of a bundled resource: ``templates``, ``static`` or ``catalog``."""
    inside = _PACKAGE / _INSTALLED[name]
    return inside if inside.is_dir() else _PACKAGE.parent / name
