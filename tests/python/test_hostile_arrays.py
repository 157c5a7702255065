# Hostile arrays at every entry point of the ccdlab module that takes arrays or scene dicts:
# numpy arrays of every dtype (bool, signed and unsigned integers, float16 to float64,
# complex, datetime, timedelta, strings, bytes, objects), in C, Fortran, strided and reversed
# order, read-only, of every rank and of zero length, holding NaN and infinity, given as
# arguments and inside scene, generator and experiment dicts. Each call either gives the
# answer a plain float64 (or uint32) copy of the input gives, or raises a ValueError or
# TypeError whose message names the argument; a crash ends the test run. Hypothesis draws the
# inputs (fixed example counts, no deadline: about 15 s in all).
import json
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import ccdlab

# database=None: nothing is written into the source tree (CTest runs the tests from it).
SETTINGS = settings(max_examples=120, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])

DTYPES = st.one_of(
    hnp.boolean_dtypes(),
    hnp.integer_dtypes(),
    hnp.unsigned_integer_dtypes(),
    hnp.floating_dtypes(),
    hnp.complex_number_dtypes(),
    hnp.datetime64_dtypes(),
    hnp.timedelta64_dtypes(),
    hnp.unicode_string_dtypes(max_len=4),
    hnp.byte_string_dtypes(max_len=4),
    st.just(np.dtype(object)),
)
OBJECTS = st.one_of(st.none(), st.floats(), st.integers(-(2**70), 2**70), st.text(max_size=3), st.booleans())
ANY_SHAPE = hnp.array_shapes(min_dims=0, max_dims=4, min_side=0, max_side=4)


@st.composite
def hostile_arrays(draw, shapes=ANY_SHAPE, values=None):
    """An array of a drawn dtype and shape, in a drawn memory layout. values: a strategy for
    its elements (cast to the dtype, unsafely, as numpy does; float64 where numpy cannot),
    instead of any value of the dtype."""
    dtype, shape = draw(DTYPES), draw(shapes)
    count = int(np.prod(shape))
    if values is not None:
        plain = np.array(draw(st.lists(values, min_size=count, max_size=count)), dtype=np.float64).reshape(shape)
        array = as_type(plain, dtype)
        array = plain if array is None else array
    elif dtype == np.dtype(object):
        array = np.empty(shape, dtype=object)
        for i, v in enumerate(draw(st.lists(OBJECTS, min_size=count, max_size=count))):
            array.flat[i] = v
    else:
        array = draw(hnp.arrays(dtype, shape))
    layout = draw(st.sampled_from(["C", "F", "strided", "reversed", "read-only"]))
    if layout == "F":
        array = np.asfortranarray(array)
    elif layout == "strided" and array.ndim > 0:
        array = np.repeat(array, 2, axis=0)[::2]  # the same values, every other row of a larger array
    elif layout == "reversed" and array.ndim > 0:
        array = np.ascontiguousarray(array[::-1])[::-1]  # the same values, negative strides
    elif layout == "read-only":
        array.setflags(write=False)
    return array


def as_type(array, dtype):
    """The array as numpy casts it unsafely (what the module's forcecast sees), or None."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            return np.asarray(array).astype(dtype)
        except (TypeError, ValueError, OverflowError):
            return None


def refused(error, argument):
    """A refusal must be a ValueError or TypeError naming the argument."""
    assert isinstance(error, (ValueError, TypeError)), repr(error)
    assert argument in str(error), f"{argument!r} not named in {error!r}"


def call(function, *args, **kwargs):
    """function(...) or the ValueError / TypeError it raised (any other exception fails)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            return function(*args, **kwargs), None
        except (ValueError, TypeError) as error:
            return None, error


def reference_pairs(boxes):
    lo, hi = boxes[:, 0, :], boxes[:, 1, :]
    overlap = np.all((lo[:, None, :] <= hi[None, :, :]) & (lo[None, :, :] <= hi[:, None, :]), axis=2)
    a, b = np.nonzero(np.triu(overlap, k=1))
    return sorted(zip(a.tolist(), b.tolist()))


