"""Reading a view of an output model from a source: each field as its ``From`` declares
(``app.contract.source``), nested models by their own view.

``reader(model, view)`` works out once per view which fields it reads and how (a getter
per field: the path's ``attrgetter``, the unit's factor, the nested model's own reader),
and returns the function that reads them: a compact select reads some twenty fields of
twenty candidates on every request, so nothing is looked up per call.

A compact view (``COMPACT_VIEWS``) read as JSON is in the compact form: each number to
``COMPACT_FIGURES`` significant figures, and a value not worked out for the query (None,
a non-finite number, a dict's None value, a part that may be null with none of its view's
fields worked out) left out; the getters of such a view do it as
they read, so the finished dict is never walked again.
"""

import math
from collections.abc import Callable
from functools import cache, lru_cache
from operator import attrgetter, itemgetter
from types import UnionType
from typing import Any, Literal, Union, cast, get_args, get_origin

from pydantic import BaseModel
from pydantic.fields import FieldInfo

from app.contract.schemas import COMPACT_FIGURES, COMPACT_VIEWS, VIEWS, View
from app.contract.source import From, Writer
from app.contract.units import API_UNITS, DEFAULT_UNITS
from app.core.phrase import Phrase

#: A number to ``COMPACT_FIGURES`` significant figures, as text (the fastest of the ways).
FIGURES = f"%.{COMPACT_FIGURES}g"
INF = math.inf
#: (source, record, sentences' writer) -> the view: a dict of JSON values, or the model.
Reader = Callable[[Any, Any, Writer], Any]
#: (source, record, sentences' writer) -> one field's value.
Getter = Callable[[Any, Any, Writer], Any]


@cache
def reader(
    model: type[BaseModel], view: str, path: tuple[str, ...] = (), as_dict: bool = False
) -> Reader:
    """The function that reads ``model`` in ``VIEWS[view]`` (at ``path``, field names, for
    a nested model) from a source: as a dict of JSON values (``as_dict``) or as the model
    holding the view's fields alone (``model_construct``: no validation)."""
    shown = _view(model, view, path)
    compact = as_dict and view in COMPACT_VIEWS
    fields = tuple(
        (name, _getter(info, view, (*path, name), as_dict, compact))
        for name, info in model.model_fields.items()
        if name in shown
    )

    def read_dict(s: Any, r: Any, u: Writer) -> dict[str, Any]:
        return {name: get(s, r, u) for name, get in fields}

    def read_compact(s: Any, r: Any, u: Writer) -> dict[str, Any]:
        return {name: v for name, get in fields if (v := get(s, r, u)) is not None}

    if compact:
        return read_compact

    def read_model(s: Any, r: Any, u: Writer) -> BaseModel:
        return model.model_construct(**{name: get(s, r, u) for name, get in fields})

    return read_dict if as_dict else read_model


def _view(model: type[BaseModel], view: str, path: tuple[str, ...]) -> View:
    """The part of ``VIEWS[view]`` at ``path`` (field names), every field of ``model``
    where the view takes a nested model whole."""
    part: Any = VIEWS[view]
    for name in path:
        part = part[name]
        if part is True:
            return dict.fromkeys(model.model_fields, True)
    return cast(View, part)


def _getter(
    info: FieldInfo, view: str, path: tuple[str, ...], as_dict: bool, compact: bool = False
) -> Getter:
    """How one field's value is read from ``s`` (the source), ``r`` (the record) and ``u``
    (the sentences' writer); ``compact``: in the compact form (``COMPACT_VIEWS``), numbers
    to ``COMPACT_FIGURES`` significant figures and a dict without its null values."""
    source = next((m for m in info.metadata if isinstance(m, From)), None)
    if source is None:
        default = info.default
        return lambda s, r, u: default
    at = _access(source.path)
    nested, shape = _nested(info.annotation)
    if nested is not None:
        read = reader(nested, view, path, as_dict)
        get = _each(at, _shared(read) if nested.model_config.get("frozen") else read, shape)
        if compact and shape == "one" and _nullable(info.annotation):
            # nothing of it worked out for this query (e.g. a life's years without a duty)
            return lambda s, r, u: v if (v := get(s, r, u)) else None
        return get
    if source.via is not None:
        via = source.via
        if compact:
            return lambda s, r, u: _compact(via(at(s, r), u))
        return lambda s, r, u: via(at(s, r), u)
    if source.quantity is not None:
        scale = API_UNITS[source.quantity][1]
        if compact:
            return lambda s, r, u: _scaled_figures(at(s, r), scale)
        return lambda s, r, u: _scaled(at(s, r), scale)
    kind = _kind(info.annotation)
    if compact and kind == "number":
        return lambda s, r, u: _figures(at(s, r))
    if compact and kind == "plain":
        return lambda s, r, u: _compact(_plain(at(s, r), u))
    return _written(at, kind)


