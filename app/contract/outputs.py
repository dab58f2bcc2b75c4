"""The API's response models besides the candidate: the selection (counts, summary,
remedies), compare, evaluate, formulas, catalog series, checks, health and errors.
"""

from types import GenericAlias
from typing import Any, Literal, cast

from pydantic import (
    BaseModel,
    Field,
    ValidationInfo,
    create_model,
    field_validator,
)

from app.catalog.axis_motor import CurveOrigin
from app.contract.inputs import ApplicationIn
from app.contract.schemas import CandidateOut, CandidateSummaryOut, RejectedSummaryOut
from app.contract.sections import ProvenanceOut

#: What every response's two links are.
SHARE_URL = "The page of the same inputs (the share link, the page's names)."
API_URL = (
    "The API's GET of the same query (the API's names and units): share_url's inputs "
    "as this API reads them."
)

#: What every response that runs the checks says of its motor curve.
MOTOR_CURVE_ORIGIN = (
    "Where the torque-speed curve the motor-curve check reads comes from: entered (the "
    "curve typed in), published (the library motor's maker's published curve, at the "
    "drive of its chart), model (drawn from datasheet values by the stepper or servo "
    "model: an estimate, to confirm on the maker's curve); null: no curve, so no curve "
    "check runs."
)


def _curve_origin_field() -> Any:
    """The ``motor_curve_origin`` field of a response (``ApplicationIn.to_core_traced``):
    a field of its own for each model that carries it."""
    return Field(None, description=MOTOR_CURVE_ORIGIN)


class CountsOut(BaseModel):
    evaluated: int
    passed: int
    rejected: int
    failed_by_check: dict[str, int]


class ChangeOut(BaseModel):
    inputs: dict[str, float] = Field(
        description="API input -> the value at which the screw's failed limits are reached "
        "exactly: it admits the screw with no margin (the remedies keep 5 %)."
    )
    admits: str = Field(description="The candidate the change admits.")


class RemedyOut(BaseModel):
    inputs: dict[str, float | str] = Field(
        description="API input -> value (end_fixity: its choice), 5 % past each limit."
    )
    passing: int = Field(description="Candidates that pass with the change made.")
    utilization: float = Field(
        description="The lowest governing utilization among them: at most 1 / 1.05."
    )


class SummaryOut(BaseModel):
    message: str
    most_excluding_check: str | None
    best_rejected_id: str | None
    input_change: dict[str, float] = Field(
        description="The inputs at which the nearest candidate's failed checks reach "
        "their limits exactly; remedies apply a margin."
    )
    changes: list[ChangeOut] = Field(
        description="Feasible input changes, each admitting a near candidate at its limits "
        "exactly (no margin: the remedies keep one)."
    )
    remedies: list[RemedyOut] = Field(
        default_factory=list,
        description="When nothing passes: changes (one input or several, or the mounting) "
        "each verified by selecting again with it made, a candidate then passing with a "
        "5 % margin on its governing check.",
    )
    impossible: str | None = Field(
        default=None,
        description="When nothing passes and no remedy is found: why no screw can do it.",
    )


class FormulaOut(BaseModel):
    formula: str
    function: str
    source: str


class SelectionBaseOut(BaseModel):
    """What every form of a selection gives besides its candidates."""

    inputs: ApplicationIn
    counts: CountsOut
    summary: SummaryOut
    catalog_version: str
    motor_curve_origin: CurveOrigin | None = _curve_origin_field()
    share_url: str = Field(description=SHARE_URL)
    api_url: str = Field(description=API_URL)


class SelectOut(SelectionBaseOut):
    candidates: list[CandidateOut]
    rejected: list[CandidateOut]
    formulas: dict[str, FormulaOut] = Field(
        description="Quantity (dotted path in a candidate) -> formula, core function, source."
    )


class PageSelectionOut(SelectionBaseOut):
    """The results page's selection: the passing candidates as table rows (the ``row``
    view); the rejected in full only when nothing passes (the charts and the advice are
    then about them)."""

    candidates: list[CandidateOut]
    rejected: list[CandidateOut]


class FormulasOut(BaseModel):
    formulas: dict[str, FormulaOut] = Field(
        description="Quantity (dotted path in a candidate) -> formula, core function, source."
    )


class SelectQuery(ApplicationIn):
    """The GET select's query: the application's fields and the response's form."""

    detail: Literal["summary", "full"] = Field(
        "summary",
        description="summary (default): passing candidates as the results table shows "
        "them, rejected ones as their failed checks with utilization and fix, formulas at "
        "/api/v1/formulas (SelectSummaryOut); full: every number, check message, formula "
        "and provenance of every candidate, and the formulas table (SelectOut). The "
        "compact form gives numbers to 6 significant figures and leaves out values not "
        "worked out for this query; detail=full gives every field at full precision.",
    )

    @field_validator("*")
    @classmethod
    def _needs(cls, value: Any, info: ValidationInfo) -> Any:
        """The application's fields as ``ApplicationIn`` checks them; ``detail`` as it is."""
        if info.field_name == "detail":
            return value
        return super()._needs(value, info)

    def application(self) -> ApplicationIn:
        """The application's fields alone, as the body of a POST would give them."""
        values = {name: getattr(self, name) for name in ApplicationIn.model_fields}
        return ApplicationIn.model_construct(self.model_fields_set - {"detail"}, **values)


