"""Query parameters nothing reads: named, with the likely intended name, never ignored.

A link with a misspelled input (``moving_mass=3`` for ``moving_mass_kg``) would otherwise
give the result without it, and one with a unit no switch offers (``force_unit=lbs``)
would read its numbers in the default unit. The names a page reads come from the
tables: every input's page name (``FIELDS``), the display-unit switches
(``DEFAULT_UNITS``), the units the form's numbers were typed in (``from_<switch>``) and
each field's typed record (``typed_<field>``), the cells of the table of moves and its
buttons (``app.contract.move_table``), plus the route's own (``id``, ``ids``; the custom
screw's fields, without the catalog's filters).

The API reads the API names alone: given a page's name (a share link's ``load`` for
its API name, with the unit), its 422 names the API's (``api_hint``); every response
carries the API query
of its inputs beside the share link (``api_query``).
"""

from collections.abc import Collection, Iterable, Mapping, Sequence
from difflib import get_close_matches
from urllib.parse import parse_qsl

from app.contract.fields import BY_API, BY_PAGE
from app.contract.form import ENTERED_PREFIX, MOVES, TYPED_PREFIX, UNIT_CHOICES, repeated
from app.contract.inputs import ApplicationIn
from app.contract.move_table import ADD_MOVE, REMOVE_MOVE, is_cell
from app.contract.share_link import encode_query, share_query
from app.contract.units import DEFAULT_UNITS

#: Every name a page with the application form reads, whatever the route.
PAGE_NAMES = frozenset(
    [
        *BY_PAGE,
        *DEFAULT_UNITS,
        *(ENTERED_PREFIX + key for key in DEFAULT_UNITS),
        *(TYPED_PREFIX + page for page in BY_PAGE),
        MOVES,
        ADD_MOVE,
        REMOVE_MOVE,
    ]
)


def likely_name(name: str, known: Iterable[str]) -> str | None:
    """The known name closest to ``name`` where one is close (difflib's ratio 0.75 or
    more); an API name given on a page is its page name.

    >>> likely_name("moving_mass", BY_PAGE), likely_name(BY_PAGE["speed"].api, BY_PAGE)
    ('moving_mass_kg', 'speed')
    >>> likely_name("colour", BY_PAGE) is None
    True
    """
    known = list(known)
    if name in BY_API and BY_API[name].page in known:
        return BY_API[name].page
    close = get_close_matches(name, known, n=1, cutoff=0.75)
    return close[0] if close else None


def unknown_message(name: str, known: Iterable[str]) -> str:
    """What the page or API says of a parameter it does not read.

    >>> unknown_message("moving_mass", BY_PAGE)
    "Unknown parameter 'moving_mass' (did you mean 'moving_mass_kg'?): it is not read."
    """
    close = likely_name(name, known)
    hint = f" (did you mean '{close}'?)" if close else ""
    return f"Unknown parameter '{name[:100]}'{hint}: it is not read."


def form_errors(messages: Collection[str]) -> dict[str, str]:
    """A page's errors that are no one field's (a parameter nothing reads), as the form's
    notice shows them under the key 'form'; empty when there are none.

    >>> form_errors(["Unknown parameter 'x': it is not read."]), form_errors([])
    ({'form': "Unknown parameter 'x': it is not read."}, {})
    """
    return {"form": " ".join(messages)} if messages else {}


#: What a page says of an input it does not have (the custom screw's page of a catalog filter).
NOT_HERE = "'{name}' is not read on this page: it chooses among the catalog's screws."


def unknown_parameters(
    params: Mapping[str, str], extra: Collection[str] = (), left_out: Collection[str] = ()
) -> dict[str, str]:
    """Each parameter of ``params`` that no page field or switch reads, nor the route's
    own names ``extra``, and each page name in ``left_out`` (the fields a page does not
    have) -> its message; then each unit switch set to a unit it does not offer
    (``unknown_units``), and each name given more than once where it takes one value
    (``repeated``). Empty when every name and unit is read."""
    known = (PAGE_NAMES - frozenset(left_out)) | frozenset(extra)
    unknown = {
        name: NOT_HERE.format(name=name) if name in left_out else unknown_message(name, known)
        for name in params
        if name not in known and not is_cell(name)
    }
    return repeated(params, extra) | unknown | unknown_units(params)


