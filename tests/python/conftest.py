# Shared fixtures of the Python tests. CTest runs each test_*.py file with PYTHONPATH set
# to the build's python/ folder and CCDLAB_BINARY / CCDLAB_SOURCE_DIR naming the command
# and the source tree (tests/CMakeLists.txt).
import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("CCDLAB_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("CCDLAB_BINARY", str(SOURCE_DIR / "build" / "ccdlab"))


@pytest.fixture
def source_dir():
    return SOURCE_DIR


def ccdlab_cli(*args, check=True):
    """Runs the ccdlab command; returns the CompletedProcess."""
    return subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True, check=check)


@pytest.fixture
def cli():
    return ccdlab_cli


def write_json(path, document):
    path.write_text(json.dumps(document))
    return path
