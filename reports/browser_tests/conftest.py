"""One headless Chromium for all the browser tests: starting it and loading the viewer's scripts
the first time take about 4 s, which each of the tests paid when it started its own. Each test
gets the browser reset (check_viewer.reset: first window size, a blank page, no earlier console
messages), so no test sees what the one before it left."""
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import check_viewer  # noqa: E402


@pytest.fixture(scope="session")
def chromium():
    browser = check_viewer.browser()
    yield browser
    browser.quit()


@pytest.fixture()
def driver(chromium):
    check_viewer.reset(chromium)
    return chromium
