"""The viewer page in a real browser: Debian's chromium, headless, loads pages written by
`ccdlab view` from disk (file://, no server, no network) and this test reads what it
rendered.

- The example experiment (data/experiments/example.json, which lists missed contacts): the
  page's table (elements with data-missed) equals the results file's missed_events for the
  method and dt the URL fragment selects (aabb/sap, which misses; capsule/sap and
  horn:4/grid, which miss nothing, with every body's bounds drawn); a screenshot at a
  missed contact is not blank and shows the highlighted pair in red.
- A floor_ramp scene (a floor and ramps): the table lists the record's body-body and
  body-scenery misses together in order of entry, and the screenshot shows the scenery.
- The bounds drawn are the volumes the C++ bounds computed: for every bound of the registry
  (the example's methods, four more on the example scene, one of them `@earliest` with
  speed-adapted windows, and three on the rigid example), with every body's bounds shown,
  the page reports per body its window and the world box of the instances it drew
  (data-volumes); that box must equal the hull of the body's volumes in the page's data for
  the window that holds t, and, where the ccdlab Python module is importable (CMake puts the
  build's on PYTHONPATH), the box ccdlab.Bound(BOUND).prepare(scene, w0, w1) computes on its
  own for the sphere scene (contained in the drawn box for capsule and horn_sat, whose
  volumes are larger than their boxes: docs/viewer.md).
- The rigid example scene and the frames of a small cloth run load without error.

Usage: browser_test.py CCDLAB SOURCE_DIR. Exits 77 (skipped) with a message when no chromium
is installed (scripts/install-deps.sh installs it).
"""
import html.parser
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

SKIP = 77


def chromium():
    for name in (os.environ.get("CCDLAB_CHROMIUM"), "chromium", "chromium-browser", "google-chrome"):
        if name and shutil.which(name):
            return shutil.which(name)
    return None


def browser_args(browser, profile):
    args = [browser, "--headless", "--disable-gpu-sandbox", "--use-gl=angle", "--use-angle=swiftshader",
            "--enable-unsafe-swiftshader", "--no-first-run", "--no-default-browser-check",
            "--disable-extensions", "--disable-background-networking", "--mute-audio",
            "--user-data-dir=" + profile, "--window-size=1100,700", "--hide-scrollbars"]
    if os.geteuid() == 0:
        args.append("--no-sandbox")  # chromium refuses to run as root with its sandbox
    return args


def run(cmd, timeout=120):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    if p.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {p.returncode}\n{p.stdout}\n{p.stderr}")
    return p.stdout


def load(browser, profile, url, png):
    """The page's DOM after loading `url`, and its screenshot written to `png` (one launch)."""
    dom = run(browser_args(browser, profile) + ["--screenshot=" + png, "--dump-dom", url])
    if not os.path.exists(png):
        sys.exit(f"FAIL: chromium wrote no screenshot for {url}")
    return parse(dom)


class Dom(html.parser.HTMLParser):
    """The body's data attributes and the rows of the missed-contact table."""

    def __init__(self):
        super().__init__()
        self.body = {}
        self.missed = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "body":
            self.body = a
        if "data-missed" in a:
            self.missed.append(a)


def parse(text):
    d = Dom()
    d.feed(text)
    return d


def png_pixels(path):
    """(width, height, rows of RGBA or RGB bytes) of an 8-bit non-interlaced PNG."""
    with open(path, "rb") as f:
        raw = f.read()
    if raw[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"FAIL: {path} is not a PNG")
    pos, idat, w = 8, b"", None
    while pos < len(raw):
        n, kind = struct.unpack(">I4s", raw[pos:pos + 8])
        chunk = raw[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunk)
            if depth != 8 or colour not in (2, 6) or interlace:
                sys.exit(f"FAIL: {path}: unexpected PNG layout (depth {depth}, colour {colour})")
            bpp = 4 if colour == 6 else 3
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + n
    data = zlib.decompress(idat)
    stride = w * bpp
    rows, prev = [], bytearray(stride)
    for y in range(h):
        ftype = data[y * (stride + 1)]
        line = bytearray(data[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - bpp] if i >= bpp else 0
            up = prev[i]
            ul = prev[i - bpp] if i >= bpp else 0
            if ftype == 1:
                line[i] = (line[i] + left) & 255
            elif ftype == 2:
                line[i] = (line[i] + up) & 255
            elif ftype == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif ftype == 4:
                p = left + up - ul
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - ul)
                pred = left if pa <= pb and pa <= pc else up if pb <= pc else ul
                line[i] = (line[i] + pred) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, bpp, rows


