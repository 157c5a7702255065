# ccdlab.BroadPhase and ccdlab.Bound over numpy arrays: every broad phase of the registry
# against a brute-force numpy reference, adversarial boxes built from dyadic numbers, the
# bounds' boxes and tests conservative against the exact truth, and no copies.
import numpy as np
import pytest

import ccdlab

BROAD_PHASES = [p["name"] for p in ccdlab.methods()["broad_phases"]]


def reference_pairs(boxes):
    lo, hi = boxes[:, 0, :], boxes[:, 1, :]
    overlap = np.all((lo[:, None, :] <= hi[None, :, :]) & (lo[None, :, :] <= hi[:, None, :]), axis=2)
    a, b = np.nonzero(np.triu(overlap, k=1))
    return sorted(zip(a.tolist(), b.tolist()))


def as_set(pairs):
    assert pairs.ndim == 2 and pairs.shape[1] == 2 and pairs.dtype == np.uint32
    listed = [tuple(p) for p in pairs.tolist()]
    assert len(listed) == len(set(listed))  # each pair once
    assert all(a < b for a, b in listed)
    return sorted(listed)


def random_boxes(n, seed, offset=0.0):
    rng = np.random.default_rng(seed)
    centre = rng.uniform(0, 10, size=(n, 3)) + offset
    half = rng.uniform(0.05, 0.6, size=(n, 1)) * np.ones((1, 3))
    return np.stack([centre - half, centre + half], axis=1)


def adversarial_boxes():
    # Dyadic corners: boxes 0 and 1 touch on a face (hi == lo in x: a pair), 2 touches 1 on an
    # edge and a corner, 3 and 4 coincide, 5 has zero size inside 3, 6 is a point on 0's corner,
    # 7 sits 2^-20 away from 0 in x (no pair), 8 and 9 are the same far from the origin.
    far = 2.0 ** 40
    b = [
        [[0, 0, 0], [1, 1, 1]],
        [[1, 0, 0], [2, 1, 1]],
        [[2, 1, 1], [3, 2, 2]],
        [[5, 5, 5], [6, 6, 6]],
        [[5, 5, 5], [6, 6, 6]],
        [[5.5, 5.5, 5.5], [5.5, 5.5, 5.5]],
        [[0, 0, 0], [0, 0, 0]],
        [[-1, 0, 0], [-2.0 ** -20, 1, 1]],
        [[far, far, far], [far + 0.5, far + 0.5, far + 0.5]],
        [[far + 0.5, far, far], [far + 1, far + 0.5, far + 0.5]],
    ]
    return np.array(b, dtype=np.float64)


@pytest.mark.parametrize("name", BROAD_PHASES)
def test_every_broad_phase_equals_brute_force(name):
    broad = ccdlab.BroadPhase(name)
    for frame, boxes in enumerate([random_boxes(400, 1), random_boxes(400, 2), random_boxes(50, 3, 2.0 ** 30)]):
        assert as_set(broad.find_pairs(boxes)) == reference_pairs(boxes), f"frame {frame}"


@pytest.mark.parametrize("name", BROAD_PHASES)
def test_adversarial_boxes(name):
    boxes = adversarial_boxes()
    expected = [(0, 1), (0, 6), (1, 2), (3, 4), (3, 5), (4, 5), (8, 9)]
    assert reference_pairs(boxes) == expected
    assert as_set(ccdlab.BroadPhase(name).find_pairs(boxes)) == expected
    assert as_set(ccdlab.BroadPhase(name).find_pairs(boxes.reshape(-1, 6))) == expected


def test_pairs_are_not_copied():
    pairs = ccdlab.BroadPhase("sap").find_pairs(random_boxes(200, 4))
    assert not pairs.flags.owndata and pairs.base is not None  # owns the broad phase's vector
    assert ccdlab.BroadPhase("brute").find_pairs(np.zeros((0, 2, 3))).shape == (0, 2)


def test_sap_counts_its_swaps_across_frames():
    sap = ccdlab.BroadPhase("sap")
    boxes = random_boxes(300, 5)
    sap.find_pairs(boxes)
    assert sap.stats()["rebuilt"] is True
    boxes[:, :, 0] += np.linspace(0, 0.5, 300)[:, None]
    sap.find_pairs(boxes)
    assert sap.stats()["rebuilt"] is False and sap.stats()["swaps"] > 0


def test_bad_boxes_and_specs():
    boxes = random_boxes(5, 6)
    boxes[2, 0, 1] = np.nan
    with pytest.raises(ValueError) as err:
        ccdlab.BroadPhase("grid").find_pairs(boxes)
    assert err.value.field == "boxes[2]"
    inverted = random_boxes(5, 6)
    inverted[4] = inverted[4][::-1]
    with pytest.raises(ValueError) as err:
        ccdlab.BroadPhase("grid").find_pairs(inverted)
    assert err.value.field == "boxes[4]"
    with pytest.raises(ValueError) as err:
        ccdlab.BroadPhase("grid").find_pairs(np.zeros((4, 3)))
    assert err.value.field == "boxes"
    with pytest.raises(ValueError) as err:
        ccdlab.BroadPhase("no_such_phase")
    assert err.value.field == "spec" and "sap" in str(err.value)
    with pytest.raises(ValueError):
        ccdlab.Bound("horn:pieces=0")


def test_instant_aabb_bound_is_the_sphere_box():
    scene = ccdlab.generate("gas", bodies=50, seed=2)
    boxes = ccdlab.Bound("aabb").prepare(scene, 0.0)
    r = scene.radius[:, None]
    p = scene.position
    # The sphere's box, grown by the bounds' rounding slack: 64 ulps of |p|_inf + r
    # (bounds/rounding.hpp), no more.
    slack = 64 * np.finfo(float).eps * (np.abs(p).max(axis=1, keepdims=True) + r)
    assert np.all(boxes[:, 0, :] <= p - r) and np.all(boxes[:, 1, :] >= p + r)
    assert np.all(boxes[:, 0, :] >= p - r - 2 * slack) and np.all(boxes[:, 1, :] <= p + r + 2 * slack)
    assert not boxes.flags.owndata


@pytest.mark.parametrize("bound", ["swept_aabb", "capsule", "horn:4", "horn_sat:4", "enclosing_sphere"])
def test_conservative_bounds_miss_no_contact(bound):
    # Every truth event that overlaps a step must be a bounded broad-phase pair that the
    # bound's own test keeps, at or before its enter time within the step.
    scene = ccdlab.generate("gas", bodies=300, seed=7)
    a, b, enter, exit = ccdlab.truth(scene)
    method = ccdlab.Bound(bound)
    broad = ccdlab.BroadPhase("grid")
    dt = 1.0 / 16  # dyadic step ends
    checked = 0
    for k in range(16):
        t0, t1 = k * dt, (k + 1) * dt
        pairs = broad.find_pairs(method.prepare(scene, t0, t1))
        possible, earliest = method.test_pairs(pairs)
        kept = {tuple(p): e for p, ok, e in zip(pairs.tolist(), possible, earliest) if ok}
        for i in np.nonzero((enter <= t1) & (exit >= t0))[0]:
            key = (int(a[i]), int(b[i]))
            assert key in kept, f"{bound} missed {key} in step {k}"
            assert kept[key] <= max(enter[i], t0)
            checked += 1
    assert checked > 20