SCENE = {
    "format": "ccdlab-scene/1",
    "horizon": 1.0,
    "bodies": [
        {"radius": 0.5, "position": [0, 0, 0], "velocity": [1, 0, 0]},
        {"radius": 0.5, "position": [2, 0, 0], "velocity": [-1, 0, 0]},
        {"radius": 0.25, "position": [0, 3, 0]},
        {"radius": 0.25, "position": [0, 3, 0.4], "acceleration": [0, 0, -1]},
    ],
}
BOX_SHAPES = st.one_of(
    ANY_SHAPE,
    st.tuples(st.integers(0, 5), st.just(2), st.just(3)),
    st.tuples(st.integers(0, 5), st.just(6)),
    st.tuples(st.integers(0, 5), st.just(3), st.just(2)),
)


@SETTINGS
@given(boxes=hostile_arrays(BOX_SHAPES), name=st.sampled_from([p["name"] for p in ccdlab.methods()["broad_phases"]]))
def test_broad_phase_boxes(boxes, name):
    pairs, error = call(ccdlab.BroadPhase(name).find_pairs, boxes)
    if error is not None:
        refused(error, "boxes")
        return
    plain = as_type(boxes, np.float64)
    assert plain is not None and plain.ndim in (2, 3) and plain.size % 6 == 0
    plain = plain.reshape(-1, 2, 3)
    assert np.all(np.isfinite(plain)) and np.all(plain[:, 0, :] <= plain[:, 1, :])
    assert pairs.dtype == np.uint32 and pairs.shape == (len(pairs), 2)
    assert sorted(map(tuple, pairs.tolist())) == reference_pairs(plain)


PAIR_SHAPES = st.one_of(ANY_SHAPE, st.tuples(st.integers(0, 5), st.just(2)))


@SETTINGS
@given(pairs=hostile_arrays(PAIR_SHAPES), t0=st.one_of(st.floats(), hostile_arrays(hnp.array_shapes(min_dims=0, max_dims=1, max_side=2))))
def test_bound_prepare_and_pairs(pairs, t0):
    scene = ccdlab.scene_from_json(SCENE)
    bound = ccdlab.Bound("aabb")
    boxes, error = call(bound.prepare, scene, t0, 1.0)
    if error is not None:
        refused(error, "t0")
    else:
        assert boxes.shape == (4, 2, 3) and np.all(np.isfinite(boxes))
        assert 0.0 <= float(np.asarray(t0, dtype=np.float64)) <= scene.horizon
    bound.prepare(scene, 0.0, 1.0)
    result, error = call(bound.test_pairs, pairs)
    if error is not None:
        refused(error, "pairs")
        return
    plain = as_type(pairs, np.uint32)
    assert plain is not None and plain.ndim == 2 and plain.shape[1] == 2
    assert np.all(plain < 4) and np.all(plain[:, 0] != plain[:, 1])
    possible, earliest = result
    assert possible.shape == earliest.shape == (len(plain),)


@SETTINGS
@given(times=hostile_arrays())
def test_scene_positions(times):
    scene = ccdlab.scene_from_json(SCENE)
    positions, error = call(scene.positions, times)
    if error is not None:
        refused(error, "times")
        return
    plain = as_type(times, np.float64)
    assert plain is not None and plain.ndim >= 1
    if len(plain) == 0:  # an empty sequence, whatever its inner shape
        assert positions.shape == (0, 4, 3)
        return
    assert plain.ndim == 1 and np.all((0.0 <= plain) & (plain <= scene.horizon))
    assert positions.shape == (len(plain), 4, 3) and np.all(np.isfinite(positions))


FIELDS = [("horizon", None), ("position", 0), ("velocity", 1), ("acceleration", 3), ("radius", 2)]


