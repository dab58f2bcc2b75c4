"""The compute threads (app.server.compute)."""

import sys

import pytest

from app.server.compute import executor
from app.server.settings import get_settings


def test_the_compute_threads_come_with_a_short_switch_interval() -> None:
    """With compute threads running, the event loop waits for the interpreter after each
    socket call up to the switch interval: 0.5 ms, not Python's 5 ms (issue 31: the
    health check waited over a second behind a flood of 503s)."""
    executor()
    assert sys.getswitchinterval() == pytest.approx(get_settings().thread_switch_interval_s)
    assert sys.getswitchinterval() < 0.005
