# `ccdlab report` on what users hope for (nothing missed), on the smallest results (one
# record, every number 0) and on hostile input (issue 36): each bad input ends in one line
# naming the file and the field, exit 2, nothing written; a full disk or a read-only folder
# leaves every old output as it was and no temporary file.
import json
import os
import shutil
import subprocess

import pytest

from conftest import BINARY, write_json
from results_fixtures import crossing_results, never_meeting_results, single_record_results

OUTPUTS = ("report.md", "report.html", "missed.png", "cost.png")


@pytest.fixture(scope="module")
def crossing(tmp_path_factory):
    return crossing_results(tmp_path_factory.mktemp("crossing"))


def one_line_error(run, needle):
    """The command failed with a single line on stderr holding `needle`, no traceback."""
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1, run.stderr
    assert "Traceback" not in run.stderr and lines[0].startswith("ccdlab report: ")
    assert needle in lines[0], lines[0]
    return lines[0]


def test_nothing_missed_is_said_plainly(tmp_path, cli, crossing):
    # Issue 36's reproduction: two spheres crossing once, aabb/sap and capsule/grid at dt 0.1
    # and 0.01. Once a matplotlib traceback (a log scale of an all-zero series).
    assert all(r["missed"] == 0 and r["false_positives_per_step"] == 0 for r in crossing["records"])
    out = tmp_path / "report"
    run = cli("report", write_json(tmp_path / "r.json", crossing), "-o", out)
    assert run.returncode == 0 and run.stderr == ""
    md = (out / "report.md").read_text()
    assert md.splitlines()[2] == ("Nothing was missed: no method missed a contact at any dt (4 runs of 2 methods); "
                                  "and no method had a false positive.")
    assert '<p id="verdict"><strong>Nothing was missed:' in (out / "report.html").read_text()
    for name in ("missed.png", "cost.png"):
        assert (out / name).read_bytes().startswith(b"\x89PNG")


def test_a_method_that_missed_is_not_hidden(tmp_path, cli, crossing):
    res = json.loads(json.dumps(crossing))
    rec = next(r for r in res["records"] if r["method"] == "aabb/sap" and r["dt"] == 0.1)
    rec["missed"], rec["detected"], rec["missed_fraction"] = 1, 0, 1.0
    out = tmp_path / "report"
    cli("report", write_json(tmp_path / "r.json", res), "-o", out)
    md = (out / "report.md").read_text()
    assert "Nothing was missed" not in md and "Missed nothing at every dt run: capsule/grid." in md


@pytest.mark.parametrize("make", [never_meeting_results, single_record_results], ids=["all-zero", "one-record"])
def test_all_zero_and_single_record(tmp_path, cli, make):
    res = make(tmp_path / "in")
    out = tmp_path / "report"
    run = cli("report", write_json(tmp_path / "r.json", res), "-o", out, check=False)
    assert run.returncode == 0, run.stderr
    assert "Nothing was missed" in (out / "report.md").read_text()
    for name in OUTPUTS:
        assert (out / name).stat().st_size > 0


HOSTILE = ("invalid UTF-8", "nesting 100,000 deep", "an experiment that is a list", "the same file twice",
           "the same file under another name", "the same results twice", "dt = 1e-320 with cost 1e308",
           "cost 1e308", "NaN", "payloads in names", "a folder", "a missing file")


def hostile_cases(tmp_path, good):
    """{name: (the files given, what the error line must hold)} for each hostile input."""
    good_path = write_json(tmp_path / "good.json", good)
    cases = {}

    def add(name, files, needle):
        cases[name] = ([str(f) for f in files], needle)

    text = json.dumps(good).replace('"crossing"', '"cross-ing"', 1).encode()
    (tmp_path / "utf8.json").write_bytes(text.replace(b"cross-ing", b"cross\xffing"))
    add("invalid UTF-8", [tmp_path / "utf8.json"], "utf8.json: ")
    (tmp_path / "deep.json").write_text("[" * 100000 + "]" * 100000)
    add("nesting 100,000 deep", [tmp_path / "deep.json"], "nested deeper than 64 levels")
    as_list = dict(good, experiment=[good["experiment"]])
    add("an experiment that is a list", [write_json(tmp_path / "list.json", as_list)],
        "list.json: experiment: must be an object")
    add("the same file twice", [good_path, good_path], "good.json: given twice (also as ")
    os.symlink(good_path, tmp_path / "link.json")
    add("the same file under another name", [good_path, tmp_path / "link.json"], "link.json: given twice")
    shutil.copy(good_path, tmp_path / "copy.json")
    add("the same results twice", [good_path, tmp_path / "copy.json"], "copy.json: the same results as ")
    tiny = json.loads(json.dumps(good))
    tiny["experiment"]["dt"] = [1e-320, tiny["experiment"]["dt"][1]]
    for r in tiny["records"]:
        if r["dt"] == 0.1:
            r["dt"], r["seconds_per_simulated_second"] = 1e-320, 1e308
    add("dt = 1e-320 with cost 1e308", [write_json(tmp_path / "tiny.json", tiny)], "tiny.json: experiment.dt")
    huge = json.loads(json.dumps(good))
    huge["records"][0]["seconds_per_simulated_second"] = 1e308
    add("cost 1e308", [write_json(tmp_path / "huge.json", huge)],
        "huge.json: records[0].seconds_per_simulated_second: 1e+308 is outside [1e-300, 1e300]")
    (tmp_path / "nan.json").write_text(json.dumps(good).replace('"missed_fraction": 0.0', '"missed_fraction": NaN', 1))
    add("NaN", [tmp_path / "nan.json"], "nan.json: ")
    # Payloads in names: a newline (one line still), a shell command, HTML, a leading dash.
    folder = tmp_path / "pay\nload$(touch PWNED)<script>"
    folder.mkdir()
    (folder / "-o.json").write_bytes((tmp_path / "utf8.json").read_bytes())
    add("payloads in names", [folder / "-o.json"], "pay\\x0aload$(touch PWNED)<script>/-o.json: ")
    add("a folder", [tmp_path], "not a regular file")
    add("a missing file", [tmp_path / "missing.json"], "missing.json: cannot open file")
    return cases


