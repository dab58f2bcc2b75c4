"""The Jinja2 environment shared by page routes and error pages."""

import math
from typing import Any

import pydantic_core
from fastapi.templating import Jinja2Templates

from app.core.verdict import value_label
from app.server.paths import resource_dir

templates = Jinja2Templates(directory=str(resource_dir("templates")))
# templates are part of the installed package: no per-render file checks
templates.env.auto_reload = False


def _json(value: Any, **_: Any) -> str:
    """The JSON of ``tojson`` (which then escapes it for HTML): pydantic-core's encoder,
    about four times faster than the standard library's on the charts, and NaN or
    infinity as null (JSON has neither, and a browser's JSON.parse refuses them)."""
    return pydantic_core.to_json(value, inf_nan_mode="null").decode()


def figures(value: float) -> str:
    """A count or life to three significant figures as an engineer writes it: without an
    exponent from 0.001 to below ten million, thousands grouped.

    >>> figures(2391.7), figures(262.04), figures(0.04567), figures(4.2e8), figures(1.5e-5)
    ('2,390', '262', '0.0457', '4.2e+08', '1.5e-05')
    >>> figures(0.0), figures(float("inf"))
    ('0', 'inf')
    """
    if not math.isfinite(value) or value == 0 or not -3 <= math.floor(math.log10(abs(value))) < 7:
        return f"{value:.3g}"
    rounded = float(f"{value:.3g}")
    return f"{rounded:,.0f}" if rounded >= 100 else f"{rounded:.3g}"


templates.env.policies["json.dumps_function"] = _json
templates.env.filters["figures"] = figures
templates.env.globals["value_label"] = value_label
templates.env.filters["value_label"] = value_label
