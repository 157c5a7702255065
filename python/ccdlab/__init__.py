"""ccdlab: continuous collision detection research toolkit (docs/python.md).

Scenes of spheres and rigid bodies with static scenery, their certified ground truth, the
bounds and broad phases over numpy arrays, whole experiments that count what each method
misses, and mesh CCD between two frames. The compiled part is `ccdlab._ccdlab`; everything
is re-exported here.
"""
from . import _ccdlab
from ._ccdlab import *  # noqa: F401,F403  (the compiled module's names)
from ._ccdlab import __version__  # noqa: F401

# The compiled classes and functions say they are ccdlab's (repr, help, pickling names),
# not the private module's.
for _name in dir(_ccdlab):
    _obj = getattr(_ccdlab, _name)
    if not _name.startswith("_") and getattr(_obj, "__module__", None) == "ccdlab._ccdlab":
        try:
            _obj.__module__ = "ccdlab"
        except (AttributeError, TypeError):  # builtin functions keep theirs
            pass
del _name, _obj

from .arrays import scene_from_arrays  # noqa: E402
from .progress import with_progress as _with_progress  # noqa: E402
from .results import Results, missed  # noqa: E402


def run(experiment, *, progress=None, **kwargs):
    return Results(_with_progress(_ccdlab.run, progress, "ccdlab run", experiment, **kwargs))


run.__doc__ = (_ccdlab.run.__doc__ or "") + (
    "\n\nReturns a ccdlab.Results (a dict with helpers). progress=True draws a bar (tqdm's when "
    "tqdm is installed, else a line on stderr).")


def truth(scene, threads=0, progress=None):
    return _with_progress(_ccdlab.truth, progress, "ccdlab truth", scene, threads=threads)


truth.__doc__ = (_ccdlab.truth.__doc__ or "") + (
    "\n\nprogress=True draws a bar (tqdm's when tqdm is installed, else a line on stderr).")


def __getattr__(name):
    # ccdlab.plot (charts as matplotlib Figures) is imported on first use: matplotlib is
    # needed by it alone.
    if name == "plot":
        import importlib
        return importlib.import_module(".plot", __name__)
    raise AttributeError(f"module 'ccdlab' has no attribute {name!r}")
