"""Strings from input files never break the pages ccdlab writes (issue 36): for each of three
payloads, `</script><script>...`, `<!--<script>` and `<img src=x onerror=...>`, every string a
scene, an experiment, a results file, a truth file or a cloth frames file may hold, and every
file name (the payload is in the folder of every input), carries the payload; `ccdlab view`
(a rigid scene with results and truth, a cloth run's frames) and `ccdlab report` (payload
also in --title) write their pages, and Debian's chromium, headless, loads each one.

Each page must load (the viewer's data-status is 'ready', or 'no-webgl' where the browser
has no WebGL: never stuck at 'loading' nor 'error'), no injected script may run (the
payloads set data-injected on the root element), and the payload must be on the page as
text (the viewer's info line names the scene file, the report's heading is the title).

One browser for every page, driven over its DevTools pipe (--remote-debugging-pipe: JSON
messages on file descriptors 3 and 4, no network, no extra package): one start, not nine. Usage: injection_test.py CCDLAB SOURCE_DIR. Exits 77 (skipped) with a message when
no chromium is installed.
"""
import json
import os
import select
import shutil
import subprocess
import sys
import tempfile
import time

from browser_test import SKIP, browser_args, chromium, run

MARK = "document.documentElement.dataset.injected='1'"
PAYLOADS = [f"</script><script>{MARK}</script>", "<!--<script>", f'<img src=x onerror="{MARK}">']


