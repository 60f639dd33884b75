#!/bin/sh
# Paired comparison of two builds' `maquette ingest` on the inputs of compare.sh: runs them
# alternately RUNS (25) times after one untimed run each, and prints each build's median wall
# and CPU (user + system) time. On a machine that other work shares, the alternation lets both
# builds see the same load, so the difference of the medians holds where absolute times do not.
# Usage: benchmarks/ingest/paired.sh BEFORE_BUILD AFTER_BUILD
set -eu
[ $# -eq 2 ] || { echo "usage: $0 BEFORE_BUILD AFTER_BUILD" >&2; exit 2; }
HERE=$(cd "$(dirname "$0")" && pwd)
DATA=${MAQUETTE_SHARED_DATA:-$HERE/../../../shared/data}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
python3 - "$1" "$2" "${RUNS:-25}" "$DATA" "$TMP" <<'PY'
import os, resource, statistics, subprocess, sys, time
before, after, runs, data, tmp = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4], sys.argv[5]
inputs = {
    "srtm_rainier": ["--as", "dem", "--resampling", "bilinear", f"{data}/srtm3/mt_rainier_90m.tif"],
    "landsat_b4": ["--as", "imagery", "--resampling", "bilinear", f"{data}/zion/landsat_b4.tif"],
    "landsat_b4_level12": ["--as", "imagery", "--resampling", "bilinear", "--level", "12",
                           f"{data}/zion/landsat_b4.tif"],
}
print(f"load average {os.getloadavg()[0]:.2f}, median of {runs}")
for name, args in inputs.items():
    if not os.path.exists(args[-1]):
        print(f"{name}: {args[-1]} is absent, skipped")
        continue
    times = {before: [], after: []}
    for i in range(runs + 1):  # the first round warms the file cache
        for build in (before, after):
            store = f"{tmp}/s.mqt"
            for f in (store, store + "-wal", store + "-shm"):
                if os.path.exists(f):
                    os.remove(f)
            r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
            t = time.monotonic()
            subprocess.run([f"{build}/bin/maquette", "-q", "ingest", store, "--layer", "l"] + args,
                           check=True)
            wall = time.monotonic() - t
            r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
            if i:
                times[build].append((wall, r1.ru_utime + r1.ru_stime - r0.ru_utime - r0.ru_stime))
    for build in (before, after):
        w = statistics.median(x[0] for x in times[build]) * 1000
        c = statistics.median(x[1] for x in times[build]) * 1000
        print(f"{name:20s} {build}: wall {w:6.1f} ms  cpu {c:6.1f} ms")
PY
