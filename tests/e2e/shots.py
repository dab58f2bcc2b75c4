"""Screenshots for a person to look at, under test-artifacts/.

They assert nothing, and taking them (a full page is encoded to PNG in software) cost
about a sixth of the browser tests' CPU, so they are taken when the run asks for them:
``SCREENSHOTS=1 python3 -m pytest tests/e2e``. A screenshot that shows a failure (the
accessibility scan's) is taken whatever the setting.
"""

import os
from pathlib import Path
from typing import Any

#: whether this run takes the screenshots (``SCREENSHOTS=1``)
WANTED = os.environ.get("SCREENSHOTS", "") not in ("", "0")


def shoot(target: Any, path: Path, full_page: bool = False) -> None:
    """A screenshot of ``target`` (a Playwright page, or a locator) to ``path`` when the
    run takes screenshots (``WANTED``); ``full_page`` for a page's whole height."""
    if not WANTED:
        return
    if full_page:
        target.screenshot(path=str(path), full_page=True)
    else:
        target.screenshot(path=str(path))
