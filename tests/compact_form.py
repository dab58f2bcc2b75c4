"""The compact form's rule (``app.contract.schemas.COMPACT_VIEWS``), checked against the
full form of the same candidate: every number to 6 significant figures, within half a
unit of the sixth figure of the full value (relative 5e-6), and a value left out exactly
where the full form gives null."""

import math
from typing import Any

import pytest

from app.contract.schemas import View

#: Rounding to 6 significant figures moves a number by at most half a unit of its sixth
#: figure: 0.5e-5 of a leading digit of 1 at the worst.
RELATIVE = 5e-6


def _null(value: Any) -> bool:
    return value is None or (isinstance(value, float) and not math.isfinite(value))


def _empty(full: Any, view: View | bool) -> bool:
    """Whether ``full`` is an object none of whose fields in ``view`` is worked out: the
    compact form leaves such a part out (``app.report.reader``; the parts that may be null,
    which are the only ones that can be so)."""
    if not isinstance(full, dict) or view is True:
        return False
    return all(_null(full[k]) or _empty(full[k], view[k]) for k in view)


def assert_compact_of(compact: Any, full: Any, view: View | bool = True, at: str = "") -> None:
    """``compact`` is ``full`` (JSON values) in the compact form of ``view`` (True: whole):
    each key of the view that is not null in ``full`` and no other, each number to 6
    significant figures and equal to the full one within ``RELATIVE``; a part with nothing
    in ``view`` worked out is left out."""
    if isinstance(full, dict):
        assert isinstance(compact, dict), at
        shown = full if view is True else view
        expected = {k for k in shown if not _null(full[k]) and not _empty(full[k], shown[k])}
        assert set(compact) == expected, f"{at}: {sorted(set(compact) ^ expected)}"
        for key in expected:
            part = True if view is True else view[key]
            assert_compact_of(compact[key], full[key], part, f"{at}.{key}")
    elif isinstance(full, list):
        assert isinstance(compact, list) and len(compact) == len(full), at
        for i, (c, f) in enumerate(zip(compact, full, strict=True)):
            assert_compact_of(c, f, view, f"{at}[{i}]")
    elif isinstance(full, float) and math.isfinite(full):
        assert isinstance(compact, float), at
        assert compact == float(f"{compact:.6g}"), f"{at}: {compact} has more than 6 figures"
        assert compact == pytest.approx(full, rel=RELATIVE, abs=0.0), at
    else:
        assert compact == (None if _null(full) else full), at


def null_keys(value: Any, at: str = "") -> list[str]:
    """Where a JSON value has a key whose value is null."""
    if isinstance(value, dict):
        found = [f"{at}.{k}" for k, v in value.items() if v is None]
        return found + [p for k, v in value.items() for p in null_keys(v, f"{at}.{k}")]
    if isinstance(value, list):
        return [p for i, v in enumerate(value) for p in null_keys(v, f"{at}[{i}]")]
    return []
