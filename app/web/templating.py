"""The Jinja2 environment shared by page routes and error pages."""

from typing import Any

import pydantic_core
from fastapi.templating import Jinja2Templates

from app.catalog.axis_motor import CURVE_ORIGINS
from app.catalog.entry import PROVENANCE_MEANINGS
from app.contract.figures import apart, sig
from app.core.phrase import figures
from app.core.wording import percent, times, value_label
from app.paths import resource_dir

templates = Jinja2Templates(directory=str(resource_dir("templates")))
# templates are part of the installed package: no per-render file checks
templates.env.auto_reload = False


def _json(value: Any, **_: Any) -> str:
    """The JSON of ``tojson`` (which then escapes it for HTML): pydantic-core's encoder,
    about four times faster than the standard library's on the charts, and NaN or
    infinity as null (JSON has neither, and a browser's JSON.parse refuses them)."""
    return pydantic_core.to_json(value, inf_nan_mode="null").decode()


def band(ends: Any) -> str:
    """A (low, high) band to its figures, "low–high"; one figure where the ends agree
    (a ball nut's L10 life is one value, a plain nut's wear life a band).

    >>> band((3178.53, 3178.53)), band((507.4, 4610.0))
    ('3,180', '507–4,610')
    """
    low, high = figures(ends[0]), figures(ends[1])
    return low if low == high else f"{low}–{high}"


templates.env.policies["json.dumps_function"] = _json
templates.env.filters["figures"] = figures
templates.env.filters["sig"] = sig
templates.env.globals["apart"] = apart
templates.env.filters["band"] = band
templates.env.filters["percent"] = percent
templates.env.filters["times"] = times
templates.env.globals["value_label"] = value_label
#: where a motor curve comes from, in words (the results' and the report's footnotes)
templates.env.globals["curve_origins"] = CURVE_ORIGINS
#: each provenance kind in words (the catalog pages' legend)
templates.env.globals["provenance_meanings"] = PROVENANCE_MEANINGS
templates.env.filters["value_label"] = value_label