@SETTINGS
@given(value=hostile_arrays(hnp.array_shapes(min_dims=0, max_dims=2, min_side=0, max_side=4)), field=st.sampled_from(FIELDS))
def test_scene_dict_holding_arrays(value, field):
    key, body = field
    scene = json.loads(json.dumps(SCENE))
    (scene if body is None else scene["bodies"][body])[key] = value
    loaded, error = call(ccdlab.scene_from_json, scene)
    if error is not None:
        refused(error, "scene")
        return
    # Accepted: the array's plain values are a valid field value.
    plain = value.tolist()
    expected = 3 if key in ("position", "velocity", "acceleration") else None
    if expected:
        assert isinstance(plain, list) and len(plain) == expected
    else:
        assert isinstance(plain, (int, float)) and not isinstance(plain, bool) and plain > 0


# Counts and seeds at and beyond the accepted ranges (1e9 bodies is over kMaxBodies = 1e8).
COUNTS = st.sampled_from([0, 1, 3, 8, -1, 2.5, float("nan"), float("inf"), 1e9, 1e30, 2.0**64])
SMALL_SHAPES = hnp.array_shapes(min_dims=0, max_dims=1, min_side=0, max_side=2)


@settings(max_examples=60, deadline=None, database=None)
@given(bodies=hostile_arrays(SMALL_SHAPES, COUNTS), seed=hostile_arrays(SMALL_SHAPES, COUNTS))
def test_generator_parameters_as_arrays(bodies, seed):
    scene, error = call(ccdlab.generate, "gas", bodies=bodies, seed=seed)
    if error is not None:
        refused(error, "generate")
        return
    # A generator parameter is one number, or an array holding one.
    assert bodies.size == 1 and len(scene) == int(bodies.reshape(-1)[0])


# Steps at and beyond the accepted ranges (dt = 1e-30 is over the work limit).
STEPS = st.sampled_from([0.1, 0.25, 0.5, 2.0, 0.0, -0.1, float("nan"), float("inf"), 1e-30, 1e300])


@settings(max_examples=25, deadline=None, database=None)
@given(dt=hostile_arrays(hnp.array_shapes(min_dims=0, max_dims=2, min_side=0, max_side=3), STEPS))
def test_experiment_dict_holding_arrays(dt, tmp_path_factory):
    scene = tmp_path_factory.mktemp("scene") / "scene.json"
    scene.write_text(json.dumps(SCENE))
    experiment = {"format": "ccdlab-experiment/1", "name": "hostile", "scene": str(scene), "dt": dt,
                  "methods": ["aabb/sap"]}
    results, error = call(ccdlab.run, experiment, threads=1)
    if error is not None:
        refused(error, "experiment")
        return
    assert results["format"] == "ccdlab-results/2"
    assert all(r["events"] == results["records"][0]["events"] for r in results["records"])


@SETTINGS
@given(value=hostile_arrays())
def test_arrays_where_a_scene_object_belongs(value):
    _, error = call(ccdlab.truth, value)
    refused(error, "scene")
    _, error = call(ccdlab.Bound("aabb").prepare, value, 0.0)
    refused(error, "scene")


# The entry points above, and those that take no arrays or dicts. A new function or class of the
# module belongs in one of the two lists (with a test above when it takes arrays or dicts).
MESH_V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
MESH_F = np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int64)
MESH_SHAPES = st.one_of(ANY_SHAPE, st.tuples(st.integers(0, 5), st.just(3)))


