"""The page templates' JSON (``tojson``, the charts' data): valid JSON, HTML-safe."""

import json
import math

from app.web.templating import templates


def test_tojson_gives_json_a_browser_parses_and_html_cannot_break_out_of() -> None:
    figure = {"y": [1.5, math.nan, math.inf], "name": "</script><b>'x' & y</b>", "n": 1e-5}
    text = templates.env.from_string("{{ figure | tojson }}").render(figure=figure)
    assert "<" not in text and ">" not in text and "&" not in text and "'" not in text
    assert "NaN" not in text and "Infinity" not in text
    assert json.loads(text) == {"y": [1.5, None, None], "name": figure["name"], "n": 1e-5}
