"""Scenes from numpy arrays: the bodies of a simulation's state, no file (docs/python.md)."""
import numpy as np

from ._ccdlab import InputError, scene_from_json


def _floats(name, values):
    try:
        return np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise InputError(f"scene_from_arrays: {name}: not an array of numbers ({e})") from None


def _rows(name, values, n, width):
    a = _floats(name, values)
    want = (n, width) if width else (n,)
    if a.shape != want:
        raise InputError(f"scene_from_arrays: {name}: must be an array of shape {want} "
                         f"(one entry per body of positions), got {a.shape}")
    return _finite(name, a)


def _finite(name, a):
    bad = np.argwhere(~np.isfinite(a))
    if len(bad):
        where = ", ".join(str(int(i)) for i in bad[0])
        raise InputError(f"scene_from_arrays: {name}[{where}]: not a finite number ({a[tuple(bad[0])]})")
    return a


def _vector(name, values):
    a = _floats(name, values)
    if a.shape != (3,):
        raise InputError(f"scene_from_arrays: {name}: must be 3 numbers, got shape {a.shape}")
    return [float(x) for x in _finite(name, a)]


def scene_from_arrays(positions, velocities, radii, *, horizon, accelerations=None,
                      gravity=None, box=None, boundary=None):
    """A sphere scene (ccdlab-scene/1) from arrays: positions and velocities (n, 3), radii
    (n,), optional accelerations (n, 3), over [0, horizon] s; gravity (3,); box a pair
    (min, max) of 3-vectors for elastic walls, with `boundary` "reflect" (the default) or
    "wrap", or a list of three. Every value is checked as in a scene file (the message names
    the field and the body, e.g. `bodies[3].radius`)."""
    p = _floats("positions", positions)
    if p.ndim != 2 or p.shape[1:] != (3,):
        raise InputError(f"scene_from_arrays: positions: must be an (n, 3) array, got shape {p.shape}")
    n = p.shape[0]
    _finite("positions", p)
    if not np.isfinite(_floats("horizon", horizon)).all() or np.ndim(horizon) != 0:
        raise InputError(f"scene_from_arrays: horizon: not a finite number ({horizon})")
    v = _rows("velocities", velocities, n, 3)
    r = _rows("radii", radii, n, 0)
    a = None if accelerations is None else _rows("accelerations", accelerations, n, 3)
    bodies = []
    for i in range(n):
        body = {"radius": float(r[i]), "position": [float(x) for x in p[i]],
                "velocity": [float(x) for x in v[i]]}
        if a is not None:
            body["acceleration"] = [float(x) for x in a[i]]
        bodies.append(body)
    doc = {"format": "ccdlab-scene/1", "horizon": float(_floats("horizon", horizon)), "bodies": bodies}
    if gravity is not None:
        doc["gravity"] = _vector("gravity", gravity)
    if box is not None:
        if len(box) != 2:
            raise InputError("scene_from_arrays: box: must be a pair (min, max) of 3-vectors")
        doc["box"] = {"min": _vector("box[0]", box[0]), "max": _vector("box[1]", box[1])}
        if boundary is not None:
            doc["box"]["boundary"] = boundary
    elif boundary is not None:
        raise InputError("scene_from_arrays: boundary: needs a box")
    return scene_from_json(doc)