@SETTINGS
@given(value=hostile_arrays(MESH_SHAPES), which=st.sampled_from(["V0", "V1", "F"]))
def test_mesh_ccd_arrays(value, which):
    args = {"V0": MESH_V, "V1": MESH_V + 0.25, "F": MESH_F}
    args[which] = value
    result, error = call(ccdlab.mesh_ccd, args["V0"], args["V1"], args["F"])
    if error is not None:
        # A vertex array of another length than the other frame's is named as V1.
        refused(error, which if which == "F" else "V")
        return
    if which == "F":
        plain = as_type(value, np.int64)
        assert plain is not None and plain.ndim == 2 and plain.shape[1] == 3
        assert np.all((plain >= 0) & (plain < len(MESH_V)))
    else:
        plain = as_type(value, np.float64)
        assert plain is not None and plain.shape == MESH_V.shape and np.all(np.isfinite(plain))
    assert isinstance(result, dict)


STEMS = {"positions": "position", "velocities": "velocit", "radii": "radi", "accelerations": "acceleration"}


@SETTINGS
@given(value=hostile_arrays(st.one_of(ANY_SHAPE, st.tuples(st.just(2), st.just(3)), st.just((2,)))),
       which=st.sampled_from(sorted(STEMS)))
def test_scene_from_arrays(value, which):
    args = {"positions": [[0, 0, 0], [3, 0, 0.0]], "velocities": [[1, 0, 0], [-1, 0, 0.0]], "radii": [0.5, 0.5],
            "accelerations": None}
    args[which] = value
    result, error = call(ccdlab.scene_from_arrays, args["positions"], args["velocities"], args["radii"],
                         accelerations=args["accelerations"], horizon=2.0)
    if error is not None:
        refused(error, STEMS[which])
        return
    plain = as_type(value, np.float64)
    assert plain is not None and np.all(np.isfinite(plain)) and isinstance(result, ccdlab.Scene)


@SETTINGS
@given(value=hostile_arrays(st.one_of(ANY_SHAPE, st.tuples(st.just(2), st.just(2), st.just(3)), st.just((2,)))),
       which=st.sampled_from(["positions", "times", "radii"]))
def test_import_frames_arrays(value, which):
    args = {"positions": np.array([[[0, 0, 0], [3, 0, 0]], [[1, 0, 0], [2, 0, 0]]], dtype=float),
            "times": np.array([0.0, 1.0]), "radii": np.array([0.5, 0.5])}
    args[which] = value
    result, error = call(ccdlab.import_frames, args["positions"], args["times"], radii=args["radii"])
    if error is not None:
        refused(error, "frames" if which == "times" else STEMS.get(which, which))
        return
    assert isinstance(result, ccdlab.Scene)


QUERY_SHAPES = st.one_of(ANY_SHAPE, st.just((4, 3)), st.tuples(st.integers(0, 3), st.just(4), st.just(3)))


@SETTINGS
@given(value=hostile_arrays(QUERY_SHAPES), which=st.sampled_from(["start", "end"]),
       query=st.sampled_from(["vertex_face_ccd", "edge_edge_ccd"]))
def test_triangle_query_arrays(value, which, query):
    args = {"start": np.eye(4, 3), "end": np.eye(4, 3) + 0.25}
    args[which] = value
    result, error = call(getattr(ccdlab, query), args["start"], args["end"])
    if error is not None:
        refused(error, which)
        return
    plain = as_type(value, np.float64)
    assert plain is not None and plain.shape == (4, 3) and isinstance(result, dict)


@SETTINGS
@given(value=hostile_arrays(st.one_of(ANY_SHAPE, st.just((3,)))),
       which=st.sampled_from(["position_a", "velocity_b", "acceleration_a"]))
def test_sphere_sphere_toi_arrays(value, which):
    args = {"position_a": [0, 0, 0], "velocity_a": [1, 0, 0], "position_b": [3, 0, 0], "velocity_b": [-1, 0, 0],
            "acceleration_a": None}
    args[which] = value
    result, error = call(ccdlab.sphere_sphere_toi, args["position_a"], args["velocity_a"], 0.5, args["position_b"],
                         args["velocity_b"], 0.5, 4.0, acceleration_a=args["acceleration_a"])
    if error is not None:
        refused(error, which)
        return
    plain = as_type(value, np.float64)
    assert plain is not None and plain.shape == (3,) and np.all(np.isfinite(plain)) and isinstance(result, dict)


