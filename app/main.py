"""Application factory: load the catalog (fail fast), wire routes and middleware."""

from fastapi import FastAPI
from fastapi.exceptions import RequestValidationError
from fastapi.staticfiles import StaticFiles
from starlette.middleware.gzip import GZipMiddleware

from app import __version__
from app.catalog import load_catalog
from app.errors import AppError, app_error_handler, validation_error_handler
from app.paths import resource_dir
from app.routes import api, pages
from app.security import SecurityMiddleware
from app.settings import Settings, get_settings


def create_app(settings: Settings | None = None) -> FastAPI:
    """Build the app. A broken catalog file raises CatalogError here, before serving."""
    settings = settings or get_settings()
    app = FastAPI(
        title="leadscrew-selector",
        version=__version__,
        description="Select a leadscrew and nut against every published limit. "
        "Lengths in mm, speeds in mm/s, forces in N, torques in N m.",
    )
    app.state.catalog = load_catalog(settings.catalog_dirs)
    app.include_router(api.router)
    app.include_router(pages.router)
    app.mount("/static", StaticFiles(directory=resource_dir("static")), name="static")
    app.add_exception_handler(AppError, app_error_handler)
    app.add_exception_handler(RequestValidationError, validation_error_handler)
    app.add_middleware(GZipMiddleware, minimum_size=500)
    app.add_middleware(
        SecurityMiddleware,
        max_body_bytes=settings.max_body_bytes,
        max_query_chars=settings.max_query_chars,
        max_query_params=settings.max_query_params,
    )
    return app
