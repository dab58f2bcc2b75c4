"""The Jinja2 environment shared by page routes and error pages."""

from fastapi.templating import Jinja2Templates

from app.paths import resource_dir

templates = Jinja2Templates(directory=str(resource_dir("templates")))
# templates are part of the installed package: no per-render file checks
templates.env.auto_reload = False