@pytest.mark.parametrize("name", HOSTILE)
def test_hostile_input_exits_2_with_one_line_writing_nothing(tmp_path, cli, crossing, name):
    cases = hostile_cases(tmp_path, crossing)
    assert sorted(cases) == sorted(HOSTILE)
    files, needle = cases[name]
    out = tmp_path / "out"
    run = cli("report", *files, "-o", out, check=False)
    assert run.returncode == 2, run.stderr
    one_line_error(run, needle)
    assert not out.exists()
    assert not (tmp_path / "PWNED").exists()


def test_usage_errors_exit_2(tmp_path, cli, crossing):
    path = write_json(tmp_path / "r.json", crossing)
    for args, needle in ((["-o", tmp_path / "o"], "missing RESULTS.json"), ([path], "missing -o DIR"),
                         ([path, "-o"], "missing value after -o"), ([path, "--bogus", "-o", tmp_path / "o"],
                                                                    "unknown option '--bogus'")):
        run = cli("report", *args, check=False)
        assert run.returncode == 2
        one_line_error(run, needle)
    # A results file whose name starts with a dash, after "--".
    shutil.copy(path, tmp_path / "-r.json")
    run = subprocess.run([BINARY, "report", "-o", "out", "--", "-r.json"], cwd=tmp_path, capture_output=True,
                         text=True)
    assert run.returncode == 0, run.stderr


def test_output_folder_checked_before_the_work(tmp_path, cli, crossing):
    path = write_json(tmp_path / "r.json", crossing)
    (tmp_path / "file").write_text("x")
    one_line_error(cli("report", path, "-o", tmp_path / "file", check=False), "file: -o must name a folder")
    (tmp_path / "out" / "missed.png").mkdir(parents=True)
    run = cli("report", path, "-o", tmp_path / "out", check=False)
    assert run.returncode == 2
    one_line_error(run, "missed.png")
    assert sorted(os.listdir(tmp_path / "out")) == ["missed.png"]


def mount_tmpfs(folder, options):
    """Mounts a tmpfs on `folder`; False where mounting is not permitted (not root)."""
    folder.mkdir()
    try:
        done = subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(folder)], capture_output=True)
    except OSError:
        return False
    return done.returncode == 0


def test_full_disk_changes_no_old_output(tmp_path, cli, crossing):
    path = write_json(tmp_path / "r.json", crossing)
    disk = tmp_path / "disk"
    if not mount_tmpfs(disk, "size=64k"):
        pytest.skip("mount -t tmpfs is not permitted here (needs root)")
    try:
        old = {name: f"old {name}".encode() for name in OUTPUTS}
        for name, data in old.items():
            (disk / name).write_bytes(data)
        run = cli("report", path, "-o", disk, check=False)
        assert run.returncode == 1
        one_line_error(run, "No space left on device")
        assert {name: (disk / name).read_bytes() for name in OUTPUTS} == old
        assert sorted(os.listdir(disk)) == sorted(OUTPUTS)  # no temporary file left
    finally:
        subprocess.run(["umount", str(disk)], check=True)


def test_read_only_folder_exits_2_before_the_work(tmp_path, cli, crossing):
    path = write_json(tmp_path / "r.json", crossing)
    folder = tmp_path / "ro"
    mounted = os.geteuid() == 0 and mount_tmpfs(folder, "size=1m,ro")
    if os.geteuid() == 0 and not mounted:
        pytest.skip("root ignores folder permissions, and mount -t tmpfs is not permitted here")
    if not mounted:
        folder.mkdir()
        folder.chmod(0o555)
    try:
        for out in (folder, folder / "sub"):
            run = cli("report", path, "-o", out, check=False)
            assert run.returncode == 2
            one_line_error(run, str(folder))
        assert os.listdir(folder) == []
    finally:
        if mounted:
            subprocess.run(["umount", str(folder)], check=True)
