"""The built-in catalog's leadscrew families, for tests that assert a leadscrew-specific
ranking: by default ball screws rank beside the leadscrews, so those tests name the
leadscrew families."""

from app.catalog import Catalog


def leadscrew_families(catalog: Catalog) -> tuple[str, ...]:
    """Every family of sliding leadscrews in ``catalog``, sorted."""
    return tuple(sorted({s.family_id for s in catalog.screws if s.screw_type == "lead"}))
