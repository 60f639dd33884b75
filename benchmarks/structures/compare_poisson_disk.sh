#!/bin/sh
# Side by side: our blue noise (poisson_disk.h, what structures.vegetation places) against public
# Poisson-disk samplers, on the same square with the same minimum distance, every output checked
# by the same k-d tree:
#   ours   vegetation_points: poisson_disk over [0, SIDE)^2 as one window, r = 0.769 x spacing
#          (one plant per spacing^2); and the paper's random placement (vegetation_random.h),
#          round(area / spacing^2) plants, which keeps no distance;
#   npm    poisson-disk-sampling 2.3.1 (Bridson, candidates in [r, 2 r), 30 tries) and
#          fast-2d-poisson-disk-sampling 1.0.3 (30 tries), pinned in node/package-lock.json and
#          installed by `npm ci` into BUILD_DIR, run by node/samplers.mjs in one node process:
#          at our r (they pack more plants into the square), then each at the r giving it one
#          plant per spacing^2 as ours (the same cover: plants per second compare as area per
#          second);
#   SciPy  scipy.stats.qmc.PoissonDisk (Debian python3-scipy 1.10, installed with apt-get when
#          missing and run as root) with fill_space(), on a smaller square (SCIPY_SIDE, ~100,000
#          plants: it places ~2,000 a second), beside ours on that square.
# Each sampler times itself in its own process (CPU seconds, user + system, of the placement only;
# writing the points is not timed), RUNS times (SciPy once); medians. The check, the same for
# all: every point in the square, the nearest neighbour of each (scipy.spatial.cKDTree), the
# smallest distance over r (>= 1 for blue noise, up to a relative 1e-9 for SciPy's unit-square
# points scaled to metres), the plants per spacing^2, and the fraction of plants with a
# neighbour closer than half the spacing (issue 17's measure of the paper's flaw; a Poisson
# process: 1 - exp(-pi / 4) = 54.4 %). Then the whole operator (vegetation_benchmark's
# BM_VegetationCell: placement, ground, colour, look) per CPU second, the issue's goal.
# Usage: benchmarks/structures/compare_poisson_disk.sh [BUILD_DIR]
#        (SIDE=2000 SPACING=2 SCIPY_SIDE=632 RUNS=3 by default)
set -eu
BUILD=$(cd "${1:-build}" && pwd)
HERE=$(cd "$(dirname "$0")" && pwd)
SIDE=${SIDE:-2000} SPACING=${SPACING:-2} SCIPY_SIDE=${SCIPY_SIDE:-632} RUNS=${RUNS:-3}
PYTHON=/usr/bin/python3  # Debian's, where python3-scipy installs
for bin in vegetation_points vegetation_benchmark; do
  [ -x "$BUILD/bin/$bin" ] ||
    { echo "vegetation: $BUILD/bin/$bin not found; build the $bin target" >&2; exit 1; }
done
if ! "$PYTHON" -c "import scipy.stats, scipy.spatial" 2>/dev/null; then
  [ "$(id -u)" -eq 0 ] ||
    { echo "vegetation: SciPy missing (apt-get install python3-scipy as root)" >&2; exit 1; }
  apt-get install -y -qq python3-scipy >/dev/null 2>&1 ||
    { apt-get update -qq && apt-get install -y -qq python3-scipy >/dev/null; }
fi
command -v npm >/dev/null 2>&1 || { echo "vegetation: npm not found" >&2; exit 1; }

NODE_DIR=$BUILD/benchmarks/structures/node
"$HERE/../npm_peers.sh" "$HERE/node" "$NODE_DIR" samplers.mjs

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
"$PYTHON" - "$BUILD/bin" "$NODE_DIR" "$TMP" "$SIDE" "$SPACING" "$SCIPY_SIDE" "$RUNS" <<'PY'
import json, math, os, statistics, subprocess, sys, time
import numpy as np
from scipy.spatial import cKDTree
from scipy.stats import qmc

bin_dir, node_dir, tmp = sys.argv[1:4]
side, spacing, scipy_side = map(float, sys.argv[4:7])
runs = int(sys.argv[7])

def run(argv):
    return json.loads(subprocess.run(argv, check=True, capture_output=True, text=True).stdout)

