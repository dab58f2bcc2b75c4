"""The type of one application input's declaration (``InputField``), its choices and the
form's groups: what every row of the field table (``app.contract.fields.FIELDS``) says,
and what the edges read of it."""

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, Literal, get_args

from app.contract.units import API_SYSTEM, SWITCHED, UNITS, Quantity, from_api, label

Kind = Literal["number", "whole number", "yes-no", "choice", "text", "list", "curve"]
Default = float | int | bool | str | None

#: form groups, in the order the form shows them; the first is always open.
GROUPS = (
    "Axis",
    "Motion and load",
    "Ends",
    "Nut and environment",
    "Duty and requirements",
    "Motor and move",
    "Safety factors",
    "Results",
)


@dataclass(frozen=True, slots=True)
class Choice:
    """One allowed value of a choice or yes-no field and the text the form shows for it."""

    value: str
    text: str


@dataclass(frozen=True, slots=True)
class InputField:
    """One application input at every edge.

    ``api`` carries the API unit in its name (``speed_mm_s``), the API unit of its
    ``dimension``; from it ``si_factor`` converts a value to the core's unit of the core
    attribute ``core`` (``speed_m_s``) and ``unit`` is the unit's text. ``quantity`` is the
    dimension where a page switch sets its unit, else None. A field without a dimension may
    name a fixed ``unit`` text ('/day'). ``bounds`` (low, high) are inclusive and in the API
    unit. A field with no ``default`` and ``required`` False is optional: leaving it out
    switches its check off. ``needs`` names API fields that must be given whenever this one
    is; ``none_word`` is the word the page accepts for "no value" (lead: "any"). ``options``
    is the core's Literal type of a choice field and ``texts`` the display text of each of
    its values; a yes-no field with ``texts`` for "true" and "false" is shown as a two-way
    choice. A ``drawn`` choice is shown as radio buttons, each with a drawing of its value
    ("fixed-free": left end, right end). A ``text`` field is one id or name (``none_word``
    meaning none); a ``list`` field is several, a list in JSON, a repeated query parameter,
    or comma-separated text on the page and in share links. A ``curve`` field is points
    (x, y): pairs in JSON, ``x:y,x:y`` in query strings and share links, lines of "x y" on
    the page. A ``catalog_only`` field filters or ranks catalog screws and means nothing for a
    screw of the user's own (the /custom page leaves it out). ``retired`` maps a choice's
    value that is no longer offered to the one it now reads as, so that links and calls
    already sent keep working. ``api_help`` replaces ``help`` in the API's description
    where the page's words do not hold there (an empty box, text on lines, a comma list).
    """

    api: str
    page: str
    core: str
    label: str
    help: str
    group: str
    kind: Kind
    required: bool = False
    default: Default = None
    bounds: tuple[float, float] | None = None
    dimension: Quantity | None = None
    unit: str = ""
    options: Any = None
    texts: Mapping[str, str] = field(default_factory=dict)
    needs: tuple[str, ...] = ()
    none_word: str = ""
    drawn: bool = False
    catalog_only: bool = False
    retired: Mapping[str, str] = field(default_factory=dict)
    api_help: str = ""
    si_factor: float = field(init=False, default=1.0)
    quantity: Quantity | None = field(init=False, default=None)

    def __post_init__(self) -> None:
        """Take the unit, the factor to SI and the page's switch from the dimension;
        refuse a number without bounds (they keep every result finite), a unit beside a
        dimension, and display texts that miss or invent a value of the core's Literal."""
        if self.kind in ("number", "whole number") and self.bounds is None:
            raise ValueError(f"{self.api}: a number needs bounds")
        if self.dimension is not None:
            if self.unit:
                raise ValueError(f"{self.api}: the dimension gives the unit")
            api_unit = UNITS[API_SYSTEM[self.dimension]]
            object.__setattr__(self, "unit", api_unit.symbol)
            object.__setattr__(self, "si_factor", api_unit.si)
            switched = self.dimension if self.dimension in SWITCHED else None
            object.__setattr__(self, "quantity", switched)
        if self.options is not None and set(get_args(self.options)) != set(self.texts):
            values = sorted(get_args(self.options))
            raise ValueError(f"{self.api}: texts {sorted(self.texts)} do not match {values}")

    @property
    def choices(self) -> tuple[Choice, ...]:
        """The allowed values with their texts: a Literal's in its order, or the yes-no
        field's 'true' and 'false' when it is shown as a choice; none for other fields."""
        values = get_args(self.options) if self.options is not None else tuple(self.texts)
        return tuple(Choice(value, self.texts[value]) for value in values)

    def to_si(self, value: Any) -> Any:
        """The API value in the core's SI unit: numbers times ``si_factor``; a list as a
        tuple (empty for none); text equal to ``none_word`` as None; others as given.

        >>> from app.contract.fields import BY_API
        >>> BY_API["family"].to_si(["TR-C45", "B"]), BY_API["nut_material"].to_si("any")
        (('TR-C45', 'B'), None)
        >>> BY_API["motor_curve"].to_si([[0, 0.5], [3000, 0.2]])
        ((0.0, 0.5), (3000.0, 0.2))
        """
        if self.kind == "list":
            return tuple(value or ())
        if self.kind == "curve":
            return tuple((float(x), float(y)) for x, y in value or ())
        if self.kind == "text" and self.none_word and value == self.none_word:
            return None
        if self.kind != "number" or value is None:
            return value
        return float(value) * self.si_factor

    def display_unit(self, units: Mapping[str, str]) -> str:
        """Unit text in the user's display units ('in/s'), the fixed unit ('kg'), or ''; a
        curve's torques follow the torque unit ('rpm : oz in')."""
        if self.kind == "curve":
            return f"rpm : {label('torque', dict(units))}"
        if self.quantity is None:
            return self.unit
        return label(self.quantity, dict(units))

    def display_value(self, value: Any, units: Mapping[str, str]) -> Any:
        """An API value in the user's display units; values without a quantity as given."""
        if self.quantity is None or value is None:
            return value
        return from_api(float(value), self.quantity, dict(units))

    def choice_text(self, value: str) -> str:
        """The display text of one of the field's choices (the value itself if unknown)."""
        return next((c.text for c in self.choices if c.value == value), value)
