# The module's build: no -march=native in any of its objects (it may be imported on another
# CPU), the same -ffp-contract=off as the command line; read from compile_commands.json.
import json
import os
import pathlib

import pytest

BUILD_DIR = pathlib.Path(os.environ.get("CCDLAB_BUILD_DIR", pathlib.Path(__file__).resolve().parents[2] / "build"))


@pytest.fixture(scope="module")
def commands():
    path = BUILD_DIR / "compile_commands.json"
    return json.loads(path.read_text())


def test_module_objects_have_no_march_native(commands):
    module = [c for c in commands if pathlib.Path(c["directory"]) == BUILD_DIR / "python"]
    assert len(module) > 60  # the library sources and the bindings
    for c in module:
        assert "-march" not in c["command"], c["file"]
        assert "-ffp-contract=off" in c["command"], c["file"]
    if os.environ.get("CCDLAB_NATIVE") == "ON":  # the check sees the flag where it is
        library = [c for c in commands if pathlib.Path(c["directory"]) == BUILD_DIR / "ccd"]
        assert library and all("-march=native" in c["command"] for c in library)


def test_module_is_the_one_of_this_build():
    import ccdlab
    assert pathlib.Path(ccdlab.__file__).resolve().parent == (BUILD_DIR / "python").resolve()
