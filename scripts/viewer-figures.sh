#!/usr/bin/env bash
# The viewer's figures (docs/viewer.md, README.md): the screenshot of `ccdlab view` at a
# contact that aabb/sap missed in the tunnelling scene, and the page's frame time at
# 10,000 bodies measured in headless chromium (software WebGL: SwiftShader).
# Run after ./scripts/build.sh; needs Debian's chromium (scripts/install-deps.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CCDLAB_BUILD_DIR:-$root/build}
out="$root/results/viewer"
mkdir -p "$out" "$root/docs/images"
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
browser=(chromium --headless --use-gl=angle --use-angle=swiftshader --enable-unsafe-swiftshader
         --user-data-dir="$profile" --hide-scrollbars --no-first-run)
[ "$(id -u)" -ne 0 ] || browser+=(--no-sandbox)

# The screenshot: the bullets scene of the tunnelling study, aabb/sap at dt = 0.019 s.
"$build/ccdlab" scene bullets bodies=1000 bullets=50 seed=1 -o "$out/bullets.json" >/dev/null
cat >"$out/bullets-experiment.json" <<JSON
{"format": "ccdlab-experiment/1", "name": "bullets-view", "scene": "bullets.json",
 "dt": [0.019], "methods": ["aabb/sap", "capsule/sap"], "list_missed": true}
JSON
"$build/ccdlab" truth "$out/bullets.json" -o "$out/bullets-truth.json" --quiet
"$build/ccdlab" run "$out/bullets-experiment.json" -o "$out/bullets-results.json" --truth "$out/bullets-truth.json" --quiet >/dev/null
# From the folder, so that the page names the files without a path.
(cd "$out" && "$build/ccdlab" view bullets.json --results bullets-results.json --truth bullets-truth.json \
  -o bullets.html >/dev/null)
# The first missed contact after t = 0.4 (the one the tunnelling GIF shows is among them).
pair=$(/usr/bin/python3 - "$out/bullets-results.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
rec = next(x for x in r["records"] if x["method"] == "aabb/sap")
m = next(e for e in rec["missed_events"] if e["enter"] > 0.4)
print(f"t={(m['enter'] + m['exit']) / 2!r}&pair={m['a']}-{m['b']}")
PY
)
"${browser[@]}" --window-size=1200,720 --screenshot="$root/docs/images/viewer.png" \
  "file://$out/bullets.html#method=aabb/sap&dt=0.019&$pair" 2>/dev/null
echo "$root/docs/images/viewer.png (#method=aabb/sap&dt=0.019&$pair)"

# Frame time at 10,000 bodies: the page renders 30 frames spread over the horizon, each
# finished (a pixel read), and reports the median (<output id="bench">): spheres drawn as
# points (the default above 2,000 spheres), then as instanced meshes.
"$build/ccdlab" scene gas bodies=10000 seed=1 -o "$out/gas-10k.json" >/dev/null
"$build/ccdlab" view "$out/gas-10k.json" -o "$out/gas-10k.html" >/dev/null
for spheres in points mesh; do
  echo -n "spheres=$spheres: "
  "${browser[@]}" --window-size=1200,720 --dump-dom "file://$out/gas-10k.html#bench=30&spheres=$spheres" 2>/dev/null |
    grep -o '<output id="bench"[^>]*>[^<]*' | sed 's/.*>//'
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
ls -la "$out/gas-10k.html" | awk '{print "page size: " $5 " bytes"}'
