#!/bin/sh
# `maquette export tiles3d --content` of content_benchmark's town and city (city_content.h):
# content_stores writes them as stores (100,000 instances of the built-in prototypes at level
# 16; 20,000 textured Soho-derived buildings at level 15, no overviews; a flat DEM in the same
# cells, as `export tiles3d` requires one), then each export of the content's level runs once
# untimed and RUNS (3) times, with the content and without (the terrain alone: the difference is
# the content's cost); medians of wall and CPU (user + sys) seconds of the program (`wait4`),
# the bytes of the content's GLB files (CELL.LAYER.glb), per object.
# Usage: benchmarks/content/export_timing.sh [BUILD_DIR]
set -eu
BUILD=$(cd "${1:-build}" && pwd)
HERE=$(cd "$(dirname "$0")" && pwd)
RUNS=${RUNS:-3}
[ -f "$HERE/../../../shared/data/buildings/london_soho_buildings_wgs84.geojson" ] ||
  { echo "content: ../shared/data/buildings is absent, skipped"; exit 0; }
for exe in content_stores maquette; do
  [ -x "$BUILD/bin/$exe" ] ||
    { echo "content: $BUILD/bin/$exe not found; build content_stores and maquette_cli" >&2; exit 1; }
done
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
python3 - "$BUILD/bin" "$TMP" "$RUNS" <<'PY'
import json, os, shutil, statistics, subprocess, sys, time

bin_dir, tmp, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
objects = json.loads(subprocess.run([os.path.join(bin_dir, "content_stores"), tmp], check=True,
                                    capture_output=True, text=True).stdout)

def export(store, level, layer, out):
    shutil.rmtree(out, ignore_errors=True)
    argv = [os.path.join(bin_dir, "maquette"), "-q", "export", "tiles3d", store, out, "--dem",
            "dem", "--levels", f"{level}..{level}"] + (["--content", layer] if layer else [])
    t = time.monotonic()
    p = subprocess.Popen(argv, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.monotonic() - t
    if status:
        sys.exit(f"{' '.join(argv)} failed: {p.stderr.read().decode()}")
    return wall, usage.ru_utime + usage.ru_stime

def glb_bytes(out, layer):
    total = files = 0
    for root, _, names in os.walk(out):
        for n in names:
            if n.endswith("." + layer + ".glb"):
                total += os.path.getsize(os.path.join(root, n))
                files += 1
    return total, files

def median_run(path, level, layer, out):
    export(path, level, layer, out)  # warm caches
    samples = [export(path, level, layer, out) for _ in range(runs)]
    return statistics.median(s[0] for s in samples), statistics.median(s[1] for s in samples)

print(f"{'':<28}{'wall s':>8}{'cpu s':>8}{'terrain alone':>15}{'content us/object':>19}"
      f"{'GLB files':>11}{'GLB bytes':>12}{'bytes/object':>14}")
for store, layer, label in (("town", "trees", "100,000 instances"),
                            ("city", "buildings", "20,000 textured buildings")):
    out = os.path.join(tmp, layer)
    path = os.path.join(tmp, store + ".maquette")
    level, n = objects[layer]["level"], objects[layer]["objects"]
    wall, cpu = median_run(path, level, layer, out)
    size, files = glb_bytes(out, layer)
    bare_wall, bare_cpu = median_run(path, level, None, out)
    print(f"{label:<28}{wall:8.2f}{cpu:8.2f}{bare_wall:8.2f} /{bare_cpu:5.2f}"
          f"{1e6 * (wall - bare_wall) / n:10.1f} wall{1e6 * (cpu - bare_cpu) / n:6.1f} cpu"
          f"{files:8d}{size:12d}{size / n:14.1f}")
PY
