# Where the tests find the command line and the scenes: CTest sets these (python/CMakeLists.txt).
import os
import pathlib

import pytest

SOURCE = pathlib.Path(os.environ.get("PLASTICA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("PLASTICA_BINARY", str(SOURCE / "build" / "cli" / "plastica"))


@pytest.fixture
def source():
    return SOURCE


@pytest.fixture
def binary():
    return BINARY
