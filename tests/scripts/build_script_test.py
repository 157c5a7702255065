#!/usr/bin/env python3
"""scripts/build.sh: --target builds only what is named, --progress shows the build on stderr
and prints the log's end when the build fails, a bad option exits 2.

usage: build_script_test.py SOURCE_DIR"""
import os
import subprocess
import sys
import tempfile


def build(source, build_dir, *args):
    env = dict(os.environ, CCDLAB_BUILD_DIR=build_dir)
    return subprocess.run([os.path.join(source, "scripts", "build.sh"), *args], env=env,
                          capture_output=True, text=True, timeout=600)


def main():
    source = sys.argv[1]
    failures = []

    def check(what, ok, result):
        if not ok:
            failures.append(f"{what}: exit {result.returncode}\nstdout: {result.stdout[-2000:]}\n"
                            f"stderr: {result.stderr[-2000:]}")

    with tempfile.TemporaryDirectory() as tmp:
        build_dir = os.path.join(tmp, "build")
        # The smallest target: the git hash header. Nothing else may be built.
        r = build(source, build_dir, "--target", "ccdlab_git_hash", "--progress",
                  "-DCCDLAB_BENCHMARKS=OFF", "-DCCDLAB_PYTHON=OFF")
        check("--target ccdlab_git_hash --progress", r.returncode == 0
              and "ccdlab: built in" in r.stderr
              and os.path.exists(os.path.join(build_dir, "generated", "ccdlab_git_hash.hpp"))
              and not os.path.exists(os.path.join(build_dir, "ccdlab")), r)
        check("the log is kept", os.path.getsize(os.path.join(build_dir, "build.log")) > 0, r)
        r = build(source, build_dir, "--target", "no_such_target", "--progress")
        check("an unknown target fails and names the log", r.returncode != 0
              and "build.log" in r.stderr and "no_such_target" in r.stderr, r)
        r = build(source, build_dir, "--target")
        check("--target without a name exits 2", r.returncode == 2 and "--target" in r.stderr, r)

    for f in failures:
        print("FAIL", f)
    print(f"{3 + 1 - len(failures)} of 4 checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
