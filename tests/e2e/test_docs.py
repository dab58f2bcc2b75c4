"""/docs in real Chromium: Swagger UI from our static files runs under our CSP."""

from typing import Any


def test_docs_renders_every_operation_and_runs_one(page: Any, live_server: str) -> None:
    problems: list[str] = []
    page.on("console", lambda m: m.type == "error" and problems.append(m.text))
    page.on("pageerror", lambda e: problems.append(str(e)))
    page.on(
        "response",
        lambda r: r.status >= 400 and not r.url.endswith("/favicon.ico") and problems.append(r.url),
    )
    offsite: list[str] = []
    page.on("request", lambda r: not r.url.startswith(live_server) and offsite.append(r.url))
    page.goto(live_server + "/docs")
    page.wait_for_selector(".opblock")
    assert page.locator(".opblock").count() >= 6
    page.click("#operations-api-health_api_v1_health_get .opblock-summary")
    page.click("#operations-api-health_api_v1_health_get .try-out__btn")
    page.click("#operations-api-health_api_v1_health_get .execute")
    page.wait_for_selector("#operations-api-health_api_v1_health_get .live-responses-table")
    assert '"status": "ok"' in page.inner_text(
        "#operations-api-health_api_v1_health_get .live-responses-table"
    )
    assert offsite == []
    # a favicon 404 shows as a console error without a URL; anything else is a problem
    assert [p for p in problems if "404" not in p] == [], problems
