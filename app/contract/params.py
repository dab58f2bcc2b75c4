"""Query parameters nothing reads: named, with the likely intended name, never ignored.

A link with a misspelled input (``moving_mass=3`` for ``moving_mass_kg``) would otherwise
give the result without it. The names a page reads come from the tables: every input's
page name (``FIELDS``), the display-unit switches (``DEFAULT_UNITS``), the units the
form's numbers were typed in (``from_<switch>``) and each field's typed record
(``typed_<field>``), the cells of the table of moves and its buttons
(``app.contract.move_table``), plus the route's own (``id``, ``ids``).
"""

from collections.abc import Collection, Iterable, Mapping
from difflib import get_close_matches

from app.contract.fields import BY_API, BY_PAGE
from app.contract.form import ENTERED_PREFIX, MOVES, TYPED_PREFIX
from app.contract.move_table import ADD_MOVE, REMOVE_MOVE, is_cell
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


def unknown_parameters(params: Mapping[str, str], extra: Collection[str] = ()) -> dict[str, str]:
    """Each parameter of ``params`` that no page field or switch reads, nor the route's
    own names ``extra`` -> its message (empty when every name is read)."""
    known = PAGE_NAMES | frozenset(extra)
    return {
        name: unknown_message(name, known)
        for name in params
        if name not in known and not is_cell(name)
    }
