# ccdlab.mesh_ccd on numpy arrays: the same result as `ccdlab ccd FRAME0 FRAME1 -o OUT.json`
# on the same frames written as ascii PLY (Python's repr of a float reads back to the same
# double), the same collisions for every conservative culler, and bad input refused.
import json

import numpy as np
import pytest

import ccdlab

from conftest import ccdlab_cli


def folded_sheet(n=7):
    """A dyadic n x n sheet whose half x > 1/2 folds through the other half by t = 1."""
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="xy")
    x, y = (i / (n - 1)).ravel(), (j / (n - 1)).ravel()
    z = np.round(0.1 * np.sin(7 * x + 3 * y) * 2**20) / 2**20
    v0 = np.stack([x, y, z], axis=1)
    v1 = v0.copy()
    right = x > 0.5
    v1[right, 0] = 1.0 - x[right] - 0.125  # mirrored over x = 7/16: through the left half
    v1[right, 2] = -z[right] + 0.0625
    faces = []
    for jj in range(n - 1):
        for ii in range(n - 1):
            a = ii + n * jj
            faces += [[a, a + 1, a + n + 1], [a, a + n + 1, a + n]]
    return v0, v1, np.array(faces, dtype=np.int64)


def write_ascii_ply(path, vertices, faces):
    lines = ["ply", "format ascii 1.0", f"element vertex {len(vertices)}", "property double x",
             "property double y", "property double z", f"element face {len(faces)}",
             "property list uchar int vertex_indices", "end_header"]
    lines += [" ".join(repr(float(c)) for c in p) for p in vertices]
    lines += ["3 " + " ".join(str(int(k)) for k in f) for f in faces]
    path.write_text("\n".join(lines) + "\n")


def comparable(result):
    return {k: v for k, v in result.items() if k not in ("seconds", "frames", "peak_memory_bytes", "options")}


@pytest.mark.parametrize("separation", [0.0, 0.01])
def test_same_result_as_the_command(tmp_path, separation):
    v0, v1, f = folded_sheet()
    write_ascii_ply(tmp_path / "t0.ply", v0, f)
    write_ascii_ply(tmp_path / "t1.ply", v1, f)
    ccdlab_cli("ccd", tmp_path / "t0.ply", tmp_path / "t1.ply", "--separation", separation, "--quiet",
               "-o", tmp_path / "out.json")
    command = json.loads((tmp_path / "out.json").read_text())
    result = ccdlab.mesh_ccd(v0, v1, f, separation=separation)
    assert result["format"] == "ccdlab-mesh-ccd/1"
    assert comparable(result) == comparable(command)
    assert result["collisions"]["vf"] and result["collisions"]["ee"]  # the fold goes through
    assert result["options"]["cull"] == "mesh_sweep"


def test_every_conservative_culler_finds_the_same_collisions():
    v0, v1, f = folded_sheet(6)
    reference = ccdlab.mesh_ccd(v0, v1, f, cull="brute", exact=True)
    assert reference["exact"] is not None
    for cull in ["mesh_sweep", "bvh", "bvh_cones", "boxes:sap", "boxes:grid"]:
        got = ccdlab.mesh_ccd(v0, v1, f, cull=cull, exact=True, threads=2)
        assert got["collisions"] == reference["collisions"], cull
        assert got["toi"] == reference["toi"], cull


def test_bad_input_is_refused():
    v0, v1, f = folded_sheet(4)
    bad = f.copy()
    bad[3, 1] = 9001
    with pytest.raises(ccdlab.InputError, match=r"F\[3\]: vertex index 9001 out of range"):
        ccdlab.mesh_ccd(v0, v1, bad)
    nan = v1.copy()
    nan[5, 2] = np.nan
    with pytest.raises(ccdlab.InputError, match=r"V1\[5\]: coordinate not finite"):
        ccdlab.mesh_ccd(v0, nan, f)
    with pytest.raises(ccdlab.InputError, match="V1: has \\d+ vertices, V0 has \\d+"):
        ccdlab.mesh_ccd(v0, v1[:-1], f)
    with pytest.raises(ccdlab.InputError, match="unknown culler 'nope'"):
        ccdlab.mesh_ccd(v0, v1, f, cull="nope")
    with pytest.raises(ccdlab.InputError, match=r"\(n, 3\)"):
        ccdlab.mesh_ccd(v0[:, :2], v1, f)
    with pytest.raises(ccdlab.InputError, match="integers"):
        ccdlab.mesh_ccd(v0, v1, f.astype(float))