def unknown_units(params: Mapping[str, str]) -> dict[str, str]:
    """Each display-unit switch, or record of the units the numbers were typed in
    (``from_<switch>``), whose value is none of the switch's units -> its message: the
    numbers would otherwise be read in the default unit.

    >>> unknown_units({"force_unit": "lbs", "from_length_unit": "in", "load": "5"})
    {'force_unit': "Unknown force unit 'lbs': choose N, lbf or kgf."}
    """
    found = {}
    for key, choices in UNIT_CHOICES.items():
        for name in (key, ENTERED_PREFIX + key):
            value = params.get(name, "")
            if value and value not in choices:
                *rest, last = choices
                words = f"{', '.join(rest)} or {last}" if rest else last
                noun = key.removesuffix("_unit").replace("accel", "acceleration")
                found[name] = f"Unknown {noun} unit '{value[:20]}': choose {words}."
    return found


def api_query(inputs: ApplicationIn, share: str | None = None) -> str:
    """The API's query string of ``inputs``: the share link's (required fields and
    non-defaults, each number exact, in the API's units: the page's default units) under
    the API's names, a list as the parameter repeated (as the API's query reads it);
    ``share``: the share link's query in the default units when the caller has it
    already. Tested in ``tests/api/test_api_links.py``."""
    pairs: list[tuple[str, str]] = []
    shared = share_query(inputs) if share is None else share
    for name, value in parse_qsl(shared, keep_blank_values=True):
        if name == MOVES:  # the cycle's text, the same in the API
            pairs.append((name, value))
            continue
        field = BY_PAGE[name]
        items = value.split(",") if field.kind == "list" else [value]
        pairs += [(field.api, item) for item in items]
    return encode_query(pairs)


#: Where the API's routes are.
API_PREFIX = "/api/v1"


def api_url(
    route: str,
    inputs: ApplicationIn,
    extra: Sequence[tuple[str, str]] = (),
    share: str | None = None,
) -> str:
    """The API's GET of ``route`` for ``inputs`` and the route's own ``extra`` names
    (``[("ids", "a,b")]``: ``&ids=a,b``); ``share`` as ``api_query`` takes it."""
    tail = f"&{encode_query(extra)}" if extra else ""
    return f"{API_PREFIX}/{route}?{api_query(inputs, share)}{tail}"


def api_hint(name: str, known: Iterable[str] = BY_API) -> str | None:
    """What the API says of a name it does not read where it knows better: a page's name
    of an input (the field table's) and the API's name of it, a page's unit switch, or
    the API name ``name`` is close to; None for any other.

    >>> api_hint("colour") is None
    True
    >>> api_hint("load").startswith("'load' is the page's name (share links): the API's is")
    True
    """
    field = BY_PAGE.get(name)
    if field is not None and field.api != name:
        unit = f", in {field.unit}" if field.unit else ""
        return page_name_hint(name, field.api, field.label + unit)
    if name in DEFAULT_UNITS or name.startswith((ENTERED_PREFIX, TYPED_PREFIX)):
        return (
            f"'{name[:100]}' is a page's setting: the API reads every number in the unit "
            "its name carries (the api_url of a response is the API's query)"
        )
    return close_hint(name, known)


def page_name_hint(name: str, api: str, label: str) -> str:
    """The hint for a page's name ``name`` of the input the API calls ``api``."""
    return f"'{name}' is the page's name (share links): the API's is '{api}' ({label})"


def close_hint(name: str, known: Iterable[str]) -> str | None:
    """The API name of ``known`` that ``name`` is close to, as a hint; None for none.

    >>> close_hint("outer_diameter", ["outer_diameter_mm", "lead_mm"])
    "'outer_diameter' is not an API name: did you mean 'outer_diameter_mm'?"
    """
    close = get_close_matches(name, list(known), n=1, cutoff=0.75)
    return f"'{name[:100]}' is not an API name: did you mean '{close[0]}'?" if close else None
