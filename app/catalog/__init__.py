"""The only reader of ``catalog/``: load, validate, derive and expand into candidates.

Modules: ``files`` (finding, reading and layering files), ``groups`` (shared group
tables), ``family`` (thread form, id pattern, nut types, variants, rules), ``series``
(one entry into its candidates), ``entry`` (typed values with provenance), ``models``
(the values the app receives), ``catalog`` (the whole of it) and ``loader`` (all of it
into one ``Catalog``). Any error stops start-up with the file, the entry and the field
named (``CatalogError``).
"""

from app.catalog.catalog import Catalog
from app.catalog.entry import PROVENANCE_KINDS
from app.catalog.errors import CatalogError
from app.catalog.loader import load_catalog
from app.catalog.models import Material, Series, Sourced

__all__ = [
    "PROVENANCE_KINDS",
    "Catalog",
    "CatalogError",
    "Material",
    "Series",
    "Sourced",
    "load_catalog",
]
