"""Reading a view of an output model from a source: each field as its ``From`` declares
(``app.contract.source``), nested models by their own view.

``reader(model, view)`` compiles the view of a model once into one function, as
``dataclasses`` compiles ``__init__``: a field reads ``s.screw.lead_m * 1000.0`` inline,
so a view costs about what a hand-written function would (a compact select reads some
twenty fields of twenty candidates on every request).
"""

import math
from collections.abc import Callable
from functools import cache, lru_cache
from operator import attrgetter
from types import UnionType
from typing import Any, Literal, Union, cast, get_args, get_origin

from pydantic import BaseModel
from pydantic.fields import FieldInfo

from app.contract.schemas import VIEWS, View
from app.contract.source import From, Writer
from app.contract.units import API_UNITS, DEFAULT_UNITS
from app.core.phrase import Phrase
from app.report.construct import construct, from_fields

#: (source, record, sentences' writer) -> the view: a dict of JSON values, or the model.
Reader = Callable[[Any, Any, Writer], Any]


@cache
def reader(
    model: type[BaseModel], view: str, path: tuple[str, ...] = (), as_dict: bool = False
) -> Reader:
    """The function that reads ``model`` in ``VIEWS[view]`` (at ``path``, field names, for
    a nested model) from a source: as a dict of JSON values (``as_dict``) or as the model
    holding the view's fields alone (``construct``, no validation)."""
    shown = _view(model, view, path)
    whole = len(shown) == len(model.model_fields)
    make = from_fields if whole else construct
    env: dict[str, Any] = {"make": make, "model": model, "_plain": _plain}
    items = [
        f"{name!r}: {_expression(info, view, (*path, name), as_dict, env, f'_{i}')}"
        for i, (name, info) in enumerate(model.model_fields.items())
        if name in shown
    ]
    values = "{" + ", ".join(items) + "}"
    body = values if as_dict else f"make(model, {values})" if whole else f"make(model, **{values})"
    exec(f"def read(s, r, u):\n    return {body}\n", env)
    return cast(Reader, env["read"])


def _view(model: type[BaseModel], view: str, path: tuple[str, ...]) -> View:
    """The part of ``VIEWS[view]`` at ``path`` (field names), every field of ``model``
    where the view takes a nested model whole."""
    part: Any = VIEWS[view]
    for name in path:
        part = part[name]
        if part is True:
            return dict.fromkeys(model.model_fields, True)
    return cast(View, part)


def _expression(
    info: FieldInfo, view: str, path: tuple[str, ...], as_dict: bool, env: dict[str, Any], key: str
) -> str:
    """The Python expression of one field's value over ``s`` (the source), ``r`` (the
    record) and ``u`` (the sentences' writer); the values it needs go in ``env`` under
    ``key``."""
    source = next((m for m in info.metadata if isinstance(m, From)), None)
    if source is None:
        env[key] = info.default
        return key
    value = _access(source.path, env, key)
    nested, shape = _nested(info.annotation)
    if nested is not None:
        read = reader(nested, view, path, as_dict)
        env[key] = _shared(read) if nested.model_config.get("frozen") else read
        each = {
            "list": f"[{key}(x, r, u) for x in v]",
            "dict": f"{{k: {key}(x, r, u) for k, x in v.items()}}",
        }.get(shape, f"{key}(v, r, u)")
        return f"(None if (v := {value}) is None else {each})"
    if source.via is not None:
        env[key] = source.via
        return f"{key}({value}, u)"
    if source.quantity is not None:
        env[key], env[key + "q"] = _scaled, API_UNITS[source.quantity][1]
        return f"{key}({value}, {key}q)"
    kind = _kind(info.annotation)
    if kind == "number":
        return f"(v if (v := {value}) == v else None)"
    if kind == "text":
        return f"(v if type(v := {value}) is str else _plain(v, u))"
    if kind == "texts":
        return f"list({value})"
    return value if kind == "raw" else f"_plain({value}, u)"


def _access(path: str | tuple[str, ...], env: dict[str, Any], key: str) -> str:
    """The expression of the value at ``path`` (see ``app.contract.source``)."""
    if isinstance(path, tuple):
        env[key + "g"], env[key + "w"] = attrgetter(*path), _whole
        return f"{key}w({key}g(s))"
    base, names = ("r", path[1:]) if path.startswith("/") else ("s", path)
    if not names:
        return base
    if names.isdigit():
        return f"{base}[{int(names)}]"
    if not all(n.isidentifier() for n in names.split(".")):
        raise ValueError(f"not an attribute path: {path!r}")
    return f"{base}.{names}"


def _whole(values: tuple[Any, ...]) -> tuple[Any, ...] | None:
    """Values read together: None when one of them is None."""
    return None if any(v is None for v in values) else values


def _shared(read: Reader) -> Reader:
    """A frozen output model reads its source alone (no record, no units): built once
    per source (e.g. a catalog value's provenance, the same in every response)."""
    made = lru_cache(maxsize=8192)(lambda x: read(x, None, Writer(DEFAULT_UNITS)))
    return lambda x, r, u: made(x)


def _nested(annotation: Any) -> tuple[type[BaseModel] | None, str]:
    """The output model in a field's type and how it is held: ("one", "list" or "dict");
    (None, "") for a plain value."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation, "one"
    origin, args = get_origin(annotation), get_args(annotation)
    if origin in (UnionType, Union):
        return next(
            ((m, shape) for a in args for m, shape in [_nested(a)] if m is not None), (None, "")
        )
    model = args[-1] if origin in (list, dict) else None
    if isinstance(model, type) and issubclass(model, BaseModel):
        return model, origin.__name__
    return None, ""


def _kind(annotation: Any) -> str:
    """How a value of this type is written: "number" (a float: NaN as None), "text" (a
    string, or a sentence to write), "texts" (a list of strings, from any sequence of
    them), "raw" (yes/no, a count, a choice: as it is) or "plain" (anything else:
    ``_plain``)."""
    args = set(get_args(annotation)) if get_origin(annotation) in (UnionType, Union) else set()
    types = (args or {annotation}) - {type(None)}
    if types <= {float}:
        return "number"
    if types <= {str}:
        return "text"
    if annotation == list[str]:
        return "texts"
    if all(t in (bool, int) or get_origin(t) is Literal for t in types):
        return "raw"
    return "plain"


def _scaled(value: Any, scale: float) -> Any:
    """An SI number (or a tuple of them) in the API unit; NaN as None."""
    if value is None:
        return None
    if isinstance(value, tuple):
        return [v * scale for v in value]
    return None if math.isnan(value) else value * scale


def _plain(value: Any, w: Writer) -> Any:
    """A value as JSON holds it: NaN as None, tuples as lists, sentences written by ``w``."""
    kind = type(value)
    if kind is str or value is None:
        return value
    if kind is float:
        return None if math.isnan(value) else value
    if kind is tuple:
        return [_plain(v, w) for v in value]
    if kind is Phrase:
        return w.text(value)
    return value
