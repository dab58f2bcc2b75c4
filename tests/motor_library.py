"""The built-in motor library, read once for the tests that turn inputs into the core's
application (``ApplicationIn.to_core(MOTORS)``)."""

from app.catalog.motors import MOTOR_FILE, load_motors
from app.paths import resource_dir

MOTORS = load_motors(resource_dir("catalog") / MOTOR_FILE)
