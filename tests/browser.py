"""The mark of tests that run Origami Simulator's page in Chromium."""

import pytest

from kresling.testing.origami_simulator_page import CHROMIUM

needs_browser = pytest.mark.skipif(CHROMIUM is None,
                                   reason="no chromium (make test installs Debian's package)")