def ours(placement, square):
    path = os.path.join(tmp, f"ours-{placement}-{square:g}.bin")
    out = run([os.path.join(bin_dir, "vegetation_points"), placement, str(square), str(spacing),
               str(runs), path])
    return np.fromfile(path, "<f8").reshape(-1, 2), out["cpu_s"], out["min_distance"]

rows = []  # (label, square, points, cpu seconds per run, r or None)
for square in (side, scipy_side):
    points, cpu, r = ours("poisson", square)
    rows.append(("ours: poisson_disk", square, points, cpu, r))
    if square == side:
        points, cpu, _ = ours("random", square)
        rows.append(("ours: the paper's random placement", square, points, cpu, None))
        peers = run(["node", os.path.join(node_dir, "samplers.mjs"), str(square), repr(r),
                     str(runs), tmp])
        def peer_points(name):
            return np.fromfile(os.path.join(tmp, name + ".bin"), "<f8").reshape(-1, 2)
        for name, p in peers.items():
            rows.append((f"npm {name}", square, peer_points(name), p["cpu_s"], r))
        # The same again at the r giving the peer one plant per spacing^2, as ours: the same
        # cover of the square at the same density.
        for name, p in peers.items():
            r_same = r * math.sqrt(p["count"] * spacing**2 / square**2)
            again = run(["node", os.path.join(node_dir, "samplers.mjs"), str(square),
                         repr(r_same), str(runs), tmp, name])[name]
            rows.append((f"npm {name}, r {r_same:.3f}", square, peer_points(name),
                         again["cpu_s"], r_same))
    else:
        start = time.process_time()
        unit = qmc.PoissonDisk(d=2, radius=r / square, seed=1).fill_space()
        rows.append(("SciPy qmc.PoissonDisk", square, unit * square,
                     [time.process_time() - start], r))

print(f"spacing {spacing:g} m (one plant per spacing^2), r = {rows[0][4]:.4f} m; CPU seconds of "
      f"the placement in its own process, median of {runs} runs (SciPy: 1)")
print(f"{'sampler':<46}{'square m':>9}{'plants':>10}{'per s^2':>9}{'cpu s':>9}{'plants/s':>11}"
      f"{'min d/r':>9}{'< s/2':>8}")
rate, failed = {}, []
for label, square, p, cpu, r in rows:
    d = cKDTree(p).query(p, k=2)[0][:, 1]  # each plant's nearest neighbour
    c = statistics.median(cpu)
    rate[(label, square)] = len(p) / c
    if not np.all((p >= 0) & (p < square)):
        failed.append(f"{label}: points outside the square")
    if r and d.min() < r * (1 - 1e-9):
        failed.append(f"{label}: {np.sum(d < r * (1 - 1e-9))} plants closer than r to another")
    print(f"{label:<46}{square:9g}{len(p):10d}{len(p) * spacing**2 / square**2:9.3f}{c:9.3f}"
          f"{len(p) / c / 1e6:10.3f}M" + (f"{d.min() / r:9.5f}" if r else f"{'-':>9}") +
          f"{100 * np.mean(d < spacing / 2):7.1f}%")
for (label, square), v in rate.items():
    if not label.startswith("ours"):
        print(f"ours / {label}: {rate[('ours: poisson_disk', square)] / v:.1f}x plants per "
              f"CPU second")
if failed:
    sys.exit("vegetation: " + "; ".join(failed))

# (the operator logs on standard output: the results go through a file)
bench_json = os.path.join(tmp, "bench.json")
subprocess.run([os.path.join(bin_dir, "vegetation_benchmark"), "--benchmark_filter=BM_VegetationCell",
                f"--benchmark_repetitions={runs}", f"--benchmark_out={bench_json}",
                "--benchmark_out_format=json"], check=True, capture_output=True)
bench = json.load(open(bench_json))
per_s = [b["items_per_second"] for b in bench["benchmarks"] if b["run_type"] == "iteration"]
print(f"structures.vegetation on one level-12 cell (placement, ground, colour, look): "
      f"{statistics.median(per_s) / 1e6:.2f} M plants per CPU second, median of {runs} "
      f"({', '.join(f'{v / 1e6:.2f}' for v in per_s)}; issue 17: >= 1 M)")
PY
