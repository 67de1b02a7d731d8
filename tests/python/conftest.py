"""pytest set-up of the Python package's suites: where the sources and the driver are.

ctest (tests/python/CMakeLists.txt) sets INTERPHASE_SOURCE_DIR, INTERPHASE_POINT (the driver
interphase-point of the same build), INTERPHASE_LIBRARY (that build's libinterphase.so) and
PYTHONPATH (drivers/python).
"""

import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("INTERPHASE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def point_driver():
    """The interphase-point executable of the build under test."""
    path = os.environ.get("INTERPHASE_POINT")
    if not path or not os.access(path, os.X_OK):
        message = "INTERPHASE_POINT does not name the driver interphase-point (ctest sets it)"
        if os.environ.get("CI") == "true":
            pytest.fail(message)
        pytest.skip(message)
    return path
