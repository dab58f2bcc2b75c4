"""The check registry: every module of this package defines one check and registers it.

Screening, evaluation, the formulas table, the API's check list and the page iterate
``REGISTRY`` in its order. Adding a check is adding one module here (and its test).
"""

import importlib
import pkgutil

from app.core.checks.base import Check

_found: list[Check] = []


def register(cls: type[Check]) -> type[Check]:
    """Class decorator: add one instance of ``cls`` to the registry."""
    _found.append(cls())
    return cls


for _module in pkgutil.iter_modules(__path__):
    if _module.name != "base":
        importlib.import_module(f"{__name__}.{_module.name}")

#: Every check, in the order results list them.
REGISTRY: tuple[Check, ...] = tuple(sorted(_found, key=lambda c: c.order))
BY_NAME: dict[str, Check] = {c.name: c for c in REGISTRY}

__all__ = ["BY_NAME", "REGISTRY", "Check", "register"]