def colour_count(path, width_fraction, colour):
    """Pixels of the 3D view (the left `width_fraction` of the page) of `colour`, within 6
    in each channel (an unlit material draws its colour as it is)."""
    w, h, bpp, rows = png_pixels(path)
    count = 0
    for row in rows[: int(h * 0.9)]:
        for x in range(0, int(w * width_fraction) * bpp, bpp):
            if all(abs(row[x + k] - colour[k]) <= 6 for k in range(3)):
                count += 1
    return count


def check_scenery_page(ccdlab, browser, profile, work):
    """floor_ramp (a floor and ramps): the table lists the body-body and the body-scenery
    misses of the record together, in order of entry; the scenery is drawn."""
    scene = os.path.join(work, "floor.json")
    run([ccdlab, "scene", "floor_ramp", "bodies=100", "-o", scene])
    experiment = os.path.join(work, "floor-experiment.json")
    with open(experiment, "w") as f:
        json.dump({"format": "ccdlab-experiment/1", "name": "floor", "scene": scene, "hz": [30],
                   "methods": ["aabb/grid"], "list_missed": True}, f)
    results = os.path.join(work, "floor-results.json")
    run([ccdlab, "run", experiment, "-o", results, "--quiet"])
    page = os.path.join(work, "floor.html")
    run([ccdlab, "view", scene, "--results", results, "-o", page])
    with open(results) as f:
        r = json.load(f)["records"][0]
    if not r["static_missed_events"]:
        sys.exit("FAIL: aabb/grid at 30 Hz should miss floor contacts of floor_ramp")
    expected = sorted([(m["a"], m["b"], None, m["enter"], m["exit"]) for m in r["missed_events"]] +
                      [(m["body"], None, m["polygon"], m["enter"], m["exit"]) for m in r["static_missed_events"]],
                      key=lambda m: m[3])
    s0 = r["static_missed_events"][0]
    url = f"file://{page}#method=aabb/grid&dt={r['dt']!r}&t={0.5 * (s0['enter'] + s0['exit'])!r}"
    png = os.path.join(work, "floor.png")
    dom = load(browser, profile, url, png)
    if dom.body.get("data-status") != "ready":
        sys.exit(f"FAIL: {url}: page status {dom.body.get('data-status')!r}: {dom.body.get('data-error')}")
    shown = [(int(m["data-a"]), int(m["data-b"]) if "data-b" in m else None,
              int(m["data-polygon"]) if "data-polygon" in m else None, float(m["data-enter"]), float(m["data-exit"]))
             for m in dom.missed]
    if shown != expected:
        sys.exit(f"FAIL: {url}: the table lists {shown[:5]}..., the results file {expected[:5]}...")
    scenery = colour_count(png, 0.6, (0x9C, 0x8F, 0x6A))
    print(f"floor_ramp: {len(r['missed_events'])} body-body and {len(r['static_missed_events'])} body-scenery "
          f"missed contacts in the table, as in the results; {scenery} pixels of scenery")
    if scenery < 2000:
        sys.exit(f"FAIL: the screenshot {png} shows no scenery ({scenery} pixels of its colour)")


def pixel_counts(path, width_fraction):
    """Pixels of the 3D view (the left `width_fraction` of the page) that differ from its
    background, and of those the pure highlight red."""
    w, h, bpp, rows = png_pixels(path)
    background = (0xF4, 0xF4, 0xF1)
    other = red = 0
    for row in rows[: int(h * 0.9)]:
        for x in range(0, int(w * width_fraction) * bpp, bpp):
            r, g, b = row[x], row[x + 1], row[x + 2]
            if abs(r - background[0]) + abs(g - background[1]) + abs(b - background[2]) > 24:
                other += 1
                if r > 200 and g < 60 and b < 60:
                    red += 1
    return other, red


