"""JSON responses written straight from the typed output models."""

from typing import Any

import pydantic_core
from fastapi.responses import Response


class ModelJSON(Response):
    """JSON written by pydantic-core, the serializer FastAPI uses for a ``response_model``.

    The select and evaluate dicts are built field for field to their output models by
    ``app.report.service``; validating them again on every request cost more than serializing
    them (1.5 ms of 2.3 ms for a select). They are served as they are, byte for byte what
    the validated model would give (non-finite floats as null);
    tests/api/test_api_serialization.py checks that the served JSON equals the model's.
    """

    media_type = "application/json"

    def render(self, content: Any) -> bytes:
        return pydantic_core.to_json(content, inf_nan_mode="null")
