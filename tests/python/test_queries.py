# Single queries (python/query_binding.cpp): vertex_face_ccd, edge_edge_ccd and
# sphere_sphere_toi on dyadic cases whose answers are known exactly, near the origin and
# 2^20 from it; batches equal single queries; bad arrays named.
import numpy as np
import pytest

import ccdlab

OFFSETS = [np.zeros(3), np.full(3, 2.0 ** 20)]


def vf(vertex_start, vertex_end, offset):
    face = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float)
    start = np.vstack([vertex_start, face]) + offset
    end = np.vstack([vertex_end, face]) + offset
    return start, end


@pytest.mark.parametrize("offset", OFFSETS)
def test_vertex_reaching_the_face_at_one_half(offset):
    r = ccdlab.vertex_face_ccd(*vf([0.25, 0.25, 1], [0.25, 0.25, -1], offset))
    assert r["status"] == "hit" and r["hit"]
    assert r["toi"] <= 0.5 <= r["toi_upper"] and r["toi_error"] == r["toi_upper"] - r["toi"]


@pytest.mark.parametrize("offset", OFFSETS)
def test_vertex_arriving_exactly_at_t_equal_one_and_stopping_short(offset):
    assert ccdlab.vertex_face_ccd(*vf([0.25, 0.25, 1], [0.25, 0.25, 0], offset))["hit"]
    r = ccdlab.vertex_face_ccd(*vf([0.25, 0.25, 1], [0.25, 0.25, 2.0 ** -30], offset))
    assert not r["hit"] and r["toi"] is None and r["toi_error"] is None


@pytest.mark.parametrize("offset", OFFSETS)
def test_vertex_passing_beside_the_face_edge(offset):
    # Through the plane at x + y = 1 + 2^-30: beside the hypotenuse, a miss; on it, a hit.
    d = 2.0 ** -31
    assert not ccdlab.vertex_face_ccd(*vf([0.5 + d, 0.5 + d, 1], [0.5 + d, 0.5 + d, -1], offset))["hit"]
    assert ccdlab.vertex_face_ccd(*vf([0.5, 0.5, 1], [0.5, 0.5, -1], offset))["hit"]


@pytest.mark.parametrize("offset", OFFSETS)
def test_edges_crossing_and_parallel_edges_apart(offset):
    b = [[0.5, -1, 0], [0.5, 1, 0]]
    crossing = ccdlab.edge_edge_ccd(np.array([[0, 0, 1], [1, 0, 1]] + b) + offset,
                                    np.array([[0, 0, -1], [1, 0, -1]] + b) + offset)
    assert crossing["hit"] and crossing["toi"] <= 0.5 <= crossing["toi_upper"]
    # Parallel edges sliding along each other 2^-30 apart: never in contact.
    gap = 2.0 ** -30
    parallel = ccdlab.edge_edge_ccd(np.array([[0, 0, 0], [1, 0, 0], [-2, gap, 0], [-1, gap, 0]]) + offset,
                                    np.array([[0, 0, 0], [1, 0, 0], [2, gap, 0], [3, gap, 0]]) + offset)
    assert not parallel["hit"]
    # With a separation of 2^-29 they are within it.
    near = ccdlab.edge_edge_ccd(np.array([[0, 0, 0], [1, 0, 0], [-2, gap, 0], [-1, gap, 0]]) + offset,
                                np.array([[0, 0, 0], [1, 0, 0], [2, gap, 0], [3, gap, 0]]) + offset,
                                separation=2.0 ** -29)
    assert near["hit"]


def test_a_batch_gives_the_single_answers():
    rng = np.random.default_rng(7)
    start = rng.uniform(-1, 1, (64, 4, 3))
    end = start + rng.uniform(-0.6, 0.6, (64, 4, 3))
    for query in (ccdlab.vertex_face_ccd, ccdlab.edge_edge_ccd):
        batch = query(start, end)
        assert batch["hit"].shape == (64,) and batch["hit"].any() and not batch["hit"].all()
        for i in range(64):
            one = query(start[i], end[i])
            assert one["hit"] == batch["hit"][i] and one["boxes"] == batch["boxes"][i]
            if one["hit"]:
                assert one["toi"] == batch["toi"][i]
            else:
                assert np.isnan(batch["toi"][i])


def test_sphere_sphere_toi_is_exact():
    r = ccdlab.sphere_sphere_toi([0, 0, 0], [1, 0, 0], 0.5, [3, 0, 0], [-1, 0, 0], 0.5, 4.0)
    assert r == {"status": "hit", "hit": True, "toi": 1.0, "toi_error": 0.0, "intervals": [(1.0, 2.0)]}
    # Tangent: centres pass exactly 1 apart (radii 1/2): one touching instant at t = 2.
    t = ccdlab.sphere_sphere_toi([0, 1, 0], [1, 0, 0], 0.5, [4, 0, 0], [-1, 0, 0], 0.5, 4.0)
    assert t["hit"] and t["toi"] == 2.0 and t["intervals"] == [(2.0, 2.0)]
    # Falling from rest onto a still sphere: |g| = 2, drop 1 -> contact at t = 1.
    f = ccdlab.sphere_sphere_toi([0, 0, 0], [0, 0, 0], 0.5, [0, 0, 2], [0, 0, 0], 0.5, 4.0,
                                 acceleration_b=[0, 0, -2])
    assert f["toi"] == 1.0
    assert ccdlab.sphere_sphere_toi([0, 0, 0], [0, 0, 0], 0.5, [3, 0, 0], [0, 0, 0], 0.5, 4.0)["toi"] is None
    assert ccdlab.sphere_sphere_toi([0, 0, 0], [0, 0, 0], 1, [1, 0, 0], [0, 0, 0], 1, 4.0)["status"] == "overlapping"


@pytest.mark.parametrize("call, field", [
    (lambda: ccdlab.vertex_face_ccd(np.zeros((3, 3)), np.zeros((3, 3))), "start"),
    (lambda: ccdlab.vertex_face_ccd(np.zeros((4, 3)), np.zeros((2, 4, 3))), "end"),
    (lambda: ccdlab.edge_edge_ccd(np.zeros((4, 3)), np.zeros((4, 3)), separation=-1), "separation"),
    (lambda: ccdlab.edge_edge_ccd(np.zeros((4, 3)), np.zeros((4, 3)), tolerance=0), "tolerance"),
    (lambda: ccdlab.sphere_sphere_toi([0, 0], [0, 0, 0], 1, [0, 0, 0], [0, 0, 0], 1, 1), "position_a"),
    (lambda: ccdlab.sphere_sphere_toi([0, 0, 0], [0, 0, 0], -1, [0, 0, 0], [0, 0, 0], 1, 1), "radius_a"),
    (lambda: ccdlab.sphere_sphere_toi([0, 0, 0], [0, 0, 0], 1, [0, 0, 0], [np.nan, 0, 0], 1, 1), "velocity_b"),
    (lambda: ccdlab.sphere_sphere_toi([0, 0, 0], [0, 0, 0], 1, [0, 0, 0], [0, 0, 0], 1, np.inf), "duration"),
])
def test_bad_input_is_named(call, field):
    with pytest.raises(ccdlab.InputError, match=field):
        call()