def page_data(path):
    """The JSON data `ccdlab view` put in the page."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    marker = 'id="ccdlab-data">'
    start = text.index(marker) + len(marker)
    return json.loads(text[start:text.index("</script>", start)])


def volume_hull(v):
    """The world box of one volume of the page's data (as bounds/volume.hpp's hull)."""
    if v["kind"] == "box":
        return v["lo"], v["hi"]
    if v["kind"] == "sphere":
        return [c - v["r"] for c in v["c"]], [c + v["r"] for c in v["c"]]
    if v["kind"] == "capsule":
        return ([min(a, b) - v["r"] for a, b in zip(v["a"], v["b"])],
                [max(a, b) + v["r"] for a, b in zip(v["a"], v["b"])])
    if v["kind"] == "oriented_box":
        ax = v["axes"]
        e = [sum(abs(ax[3 * c + k]) * v["half"][c] for c in range(3)) for k in range(3)]
        return [v["c"][k] - e[k] for k in range(3)], [v["c"][k] + e[k] for k in range(3)]
    sys.exit(f"FAIL: unknown volume kind {v['kind']!r}")


def entry_at(run, body, t):
    """The page data's entry [w0, w1, volumes] of `body` whose window holds t (the page's lookup)."""
    best = None
    for e in run["volumes"]["bodies"][body]:
        if e[0] <= t:
            best = e
    return best if best is not None and t <= best[1] else None


def close(x, y, tol):
    return all(abs(a - b) <= tol * (1.0 + abs(b)) for a, b in zip(x, y))


# The kinds each bound draws (bounds/*.hpp: Bound::volumes); M = the bound's pieces.
KINDS = {"sphere": {"sphere"}, "aabb": {"box"}, "frame_aabb": {"box"}, "swept_aabb": {"box"},
         "capsule": {"capsule"}, "horn": {"box"}, "horn_sat": {"oriented_box"},
         "enclosing_sphere": {"sphere", "box"}, "obb": {"oriented_box"}, "obb_sat": {"oriented_box"}}


def check_volumes(dom, page, url, method, dt, t, every_body, scene_path, module):
    """The bounds the page drew (data-volumes) against the page's data and, for a sphere
    scene where the Python module is available, against ccdlab.Bound(...).prepare."""
    drawn = json.loads(dom.body.get("data-volumes") or "{}")
    data = page_data(page)
    run = next(r for r in data["runs"] if r["method"] == method and r["dt"] == dt)
    if run["volumes"]["coverage"] != "all":
        sys.exit(f"FAIL: {url}: the example's page should hold every window ({run['volumes']})")
    bodies = range(data["bodies"]["count"]) if every_body else [int(b) for b in drawn]
    if not drawn or sorted(int(b) for b in drawn) != sorted(bodies):
        sys.exit(f"FAIL: {url}: the page drew the bounds of bodies {sorted(drawn)}, expected {list(bodies)}")
    bound = method.split("/")[0]
    name = bound.split(":")[0]
    prepared = {}
    for b in bodies:
        d = drawn[str(b)]
        entry = entry_at(run, b, t)
        if entry is None or d["window"] != entry[:2]:
            sys.exit(f"FAIL: {url}: body {b}: drawn over {d['window']}, the data's window at t is {entry and entry[:2]}")
        if not set(d["kinds"]) <= KINDS[name] or len(d["kinds"]) != len(entry[2]):
            sys.exit(f"FAIL: {url}: body {b}: drew {d['kinds']} for {bound}")
        lo, hi = zip(*(volume_hull(v) for v in entry[2]))
        lo = [min(x[k] for x in lo) for k in range(3)]
        hi = [max(x[k] for x in hi) for k in range(3)]
        if not (close(d["lo"], lo, 1e-9) and close(d["hi"], hi, 1e-9)):
            sys.exit(f"FAIL: {url}: body {b}: drew the box {d['lo']} - {d['hi']}, the data's volumes {lo} - {hi}")
        if module is None or data["shapes"]:
            continue
        w0, w1 = entry[0], entry[1]
        if (w0, w1) not in prepared:
            scene = module.load_scene(scene_path)
            prepared[(w0, w1)] = module.Bound(bound).prepare(scene, w0, w1, acceleration_bound=run["acceleration_bound"])
        box = prepared[(w0, w1)][b]
        equal = name not in ("capsule", "horn_sat")
        tol = 1e-7
        inside = all(d["lo"][k] <= box[0][k] + tol * (1 + abs(box[0][k])) and box[1][k] <= d["hi"][k] + tol * (1 + abs(box[1][k]))
                     for k in range(3))
        same = close(d["lo"], box[0], tol) and close(d["hi"], box[1], tol)
        if not (same if equal else inside):
            sys.exit(f"FAIL: {url}: body {b}: drew the box {d['lo']} - {d['hi']}; Bound({bound!r}).prepare over "
                     f"[{w0}, {w1}] gives {list(box[0])} - {list(box[1])}")
    return len(bodies)


def python_module():
    """The ccdlab Python module of this build, or None (it is optional)."""
    try:
        import ccdlab  # noqa: PLC0415 (optional: CMake puts the build's module on PYTHONPATH)
        return ccdlab
    except ImportError:
        return None


def main():
    ccdlab, source = sys.argv[1], sys.argv[2]
    browser = chromium()
    if not browser:
        print("SKIPPED: no chromium found (Debian's chromium: scripts/install-deps.sh)")
        return SKIP
    module = python_module()
    work = tempfile.mkdtemp(prefix="ccdlab-view-test.")
    try:
        profile = os.path.join(work, "profile")
        results = os.path.join(work, "results.json")
        truth = os.path.join(work, "truth.json")
        page = os.path.join(work, "view.html")
        scene = os.path.join(source, "data", "scenes", "example.json")
        run([ccdlab, "truth", scene, "-o", truth, "--quiet"])
        run([ccdlab, "run", os.path.join(source, "data", "experiments", "example.json"), "-o", results,
             "--truth", truth, "--quiet"])
        run([ccdlab, "view", scene, "--results", results, "--truth", truth, "-o", page])
        with open(results) as f:
            records = json.load(f)["records"]
        with_misses = [r for r in records if r.get("missed_events")]
        if not any(r["method"] == "aabb/sap" for r in with_misses):
            sys.exit("FAIL: aabb/sap should miss contacts in the example experiment")
        # The table for the method and dt the fragment chooses: aabb/sap at its smallest dt
        # with a miss (not the page's default, its largest), and two conservative methods
        # (no misses) with every body's bounds drawn (capsules, horn boxes); each at the
        # first missed contact of aabb/sap, with its pair highlighted.
        first = min((r for r in with_misses if r["method"] == "aabb/sap"), key=lambda r: r["dt"])
        m0 = first["missed_events"][0]
        t_missed = 0.5 * (m0["enter"] + m0["exit"])
        pair = f"&pair={m0['a']}-{m0['b']}"
        checks = [(first, pair)]
        for method in ("capsule/sap", "horn:4/grid"):
            r = max((r for r in records if r["method"] == method), key=lambda r: r["dt"])
            checks.append((r, pair + "&bounds=all"))
        for k, (r, extra) in enumerate(checks):
            method = r["method"]
            url = f"file://{page}#method={method}&dt={r['dt']!r}&t={t_missed!r}{extra}"
            png = os.path.join(work, f"missed-{k}.png")
            dom = load(browser, profile, url, png)
            if dom.body.get("data-status") != "ready":
                sys.exit(f"FAIL: {url}: page status {dom.body.get('data-status')!r}: {dom.body.get('data-error')}")
            if dom.body.get("data-method") != method or float(dom.body.get("data-dt", "nan")) != r["dt"]:
                sys.exit(f"FAIL: {url}: the page chose {dom.body.get('data-method')} at {dom.body.get('data-dt')}")
            shown = [(int(m["data-a"]), int(m["data-b"]), float(m["data-enter"]), float(m["data-exit"]))
                     for m in dom.missed]
            expected = [(m["a"], m["b"], m["enter"], m["exit"]) for m in r.get("missed_events", [])]
            if shown != expected:
                sys.exit(f"FAIL: {url}: the table lists {shown}, the results file {expected}")
            # The page's own motion (the exported pieces, evaluated in the browser) puts the
            # pair in contact in the middle of the truth's contact interval: distance of the
            # centres minus the radii <= 0 (the example's pair overlaps by 0.2 m there).
            gap = float(dom.body.get("data-pair-gap", "nan"))
            if not gap <= 1e-6:
                sys.exit(f"FAIL: {url}: the pair is {gap} m apart in the page, in contact in the truth")
            # The screenshot at the missed contact: the scene drawn, the pair in red.
            other, red = pixel_counts(png, 0.6)
            print(f"{method} at dt = {r['dt']}: {len(shown)} missed contacts in the table, as in the results; "
                  f"pair {m0['a']}-{m0['b']} at t = {t_missed}: gap {gap:.4g} m, {other} drawn pixels, {red} of the pair")
            if other < 5000 or red < 200:
                sys.exit(f"FAIL: the screenshot {png} is blank or lacks the highlighted pair ({other} drawn, {red} red)")
            n = check_volumes(dom, page, url, method, r["dt"], t_missed, "bounds=all" in extra, scene, module)
            print(f"{method}: the bounds of {n} bodies drawn as the C++ bounds computed them")
        # Every other bound, on the example scene and on the rigid example (shaped bodies
        # that turn), each body's bounds drawn: a run per method at dt = 0.25.
        rigid_scene = os.path.join(source, "data", "scenes", "rigid-example.json")
        more = [(os.path.abspath(scene), ["horn_sat:4/sap", "enclosing_sphere/sap", "swept_aabb/sap@earliest:reach=1",
                                          "sphere/brute"]),
                (os.path.abspath(rigid_scene), ["obb_sat/sap", "frame_aabb/sap", "obb/sap"])]
        for k, (scene_path, methods) in enumerate(more):
            experiment = os.path.join(work, f"more-{k}.json")
            with open(experiment, "w") as f:
                json.dump({"format": "ccdlab-experiment/1", "scene": scene_path, "dt": [0.25], "methods": methods}, f)
            more_results = os.path.join(work, f"more-{k}-results.json")
            more_page = os.path.join(work, f"more-{k}.html")
            run([ccdlab, "run", experiment, "-o", more_results, "--quiet"], timeout=600)
            run([ccdlab, "view", scene_path, "--results", more_results, "-o", more_page])
            for method in methods:
                url = f"file://{more_page}#method={method}&dt=0.25&t=0.6&bounds=all"
                dom = load(browser, profile, url, os.path.join(work, "more.png"))
                if dom.body.get("data-status") != "ready":
                    sys.exit(f"FAIL: {url}: page status {dom.body.get('data-status')!r}: {dom.body.get('data-error')}")
                n = check_volumes(dom, more_page, url, method, 0.25, 0.6, True, scene_path, module)
                print(f"{method} on {os.path.basename(scene_path)}: the bounds of {n} bodies drawn as the C++ "
                      "bounds computed them")
        if module is None:
            print("the ccdlab Python module is not importable here: drawn boxes compared with the page's data only")
        check_scenery_page(ccdlab, browser, profile, work)
        # The rigid example and a cloth run's frames load and draw.
        rigid = os.path.join(work, "rigid.html")
        run([ccdlab, "view", os.path.join(source, "data", "scenes", "rigid-example.json"), "-o", rigid])
        frames = os.path.join(work, "frames.json")
        run([ccdlab, "cloth", "drape", "--n", "8", "--steps", "20", "--every", "5", "-o", frames])
        cloth = os.path.join(work, "cloth.html")
        run([ccdlab, "view", frames, "-o", cloth])
        for name, url in (("rigid", f"file://{rigid}#t=0.5"), ("cloth", f"file://{cloth}#t=0.05")):
            png = os.path.join(work, name + ".png")
            dom = load(browser, profile, url, png)
            if dom.body.get("data-status") != "ready":
                sys.exit(f"FAIL: {url}: page status {dom.body.get('data-status')!r}: {dom.body.get('data-error')}")
            other, _ = pixel_counts(png, 0.6)
            print(f"{name}: ready, {other} drawn pixels")
            if other < 2000:
                sys.exit(f"FAIL: the {name} screenshot {png} is blank ({other} drawn pixels)")
        print("ok")
        return 0
    finally:
        if os.environ.get("CCDLAB_KEEP_VIEW_TEST"):
            print("kept", work)
        else:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
