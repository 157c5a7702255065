# The README's Python example runs as written (in a scratch folder) and prints what it says.
import contextlib
import io
import os
import re

import matplotlib

import ccdlab

matplotlib.use("Agg")  # the example draws a chart


def test_readme_python_example_runs(source_dir, tmp_path):
    readme = (source_dir / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    assert len(blocks) == 1
    out = io.StringIO()
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        with contextlib.redirect_stdout(out):
            exec(compile(blocks[0], "README.md", "exec"), {})
    finally:
        os.chdir(cwd)
    lines = out.getvalue().splitlines()
    assert re.match(r"\d+ contacts; first at t = ", lines[0])
    assert re.match(r"\d+ of \d+ pairs may touch in the first step", lines[1])
    records = [line for line in lines[2:] if line.startswith(("aabb/sap", "capsule/grid"))]
    assert len(records) == 4
    assert all(line.endswith(f"of {lines[0].split()[0]}") for line in records)
    assert any(line.startswith("capsule/grid") and " missed 0 of " in line for line in records)
    assert os.listdir(tmp_path) == []  # the scene ran in memory, the chart was not saved
