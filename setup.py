"""Builds the `ccdlab` package (python/ccdlab/ and its compiled `ccdlab._ccdlab`) with the project's CMake, for the interpreter running
this script (pyproject.toml; docs/python.md, "Installing").

Environment:
  CCDLAB_BUILD_DIR  an existing CMake build folder to build the module in (quick when it is up
                    to date; it must have been configured for this interpreter's version);
                    default: build/python-<interpreter tag> in the source tree, configured here
                    portable (-DCCDLAB_NATIVE=OFF), without tests and benchmarks.
  CCDLAB_JOBS       parallel compile jobs (default: the number of cores).
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(ccdlab VERSION ([0-9.]+)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: project(ccdlab VERSION ...) not found")
    return match.group(1)


class CMakeBuild(build_ext):
    """build_ext that runs CMake's `ccdlab_python` target and copies the module it makes."""

    def build_extension(self, ext):
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        given = os.environ.get("CCDLAB_BUILD_DIR")
        tag = f"{sys.implementation.cache_tag}-{sysconfig.get_platform()}"
        build = pathlib.Path(given) if given else ROOT / "build" / f"python-{tag}"
        jobs = os.environ.get("CCDLAB_JOBS", str(os.cpu_count() or 1))
        if not (given and (build / "CMakeCache.txt").exists()):
            configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                         "-DCCDLAB_NATIVE=OFF", "-DBUILD_TESTING=OFF", "-DCCDLAB_BENCHMARKS=OFF",
                         "-DCCDLAB_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"]
            self.announce("ccdlab: " + " ".join(configure), level=2)
            subprocess.run(configure, check=True)
        print(f"ccdlab: building the module in {build} ({jobs} jobs; a fresh build takes minutes)",
              flush=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "ccdlab_python", "-j", jobs],
                       check=True)
        built = build / "python" / "ccdlab" / f"_ccdlab{suffix}"
        if not built.exists():
            found = sorted(p.name for p in (build / "python" / "ccdlab").glob("_ccdlab*.so"))
            raise RuntimeError(f"{built} not found (the build folder has {found}): "
                               f"was {build} configured for another Python than {sys.executable}?")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=project_version(),
    packages=["ccdlab"],
    package_dir={"": "python"},
    ext_modules=[Extension("ccdlab._ccdlab", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