class EvaluateQuery(ApplicationIn):
    """The GET evaluate's query: the application's fields and one catalog screw's id."""

    catalog_id: str = Field(
        pattern=r"^[A-Za-z0-9][A-Za-z0-9 ._()+/-]{0,59}$",
        description="The catalog screw to evaluate (GET /api/v1/series lists them).",
    )

    @field_validator("*")
    @classmethod
    def _needs(cls, value: Any, info: ValidationInfo) -> Any:
        """The application's fields as ``ApplicationIn`` checks them; the id as it is."""
        if info.field_name == "catalog_id":
            return value
        return super()._needs(value, info)

    def application(self) -> ApplicationIn:
        """The application's fields alone, as the body of a POST would give them."""
        values = {name: getattr(self, name) for name in ApplicationIn.model_fields}
        return ApplicationIn.model_construct(self.model_fields_set - {"catalog_id"}, **values)


#: The compact select's ``detail``.
SummaryDetail = Literal["summary"]
#: The default select response (``detail=full`` gives ``SelectOut``): the passing
#: candidates in the ``summary`` view, the rejected in the ``rejected`` view.
SelectSummaryOut = create_model(
    "SelectSummaryOut",
    __doc__="The default select response, the compact form: its candidates give numbers to "
    "6 significant figures and leave out values not worked out for this query; "
    "``detail=full`` gives ``SelectOut``, every field at full precision.",
    detail=(SummaryDetail, ...),
    inputs=(
        dict[str, Any],
        Field(
            description="The inputs (ApplicationIn's fields) that differ from their "
            "defaults; every other input is at its default (the full form echoes them all)."
        ),
    ),
    candidates=(cast(Any, GenericAlias(list, (CandidateSummaryOut,))), ...),
    rejected=(cast(Any, GenericAlias(list, (RejectedSummaryOut,))), ...),
    labels=(
        dict[str, str],
        Field(
            description="Catalog key -> the value in words, once for every key a "
            "candidate's verdict rests on (``verdict.rests_on``)."
        ),
    ),
    counts=(CountsOut, ...),
    summary=(SummaryOut, ...),
    catalog_version=(str, ...),
    motor_curve_origin=(CurveOrigin | None, _curve_origin_field()),
    share_url=(str, Field(description=SHARE_URL)),
    api_url=(str, Field(description=API_URL)),
    formulas_url=(
        str,
        Field(description="The formulas table (GET), the same for every query."),
    ),
)


class CompareOut(BaseModel):
    """2 to 4 catalog screws side by side for one application, each in full."""

    inputs: ApplicationIn
    candidates: list[CandidateOut]
    catalog_version: str
    motor_curve_origin: CurveOrigin | None = _curve_origin_field()
    share_url: str = Field(description="The compare page of the same inputs and ids.")
    api_url: str = Field(description=API_URL)


class EvaluateOut(BaseModel):
    inputs: ApplicationIn
    candidate: CandidateOut
    catalog_version: str
    motor_curve_origin: CurveOrigin | None = _curve_origin_field()
    formulas: dict[str, FormulaOut]
    share_url: str | None = Field(
        description="A catalog screw's report page for the same inputs; a custom screw's "
        "page of one's own screw with its geometry and the same inputs."
    )
    api_url: str | None = Field(
        description="The API's GET of the same query, a catalog screw's (none for a custom screw)."
    )


class SourcedOut(BaseModel):
    value: Any
    unit: str
    provenance: ProvenanceOut


class SeriesOut(BaseModel):
    id: str
    name: str
    family: str
    family_name: str
    type: str
    file: str
    fields: dict[str, SourcedOut]
    candidate_ids: list[str]


class SeriesListOut(BaseModel):
    catalog_version: str
    series: list[SeriesOut]


class CheckInfoOut(BaseModel):
    name: str
    label: str
    kind: Literal["limit", "advice"]
    description: str
    formula: str = Field(description="demand = ...; capacity = ... (or: passes when ...).")
    source: str
    sources: list[str] = Field(description="Catalog fields the check reads.")
    unit: str = Field(description="API unit of the check's value and limit.")


class ChecksOut(BaseModel):
    checks: list[CheckInfoOut]


class HealthOut(BaseModel):
    status: Literal["ok"]
    version: str
    catalog_version: str
    candidates: int


class ErrorDetail(BaseModel):
    field: str
    message: str


class ErrorOut(BaseModel):
    error: str
    detail: list[ErrorDetail]


class CitedNoteOut(BaseModel):
    """A sentence about a kind of screw and the page it rests on."""

    topic: Literal["noise", "backlash"]
    text: str
    source: str = Field(description="The cited page: maker or publication, title, URL.")


class VersusSideOut(BaseModel):
    """One kind of screw's best candidate for the application, or its nearest rejected."""

    screw_type: Literal["lead", "ball"]
    passed: bool = Field(description="A screw of this kind passes every check.")
    candidate: CandidateOut | None = Field(
        description="The kind's first-ranked passing screw, else its nearest rejected one "
        "(lowest worst utilization); null when the catalog offers none of this kind for "
        "the query's families."
    )
    excluded_by: list[str] = Field(
        description="When none passes: the checks the shown screw fails, by label."
    )
    notes: list[CitedNoteOut] = Field(description="Cited notes on this kind's noise and play.")


class VersusOut(BaseModel):
    """The best leadscrew against the best ball screw for one application."""

    inputs: ApplicationIn
    sides: list[VersusSideOut] = Field(description="The leadscrew side, then the ball screw's.")
    price_note: str = Field(description="Why no price band is shown.")
    catalog_version: str
    share_url: str = Field(description="The versus page of the same inputs.")
    api_url: str = Field(description=API_URL)