class Browser:
    """Headless chromium with its DevTools protocol on a pipe: one page (a tab) reused."""

    def __init__(self, browser, profile):
        to_browser, self.w = os.pipe()
        self.r, from_browser = os.pipe()

        def child_fds():  # the protocol's descriptors: 3 reads commands, 4 writes replies
            a, b = os.dup(to_browser), os.dup(from_browser)
            os.dup2(a, 3)
            os.dup2(b, 4)

        args = browser_args(browser, profile) + ["--remote-debugging-pipe", "about:blank"]
        self.proc = subprocess.Popen(args, preexec_fn=child_fds, close_fds=False, stdout=subprocess.DEVNULL,
                                     stderr=subprocess.DEVNULL)
        os.close(to_browser)
        os.close(from_browser)
        self.buf, self.next_id, self.events = b"", 0, []
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        self.call("Page.enable", session=True)
        self.call("Runtime.enable", session=True)

    def read(self, deadline):
        while b"\0" not in self.buf:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self.r], [], [], left)[0]:
                raise TimeoutError("chromium did not answer")
            chunk = os.read(self.r, 1 << 16)
            if not chunk:
                raise RuntimeError("chromium closed its pipe")
            self.buf += chunk
        message, self.buf = self.buf.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, session=False, timeout=30):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = self.session
        os.write(self.w, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            m = self.read(deadline)
            if m.get("id") == self.next_id:
                if "error" in m:
                    raise RuntimeError(f"{method}: {m['error']}")
                return m["result"]
            self.events.append(m)

    def load(self, url, timeout=30):
        """Navigates to `url` and waits for its load event (after every image's error)."""
        self.events = []
        self.call("Page.navigate", {"url": url}, session=True)
        deadline = time.monotonic() + timeout
        while not any(e.get("method") == "Page.loadEventFired" for e in self.events):
            self.events.append(self.read(deadline))

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", {"expression": expression, "returnByValue": True}, session=True)
        return result["result"].get("value")

    def close(self):
        try:
            self.call("Browser.close", timeout=5)
        except (OSError, RuntimeError, TimeoutError):
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


def write(path, document):
    with open(path, "w") as f:
        json.dump(document, f)
    return path


def hostile_inputs(ccdlab, folder, p):
    """Writes a rigid scene, its experiment, results and truth and a cloth run's frames,
    every string holding payload `p`, into `folder` (whose path holds it too); returns the
    pages to load: (kind, path)."""
    os.makedirs(folder)
    scene = write(os.path.join(folder, "scene.json"), {
        "format": "ccdlab-scene/2", "comment": p, "horizon": 2.0, "gravity": [0, 0, 0],
        "shapes": [{"name": "crate" + p, "comment": p, "kind": "box", "half_extents": [0.5, 0.3, 0.2]},
                   {"name": p, "kind": "capsule", "half_length": 1.0, "radius": 0.05}],
        "bodies": [{"shape": "crate" + p, "comment": p, "position": [0, 0, 0], "velocity": [2, 0, 0],
                    "angular_velocity": [0, 0, 3]},
                   {"shape": p, "position": [4, 0, 0], "velocity": [-2, 0, 0]},
                   {"radius": 0.5, "position": [0, 5, 0]}]})
    experiment = write(os.path.join(folder, "experiment.json"), {
        "format": "ccdlab-experiment/1", "name": "inject", "description": p, "comment": p, "scene": scene,
        "dt": [0.5, 0.05], "methods": ["aabb/sap", "capsule/grid"], "list_missed": True})
    truth = os.path.join(folder, "truth.json")
    results = os.path.join(folder, "results.json")
    run([ccdlab, "truth", scene, "-o", truth, "--quiet"])
    run([ccdlab, "run", experiment, "--truth", truth, "-o", results, "--quiet"])
    with open(truth) as f:
        t = json.load(f)
    t["comment"] = p
    for e in t["events"]:
        e["comment"] = p
    write(truth, t)
    with open(results) as f:
        res = json.load(f)
    for k, v in res["environment"].items():  # free text, unlike scene.motion or truth.scene_sha256
        if isinstance(v, str):
            res["environment"][k] = v + p
    res["scene"]["source"] += p
    res["truth"]["source"] += p
    for r in res["records"]:
        r["knowledge"] += p
        r["options"]["note"] = p
        r["comment"] = p
    write(results, res)
    view = os.path.join(folder, "view.html")
    run([ccdlab, "view", scene, "--results", results, "--truth", truth, "-o", view])
    frames = os.path.join(folder, "frames.json")
    run([ccdlab, "cloth", "drape", "--n", "6", "--steps", "10", "--every", "5", "-o", frames])
    with open(frames) as f:
        fr = json.load(f)
    fr["scene"] += p
    fr["comment"] = p
    write(frames, fr)
    cloth = os.path.join(folder, "cloth.html")
    run([ccdlab, "view", frames, "-o", cloth])
    report = os.path.join(folder, "report")
    run([ccdlab, "report", results, "-o", report, "--title", p])
    return [("view", view), ("cloth", cloth), ("report", os.path.join(report, "report.html"))]


CHECK = ("JSON.stringify({status: document.body ? document.body.dataset.status || null : null,"
         " error: document.body ? document.body.dataset.error || null : null,"
         " injected: document.documentElement.dataset.injected || null,"
         " info: (document.getElementById('info') || document.querySelector('h1') || {}).textContent || ''})")


def main():
    ccdlab = os.path.abspath(sys.argv[1])
    browser = chromium()
    if not browser:
        print("SKIPPED: no chromium found (Debian's chromium: scripts/install-deps.sh)")
        return SKIP
    work = tempfile.mkdtemp(prefix="ccdlab-injection-test.")
    started = time.monotonic()
    failures = []
    try:
        pages = []
        for k, p in enumerate(PAYLOADS):
            # The payload in a folder name (a '/' in it makes more folders: the path holds it).
            pages += [(p, kind, path) for kind, path in hostile_inputs(ccdlab, os.path.join(work, str(k), p), p)]
        print(f"inputs and pages written in {time.monotonic() - started:.1f} s")
        b = Browser(browser, os.path.join(work, "profile"))
        try:
            for p, kind, path in pages:
                b.load("file://" + path)
                seen = json.loads(b.evaluate(CHECK))
                ok_status = seen["status"] in ("ready", "no-webgl") if kind != "report" else seen["status"] is None
                problems = []
                if not ok_status:
                    problems.append(f"data-status {seen['status']!r} ({seen['error']})")
                if seen["injected"]:
                    problems.append("an injected script ran")
                if p not in seen["info"]:
                    problems.append(f"the payload is not shown as text (shown: {seen['info'][:200]!r})")
                print(f"{kind} page, payload {p!r}: " + ("; ".join(problems) if problems else "loads, nothing ran"))
                if problems:
                    failures.append(f"{kind} page with {p!r}: " + "; ".join(problems))
        finally:
            b.close()
    finally:
        if os.environ.get("CCDLAB_KEEP_VIEW_TEST"):
            print("kept", work)
        else:
            shutil.rmtree(work, ignore_errors=True)
    print(f"{len(pages)} pages in {time.monotonic() - started:.1f} s")
    if failures:
        print("FAIL:\n  " + "\n  ".join(failures))
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
