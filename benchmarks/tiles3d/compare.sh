#!/bin/sh
# Side by side: `maquette export tiles3d` (Draco-compressed GLB) against `draco_transcoder`
# (Debian package draco) compressing the same meshes, at the same quantization (positions 14,
# texture coordinates 10, normals 10 bits; both at Draco's default compression level, speed 3 =
# transcoder level 7). The DEM is the SRTM Mt Rainier 1201x1201 tile, ingested once into a temporary
# store; the export covers the DEM layer's own level only (--levels L..L). The transcoder's input
# is the uncompressed export of the same levels (--no-draco); it runs once per GLB file and its
# times, CPU and sizes are summed over all files. Like with like, the script prints:
#   ours          the Draco export, whole command (store reads, meshing, encoding, writing)
#   ours - plain  the Draco export minus the uncompressed export: our compression cost alone
#   transcoder    sum over files of draco_transcoder (GLB parse, encoding, writing)
# Each program runs once untimed (warm caches), then RUNS (3) times; medians of wall and CPU
# (user + sys) time, the largest peak RSS (per process, from wait4, as /usr/bin/time -v reports
# it), and the total bytes of the GLB files (tileset.json excluded). Then the export's memory per
# tile in flight: its peak RSS with one worker thread (pinned to one CPU) and with all, against
# the program's own (`maquette info`).
# Usage: benchmarks/tiles3d/compare.sh [BUILD_DIR]
set -eu
BUILD=${1:-build}
HERE=$(cd "$(dirname "$0")" && pwd)
DATA=${MAQUETTE_SHARED_DATA:-$HERE/../../../shared/data}
MAQUETTE=$BUILD/bin/maquette
TRANSCODER=${DRACO_TRANSCODER:-draco_transcoder}
RUNS=${RUNS:-3}
QP=14 QT=10 QN=10
SRC=$DATA/srtm3/mt_rainier_90m.tif

[ -f "$SRC" ] || { echo "tiles3d: $SRC is absent (no ../shared/data), skipped"; exit 0; }
[ -x "$MAQUETTE" ] || { echo "tiles3d: $MAQUETTE not found; build maquette_cli first" >&2; exit 1; }
command -v "$TRANSCODER" >/dev/null 2>&1 ||
  { echo "tiles3d: $TRANSCODER not found (apt-get install draco), skipped"; exit 0; }

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
STORE=$TMP/rainier.mqt
"$MAQUETTE" -q ingest "$STORE" --layer dem --as dem "$SRC"
LEVEL=$("$MAQUETTE" info "$STORE" --json | python3 -c '
import json, sys
print(next(l["level"] for l in json.load(sys.stdin)["layers"] if l["name"] == "dem"))')

python3 - "$MAQUETTE" "$TRANSCODER" "$STORE" "$LEVEL" "$TMP" "$RUNS" "$QP" "$QT" "$QN" <<'PY'
import os, shutil, statistics, sys, time

maquette, transcoder, store, level, tmp = sys.argv[1:6]
runs, qp, qt, qn = map(int, sys.argv[6:10])

def run(argv):
    """Runs argv (stdout discarded); returns (wall s, user+sys s, peak RSS KiB)."""
    t = time.monotonic()
    devnull = os.open(os.devnull, os.O_WRONLY)
    pid = os.posix_spawnp(argv[0], argv, os.environ, file_actions=[(os.POSIX_SPAWN_DUP2, devnull, 1)])
    os.close(devnull)
    _, status, ru = os.wait4(pid, 0)
    wall = time.monotonic() - t
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"failed: {' '.join(argv)}")
    return wall, ru.ru_utime + ru.ru_stime, ru.ru_maxrss

def glbs(root):
    return sorted(os.path.relpath(os.path.join(d, f), root)
                  for d, _, fs in os.walk(root) for f in fs if f.endswith(".glb"))

def size(root):
    return sum(os.path.getsize(os.path.join(root, f)) for f in glbs(root))

def export(out, *extra):
    shutil.rmtree(out, ignore_errors=True)
    return run([maquette, "-q", "export", "tiles3d", store, out, "--dem", "dem",
                "--levels", f"{level}..{level}", "--position-bits", str(qp),
                "--texcoord-bits", str(qt), "--normal-bits", str(qn), *extra])

def transcode(src, out):
    shutil.rmtree(out, ignore_errors=True)
    wall = cpu = rss = 0
    for f in glbs(src):
        os.makedirs(os.path.dirname(os.path.join(out, f)), exist_ok=True)
        w, c, r = run([transcoder, "-i", os.path.join(src, f), "-o", os.path.join(out, f),
                       "-qp", str(qp), "-qt", str(qt), "-qn", str(qn)])
        wall, cpu, rss = wall + w, cpu + c, max(rss, r)
    return wall, cpu, rss

ours_d, plain_d, tc_d = (os.path.join(tmp, n) for n in ("draco", "plain", "transcoded"))
samples = {"ours": [], "plain": [], "transcoder": []}
for i in range(runs + 1):  # the first round warms caches and is not counted
    r = {"ours": export(ours_d), "plain": export(plain_d, "--no-draco")}
    r["transcoder"] = transcode(plain_d, tc_d)
    if i:
        for k, v in r.items():
            samples[k].append(v)

def med(k, j): return statistics.median(s[j] for s in samples[k])
def peak(k): return max(s[2] for s in samples[k]) / 1024

# Memory against tiles in flight (one per worker thread): the program alone (`info`), and the
# Draco export on one CPU (one worker) and on all of this process's CPUs.
cpus = sorted(os.sched_getaffinity(0))
alone = run([maquette, "info", store])[2] / 1024
os.sched_setaffinity(0, cpus[:1])
one_cpu = max(export(ours_d)[2] for _ in range(runs)) / 1024
os.sched_setaffinity(0, cpus)

files = glbs(ours_d)
assert files == glbs(tc_d), "the two exports hold different GLB files"
sizes = {"ours": size(ours_d), "plain": size(plain_d), "transcoder": size(tc_d)}
print(f"DEM level {level}, {len(files)} GLB files, quantization {qp}/{qt}/{qn}, "
      f"median of {runs} runs")
print(f"{'':<14}{'wall s':>9}{'cpu s':>9}{'peak MiB':>10}{'GLB bytes':>12}")
for k, label in (("plain", "plain export"), ("ours", "ours (draco)"),
                 ("transcoder", "transcoder")):
    print(f"{label:<14}{med(k, 0):9.3f}{med(k, 1):9.3f}{peak(k):10.0f}{sizes[k]:12d}")
enc_w, enc_c = med("ours", 0) - med("plain", 0), med("ours", 1) - med("plain", 1)
print(f"{'ours - plain':<14}{enc_w:9.3f}{enc_c:9.3f}")
tw, tc = med("transcoder", 0), med("transcoder", 1)
print(f"ratios ours/transcoder: wall {med('ours', 0) / tw:.2f}x, cpu {med('ours', 1) / tc:.2f}x "
      f"(whole export); encoding only wall {enc_w / tw:.2f}x, cpu {enc_c / tc:.2f}x; "
      f"size {sizes['ours'] / sizes['transcoder']:.3f}x; "
      f"peak RSS {peak('ours') / peak('transcoder'):.1f}x")
print(f"peak RSS: program alone {alone:.0f} MiB; Draco export with 1 worker {one_cpu:.0f} MiB, "
      f"with {len(cpus)} {peak('ours'):.0f} MiB: "
      f"{(peak('ours') - alone) / len(cpus):.0f} MiB per tile in flight")
PY
