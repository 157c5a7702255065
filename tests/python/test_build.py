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
    if os.environ.get("CCDLAB_NATIVE") != "ON":
        # Without -march=native the module links the libraries themselves (CMakeLists.txt):
        # their objects (unity batches or single files) are the module's too.
        assert 0 < len(module) < 60  # the bindings only
        for d in ("ccd", "bounds", "pipeline", "cloth", "generators", "experiments"):
            library = [c for c in commands if pathlib.Path(c["directory"]) == BUILD_DIR / d]
            assert library, d
            module += library
    else:
        assert len(module) > 60  # its own build of the library sources, file by file, and the bindings
    for c in module:
        assert "-march" not in c["command"], c["file"]
        assert "-ffp-contract=off" in c["command"], c["file"]
    if os.environ.get("CCDLAB_NATIVE") == "ON":  # the check sees the flag where it is
        library = [c for c in commands if pathlib.Path(c["directory"]) == BUILD_DIR / "ccd"]
        assert library and all("-march=native" in c["command"] for c in library)


def test_module_is_the_one_of_this_build():
    import ccdlab
    package = (BUILD_DIR / "python" / "ccdlab").resolve()
    assert pathlib.Path(ccdlab.__file__).resolve().parent == package
    assert pathlib.Path(ccdlab._ccdlab.__file__).resolve().parent == package
    # Every .py file of python/ccdlab/ is in the build's package, as it is in the sources.
    sources = pathlib.Path(__file__).resolve().parents[2] / "python" / "ccdlab"
    for py in sources.glob("*.py"):
        assert (package / py.name).read_bytes() == py.read_bytes(), py.name


def test_cmake_install_puts_it_where_python3_finds_it(tmp_path):
    import subprocess
    import sys
    cmake = os.environ.get("CMAKE_COMMAND", "cmake")
    subprocess.run([cmake, "--install", str(BUILD_DIR), "--prefix", str(tmp_path)], check=True, capture_output=True)
    site = tmp_path / f"lib/python{sys.version_info.major}.{sys.version_info.minor}/dist-packages"
    env = dict(os.environ, PYTHONPATH=str(site))
    where = subprocess.run(["/usr/bin/python3", "-c", "import ccdlab; print(ccdlab._ccdlab.__file__); print(len(ccdlab.methods()['methods']))"],
                           env=env, capture_output=True, text=True, check=True, cwd=tmp_path).stdout.split()
    assert pathlib.Path(where[0]).parent == site / "ccdlab" and int(where[1]) > 0
