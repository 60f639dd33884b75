#!/bin/sh
# Program start side by side: `maquette --version` against `gdalinfo --version` (a GDAL program
# loading the same ~120 libraries), alternated RUNS (40) times; prints the median wall times and
# their ratio. Start-up is mostly the dynamic loader resolving ~60,000 symbols (see
# cmake/StartupLibraries.cmake).
# Usage: benchmarks/startup/compare.sh [BUILD_DIR]
set -eu
BUILD=${1:-build}
python3 - "$BUILD/bin/maquette" "${RUNS:-40}" <<'PY'
import statistics, subprocess, sys, time
programs = {"maquette --version": [sys.argv[1], "--version"],
            "gdalinfo --version": ["gdalinfo", "--version"]}
seconds = {name: [] for name in programs}
for _ in range(int(sys.argv[2])):
    for name, command in programs.items():
        t = time.monotonic()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        seconds[name].append(time.monotonic() - t)
median = {name: statistics.median(s) for name, s in seconds.items()}
for name, m in median.items():
    print(f"{name:20s} {m * 1e3:6.1f} ms (median of {len(seconds[name])})")
print(f"ratio gdalinfo / maquette: {median['gdalinfo --version'] / median['maquette --version']:.2f}x")
PY
