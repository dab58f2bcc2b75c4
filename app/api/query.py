"""A query model read straight from the query string.

FastAPI reads a query model (``Annotated[Model, Query()]``) field by field, looking up
each field's aliases on every request: about 0.4 ms for the select's 35 fields, more
than validating them. ``parse_query`` gathers the same values (every value of a list
field, the last of any other, and the names the model does not know, which it then
refuses) and validates them in one call, with errors located under ``query`` as FastAPI
locates them. ``query_parameters`` gives the OpenAPI parameters FastAPI writes for the
model, so the documentation is unchanged (``tests/api/test_query_path.py`` compares both).
"""

from functools import cache
from typing import Any, TypeVar, get_args, get_origin

from fastapi.exceptions import RequestValidationError
from pydantic import BaseModel, ValidationError
from starlette.datastructures import QueryParams

M = TypeVar("M", bound=BaseModel)


def _is_list(annotation: Any) -> bool:
    """A list field (possibly optional): its query values are every occurrence."""
    if get_origin(annotation) in (list, tuple, set, frozenset):
        return True
    return any(_is_list(a) for a in get_args(annotation) if a is not type(None))


@cache
def _list_fields(model: type[BaseModel]) -> frozenset[str]:
    return frozenset(n for n, f in model.model_fields.items() if _is_list(f.annotation))


def query_values(model: type[BaseModel], params: QueryParams) -> dict[str, Any]:
    """The query string as the model's input: each list field's values (when any), the
    last value of each other name."""
    lists = _list_fields(model)
    values: dict[str, Any] = {}
    for name in params:
        if name in lists:
            values[name] = params.getlist(name)
        else:
            values[name] = params[name]
    return values


def parse_query(model: type[M], params: QueryParams) -> M:
    """``model`` validated from the query string; a 422 naming each field otherwise."""
    try:
        return model.model_validate(query_values(model, params))
    except ValidationError as exc:
        errors = [{**e, "loc": ("query", *e["loc"])} for e in exc.errors()]
        raise RequestValidationError(errors) from None


#: Where the OpenAPI document keeps the models a parameter's schema refers to.
REF_TEMPLATE = "#/components/schemas/{model}"


@cache
def query_parameters(model: type[BaseModel]) -> list[dict[str, Any]]:
    """The OpenAPI parameters FastAPI writes for ``Annotated[model, Query()]``: one per
    field, in the model's order, each with the field's JSON schema (its models referred to
    under components/schemas, a null default left out) and description. Read from the
    model's own JSON schema: a FastAPI app built to write them costs some 0.2 s a model at
    every start (``tests/api/test_query_path.py`` holds both equal)."""
    schema = model.model_json_schema(ref_template=REF_TEMPLATE, mode="validation")
    required = set(schema.get("required", ()))
    parameters = []
    for name, field in model.model_fields.items():
        held = schema["properties"][name]
        parameter = {
            "name": name,
            "in": "query",
            "required": name in required,
            "schema": {k: v for k, v in held.items() if k != "default" or v is not None},
        }
        if field.description:
            parameter["description"] = field.description
        parameters.append(parameter)
    return parameters
