#!/bin/sh
# Side by side: `maquette ingest` against `gdalwarp -multi -wo NUM_THREADS=ALL_CPUS` to
# +proj=rhealpix, on the same sources, with the same resampling and the same number of output
# samples (gdalwarp's grid: the footprint's extent at our pixel size, scaled to our sample count),
# both on all cores. Each program runs once untimed (warm file cache, both alike), then RUNS (3)
# times alternately; prints the median wall and CPU (user + system) times, the largest peak RSS
# and the ratios of the medians.
# Usage: benchmarks/ingest/compare.sh [BUILD_DIR]
set -eu
BUILD=${1:-build}
HERE=$(cd "$(dirname "$0")" && pwd)
DATA=${MAQUETTE_SHARED_DATA:-$HERE/../../../shared/data}
MAQUETTE=$BUILD/bin/maquette
RUNS=${RUNS:-3}
RHP='+proj=rhealpix +ellps=WGS84 +north_square=0 +south_square=0'
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# Runs a command; prints "SECONDS CPU_SECONDS PEAK_RSS_MIB": wall time, then the command's own
# user + system time and peak RSS (rusage). CPU time is the steadier measure on a busy machine.
timed() {
  python3 - "$@" <<'PY'
import resource, subprocess, sys, time
t = time.monotonic()
subprocess.run(sys.argv[1:], check=True)
dt = time.monotonic() - t
r = resource.getrusage(resource.RUSAGE_CHILDREN)
print(f"{dt:.3f} {r.ru_utime + r.ru_stime:.3f} {r.ru_maxrss / 1024:.0f}")
PY
}

# median FILE: the median seconds, the median CPU seconds and the largest peak RSS of the lines
# of FILE.
median() {
  python3 - "$1" <<'PY'
import statistics, sys
runs = [tuple(map(float, l.split())) for l in open(sys.argv[1])]
print(f"{statistics.median(r[0] for r in runs):.3f} {statistics.median(r[1] for r in runs):.3f}"
      f" {max(r[2] for r in runs):.0f}")
PY
}

# bench NAME SOURCE AS RESAMPLING [MAQUETTE OPTIONS...]
bench() {
  name=$1 src=$2 as=$3 rs=$4
  shift 4
  [ -f "$src" ] || { echo "$name: $src is absent, skipped"; return; }
  store=$TMP/$name.mqt
  "$MAQUETTE" -q ingest "$store" --layer l --as "$as" --resampling "$rs" "$@" "$src"  # warm-up
  info=$("$MAQUETTE" info "$store" --json)
  level_tiles=$(python3 -c '
import json, sys
l = json.loads(sys.argv[1])["layers"][0]
print(l["level"], l["tile_size"], l["tiles"])' "$info")
  level=${level_tiles%% *} tiles=${level_tiles##* } n=${level_tiles#* } n=${n%% *}
  samples=$((tiles * n * n))
  pixel=$("$MAQUETTE" cells levels --tile-size "$n" --json |
          python3 -c "import json,sys; print(json.load(sys.stdin)[$level]['plane_side_m'] / $n)")
  gdalwarp -q -overwrite -of VRT -t_srs "$RHP" -tr "$pixel" "$pixel" "$src" "$TMP/probe.vrt"
  gsize=$(python3 -c '
import json, math, subprocess, sys
info = json.loads(subprocess.check_output(["gdalinfo", "-json", sys.argv[1]]))
w, h = info["size"]; k = math.sqrt(int(sys.argv[2]) / (w * h))
print(round(w * k), round(h * k))' "$TMP/probe.vrt" "$samples")
  gw=${gsize% *} gh=${gsize#* }
  gdalwarp -q -overwrite -multi -wo NUM_THREADS=ALL_CPUS -t_srs "$RHP" -ts "$gw" "$gh" -r "$rs" \
    "$src" "$TMP/$name.tif"  # warm-up
  : >"$TMP/m" && : >"$TMP/g"
  i=0
  while [ $i -lt "$RUNS" ]; do
    rm -f "$store"
    timed "$MAQUETTE" -q ingest "$store" --layer l --as "$as" --resampling "$rs" "$@" "$src" \
      >>"$TMP/m"
    timed gdalwarp -q -overwrite -multi -wo NUM_THREADS=ALL_CPUS -t_srs "$RHP" -ts "$gw" "$gh" \
      -r "$rs" "$src" "$TMP/$name.tif" >>"$TMP/g"
    i=$((i + 1))
  done
  set -- $(median "$TMP/m") $(median "$TMP/g")
  python3 -c '
import sys
name, ms, mc, mm, gs, gc, gm, samples, gw, gh, level, tiles, runs = sys.argv[1:]
print(f"{name}: level {level}, {tiles} tiles, {int(samples)/1e6:.2f} M samples (gdalwarp {gw}x{gh} = {int(gw)*int(gh)/1e6:.2f} M), median of {runs}")
print(f"  maquette ingest {float(ms):7.3f} s  cpu {float(mc):7.3f} s  peak {mm:>5} MiB")
print(f"  gdalwarp -multi {float(gs):7.3f} s  cpu {float(gc):7.3f} s  peak {gm:>5} MiB")
print(f"  ratio gdalwarp / maquette: {float(gs) / float(ms):.2f}x (cpu {float(gc) / float(mc):.2f}x)")' \
    "$name" "$1" "$2" "$3" "$4" "$5" "$6" "$samples" "$gw" "$gh" "$level" "$tiles" "$RUNS"
}

nproc | sed 's/^/cores: /'
bench srtm_rainier "$DATA/srtm3/mt_rainier_90m.tif" dem bilinear
bench landsat_b4 "$DATA/zion/landsat_b4.tif" imagery bilinear
# The same scene at the next finer level (4x the samples): fixed costs (program start, planning,
# overviews) weigh less.
bench landsat_b4_level12 "$DATA/zion/landsat_b4.tif" imagery bilinear --level 12
