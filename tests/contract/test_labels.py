"""Every label a form shows is unique (issue 34, item 5): two fields or two options of
one field with the same text cannot be told apart by the engineer or by a screen reader."""

from collections import Counter

from app.contract.fields import FIELDS
from app.contract.screws import NUT_LABEL
from app.web.screw_form import MATERIAL_FIELDS, MATERIAL_LABEL, SCREW_FIELDS


def _repeated(labels: list[str]) -> list[str]:
    return [label for label, n in Counter(label.casefold() for label in labels).items() if n > 1]


def test_every_field_label_is_unique() -> None:
    labels = [f.label for f in FIELDS]
    assert len(labels) == len(FIELDS) > 40
    assert _repeated(labels) == []


def test_every_option_of_a_field_has_its_own_text() -> None:
    for f in FIELDS:
        texts = [choice.text for choice in f.choices]
        assert _repeated(texts) == [], f.page
    # and no option repeats another field's option text in the same form group
    by_group: dict[str, list[str]] = {}
    for f in FIELDS:
        by_group.setdefault(f.group, []).extend(c.text for c in f.choices if f.kind == "choice")
    for group, texts in by_group.items():
        assert _repeated(texts) == [], group


def test_the_custom_pages_labels_are_unique() -> None:
    """/custom shows the screw's fields beside the application's (not the catalog's
    filters)."""
    labels = [f.label for f in (*SCREW_FIELDS, *MATERIAL_FIELDS)]
    labels += [MATERIAL_LABEL, NUT_LABEL]
    labels += [f.label for f in FIELDS if not f.catalog_only]
    assert _repeated(labels) == []
