"""Application factory: load the catalog (fail fast), wire routes and middleware."""

import gc
from functools import partial

from fastapi import FastAPI
from fastapi.exceptions import RequestValidationError
from starlette.exceptions import HTTPException

from app import __version__
from app.api import docs
from app.api import routes as api
from app.catalog import load_catalog
from app.contract.schemas import ApplicationIn
from app.paths import resource_dir
from app.server.cache import ResponseCache
from app.server.compression import NegotiatedGZipMiddleware
from app.server.errors import AppError
from app.server.head import HeadAsGetMiddleware
from app.server.overload import (
    NEVER_SHED,
    OverloadMiddleware,
    StatedCosts,
    full_form_stated_units,
    page_stated_units,
    select_stated_units,
)
from app.server.security import SecurityMiddleware
from app.server.settings import Settings, get_settings
from app.server.staticfiles import PrecompressedStaticFiles
from app.web import catalog_page, custom, guide, machine, pages, report_page, result_parts
from app.web.errors import app_error_handler, http_error_handler, validation_error_handler

#: GET routes whose response depends only on the query (and the catalog, fixed at start-up).
CACHED_PATHS = frozenset(
    {"/", "/detail", "/charts", "/rejected", "/api/v1/select", "/export.csv", "/export.json"}
)
#: GET routes whose response depends on nothing in the request but the path: one entry for
#: any query. "/catalog/*" stands for every path under /catalog/ (each series' page).
QUERY_FREE_PATHS = frozenset({"/catalog", "/catalog/*", "/guide", "/validation"})
#: Cached paths that answer an HTMX swap with a fragment and anything else with a page.
FRAGMENT_PATHS = frozenset({"/", "/detail", "/charts", "/rejected", "/catalog/*"})
#: A page that leaves its limit out states the default one once it fills a required field.
PAGE_STATED_UNITS = partial(
    page_stated_units,
    required=pages.REQUIRED,
    default_limit=ApplicationIn.model_fields["limit"].default,
)
#: What each costly route's query states it costs, read before its input is validated: a
#: flood of them is shed for the price of reading a query (app.server.overload).
STATED_COSTS: StatedCosts = {
    "/": PAGE_STATED_UNITS,
    "/charts": PAGE_STATED_UNITS,
    "/rejected": PAGE_STATED_UNITS,
    "/api/v1/select": select_stated_units,
    "/export.csv": full_form_stated_units,
    "/export.json": full_form_stated_units,
}


def create_app(settings: Settings | None = None) -> FastAPI:
    """Build the app. A broken catalog file raises CatalogError here, before serving."""
    settings = settings or get_settings()
    app = FastAPI(
        title="leadscrew-selector",
        version=__version__,
        description="Select a leadscrew and nut against every published limit. "
        "Lengths in mm, speeds in mm/s, forces in N, torques in N m. "
        "What each check, ranking and provenance kind means: [the guide](/guide).",
        # the built-in pages load from a CDN with inline scripts; /docs is ours (routes/docs)
        docs_url=None,
        redoc_url=None,
    )
    app.state.catalog = load_catalog(settings.catalog_dirs)
    # the pages that depend on nothing but the code and the catalog, rendered once here
    app.state.catalog_html = catalog_page.catalog_html(app.state.catalog)
    guide.guide_html()
    guide.validation_html()
    routers = (api, pages, catalog_page, custom, machine, report_page, result_parts, guide, docs)
    for module in routers:
        app.include_router(module.router)
    app.mount("/static", PrecompressedStaticFiles(directory=resource_dir("static")), name="static")
    app.add_exception_handler(AppError, app_error_handler)
    app.add_exception_handler(RequestValidationError, validation_error_handler)
    app.add_exception_handler(HTTPException, http_error_handler)
    # dynamic responses at level 1: the worker's CPU is the limit, and a select response
    # (126 kB of JSON) compresses to 14 kB instead of 9 kB in half the time of level 6;
    # static files come precompressed at level 9 (app.staticfiles)
    app.add_middleware(NegotiatedGZipMiddleware, minimum_size=500, compresslevel=1)
    # a cache hit costs next to nothing: it is answered outside the overload limit
    app.add_middleware(
        OverloadMiddleware,
        max_in_flight=settings.max_requests_in_flight,
        retry_after_s=settings.overload_retry_after_s,
        exempt_paths=NEVER_SHED,
        stated_costs=STATED_COSTS,
    )
    app.add_middleware(
        ResponseCache,
        paths=CACHED_PATHS,
        fragment_paths=FRAGMENT_PATHS,
        max_bytes=settings.response_cache_bytes,
        max_entries=settings.response_cache_entries,
        query_free_paths=QUERY_FREE_PATHS,
    )
    app.add_middleware(
        SecurityMiddleware,
        max_body_bytes=settings.max_body_bytes,
        max_query_chars=settings.max_query_chars,
        max_query_params=settings.max_query_params,
    )
    # outermost, so that every answer to a HEAD, the refusals above included, has no body
    app.add_middleware(HeadAsGetMiddleware)
    # the catalog and its index (table, variant rows) live as long as the process: keep them out
    # of the cyclic collector's full passes (each took about 30 ms every hundred queries)
    gc.collect()
    gc.freeze()
    return app