def _each(at: Callable[[Any, Any], Any], read: Reader, shape: str) -> Getter:
    """A nested model's value: read from the value at the path, or from each of its items
    (``shape``: "one", "list" or "dict"); None where that value is None."""

    def one(s: Any, r: Any, u: Writer) -> Any:
        v = at(s, r)
        return None if v is None else read(v, r, u)

    def each(s: Any, r: Any, u: Writer) -> Any:
        v = at(s, r)
        return None if v is None else [read(x, r, u) for x in v]

    def each_value(s: Any, r: Any, u: Writer) -> Any:
        v = at(s, r)
        return None if v is None else {k: read(x, r, u) for k, x in v.items()}

    return {"list": each, "dict": each_value}.get(shape, one)


def _written(at: Callable[[Any, Any], Any], kind: str) -> Getter:
    """A plain value as its kind (``_kind``) is written."""
    if kind == "number":
        return lambda s, r, u: _number(at(s, r))
    if kind == "text":
        return lambda s, r, u: v if type(v := at(s, r)) is str else _plain(v, u)
    if kind == "texts":
        return lambda s, r, u: list(at(s, r))
    if kind == "raw":
        return lambda s, r, u: at(s, r)
    return lambda s, r, u: _plain(at(s, r), u)


def _number(value: Any) -> Any:
    """A float as JSON holds it: NaN as None."""
    return value if value == value else None


def _figures(value: float | None) -> float | None:
    """A number in the compact form: to ``COMPACT_FIGURES`` significant figures, but whole
    where that would make it exactly 1 (a utilisation a hair past its limit must not read
    as at it, nor one a hair short); None (left out) for None or a non-finite number."""
    if value is None or not -INF < value < INF:  # NaN compares false
        return None
    rounded = float(FIGURES % value)
    return value if rounded == 1.0 and value != 1.0 else rounded


def _scaled_figures(value: Any, scale: float) -> Any:
    """An SI number (or a tuple of them) in the API unit, in the compact form."""
    if type(value) is tuple:
        return [_figures(v * scale) for v in value]
    return None if value is None else _figures(value * scale)


def _compact(value: Any) -> Any:
    """A JSON value in the compact form: its numbers to ``COMPACT_FIGURES`` significant
    figures, a dict without its null values (a list keeps each place: None stays)."""
    kind = type(value)
    if kind is float:
        return _figures(value)
    if kind is dict:
        return {
            k: c
            for k, v in value.items()
            if (c := _figures(v) if type(v) is float else _compact(v)) is not None
        }
    if kind is list:
        return [_compact(v) for v in value]
    return value


def _access(path: str | tuple[str, ...]) -> Callable[[Any, Any], Any]:
    """The value at ``path`` (see ``app.contract.source``) of (source, record)."""
    if isinstance(path, tuple):
        together = attrgetter(*path)
        return lambda s, r: _whole(together(s))
    from_record, names = (True, path[1:]) if path.startswith("/") else (False, path)
    if not names:
        return (lambda s, r: r) if from_record else (lambda s, r: s)
    if names.isdigit():
        get: Callable[[Any], Any] = itemgetter(int(names))
    elif all(n.isidentifier() for n in names.split(".")):
        get = attrgetter(names)
    else:
        raise ValueError(f"not an attribute path: {path!r}")
    return (lambda s, r: get(r)) if from_record else (lambda s, r: get(s))


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


def _nullable(annotation: Any) -> bool:
    """Whether a field of this type may be null (is ``X | None``)."""
    return get_origin(annotation) in (UnionType, Union) and type(None) in get_args(annotation)


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