@SETTINGS
@given(value=hostile_arrays(st.one_of(ANY_SHAPE, st.just((3,)), st.just((4,)))),
       which=st.sampled_from(["position_a", "velocity_b", "orientation_a", "angular_velocity_b", "acceleration_a",
                              "shape_b.half_extents"]))
def test_rigid_toi_arrays(value, which):
    box = {"kind": "box", "half_extents": [0.5, 0.5, 0.5]}
    args = {"shape_a": box, "position_a": [-2, 0, 0], "velocity_a": [1, 0, 0], "shape_b": dict(box),
            "position_b": [2, 0, 0], "velocity_b": [-1, 0, 0], "duration": 4.0}
    if which == "shape_b.half_extents":
        args["shape_b"]["half_extents"] = value
    else:
        args[which] = value
    result, error = call(ccdlab.rigid_toi, **args)
    if error is not None:
        refused(error, which)
        return
    plain = as_type(value, np.float64)
    assert plain is not None and np.all(np.isfinite(plain)) and isinstance(result, dict)
    assert plain.shape == ((4,) if which == "orientation_a" else (3,))


@SETTINGS
@given(dt=hostile_arrays(ANY_SHAPE), method=st.one_of(st.just("aabb/grid"), hostile_arrays(ANY_SHAPE)))
def test_results_missed_arguments(dt, method):
    results = {"records": [{"method": "aabb/grid", "dt": 0.5, "missed": 0, "missed_events": []}]}
    result, error = call(ccdlab.missed, results, method, dt)
    if error is not None:
        assert isinstance(error, ccdlab.InputError), repr(error)
        assert "method" in str(error) or "dt" in str(error), repr(error)
        return
    assert result == []


TESTED = {"BroadPhase", "Bound", "Scene", "scene_from_json", "generate", "run", "truth", "mesh_ccd",
          "scene_from_arrays", "import_frames", "vertex_face_ccd", "edge_edge_ccd", "sphere_sphere_toi", "missed",
          "rigid_toi"}
# Results takes a results document (a dict), not arrays; its methods are missed's (tested above).
NO_ARRAYS = {"InputError", "Truth", "load_scene", "load_truth", "methods", "generators", "Results"}


def test_every_entry_point_is_listed():
    public = {name for name in dir(ccdlab) if not name.startswith("_") and callable(getattr(ccdlab, name))}
    assert public - TESTED - NO_ARRAYS == set(), "entry points without a hostile-input test"


def test_values_json_cannot_hold_are_input_errors_naming_the_argument():
    # Regression: json.dumps refused these with its own ValueError or TypeError ("Out of range
    # float values are not JSON compliant", "Object of type complex is not JSON serializable"),
    # naming neither the argument nor the module's InputError.
    for value in (float("nan"), np.float32("inf"), 1j, np.array([1j, 2]), np.datetime64("2020-01-01")):
        with pytest.raises(ccdlab.InputError) as err:
            ccdlab.scene_from_json({"format": "ccdlab-scene/1", "horizon": value, "bodies": []})
        assert err.value.file == "scene" and "not JSON" in str(err.value)
        with pytest.raises(ccdlab.InputError) as err:
            ccdlab.generate("gas", bodies=value)
        assert err.value.file == "ccdlab.generate(gas)"


def test_times_that_are_no_sequence_are_type_errors_naming_times():
    # Regression: a 0-d array passed pybind11's sequence check, then failed len() with a bare
    # TypeError "len() of unsized object" that named no argument.
    scene = ccdlab.scene_from_json(SCENE)
    for times in (np.array(0.5), np.array(None, dtype=object), 0.5, "0.5", [[0.5]]):
        with pytest.raises(TypeError, match="times"):
            scene.positions(times)
    assert scene.positions(np.array([0.5])).shape == (1, 4, 3)
