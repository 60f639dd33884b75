#!/usr/bin/env bash
# Our panorama rasterizer and Mesa's OSMesa (llvmpipe) on the same mesh, side by side: the 2 M
# triangles of render_benchmark's hills, in the camera's frame, into the same 2000 x 2000 picture.
# Installs Debian's libosmesa6-dev when missing (apt-get: run as root), builds render_benchmark
# and osmesa_render.c, then prints, for 1 and 2 threads, the wall time per picture of ours (Google
# Benchmark's real time, the least of REPETITIONS) and of OSMesa (the least of as many frames),
# the ratio OSMesa / ours, and the pixels each drew; on 1 thread also the CPU times (ours: the
# calling thread's, which does all the work then; OSMesa: the process's, LP_NUM_THREADS=0), the
# measure to trust on a loaded machine. Ours fills per pixel the triangle, its depth and two
# barycentric weights; OSMesa a colour and a 32-bit depth.
# Usage: benchmarks/render/osmesa_side_by_side.sh [BUILD_DIR (default build)] [REPETITIONS (5)]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
repetitions=${2:-5}
if ! dpkg-query -W -f='${Status}' libosmesa6-dev 2>/dev/null | grep -q "install ok installed"; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q libosmesa6-dev >/dev/null
fi
cmake --build "$build" --target render_benchmark >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cc -O2 -o "$work/osmesa_render" "$root/benchmarks/render/osmesa_render.c" -lOSMesa
"$build/bin/render_benchmark" --write-mesh="$work/mesh.bin"
"$build/bin/render_benchmark" --benchmark_filter=BM_Rasterize --benchmark_format=csv \
  --benchmark_repetitions="$repetitions" 2>/dev/null >"$work/ours.csv"
for threads in 1 2; do
  # The least real and CPU times (ms) of the repetitions and the pixels drawn, from the CSV.
  read -r ours ours_cpu drawn < <(awk -F, -v arg="BM_Rasterize/$threads/real_time" '
    $1 == "\"" arg "\"" {
      if (best == "" || $3 + 0 < best) best = $3 + 0
      if (cpu == "" || $4 + 0 < cpu) cpu = $4 + 0
      drawn = $(NF - 1)
    }
    END { printf "%.1f %.1f %d\n", best, cpu, drawn }' "$work/ours.csv")
  # llvmpipe: 0 rasterizes in the calling thread, N > 0 in N threads of its own.
  osmesa=$(LP_NUM_THREADS=$((threads == 1 ? 0 : threads)) "$work/osmesa_render" "$work/mesh.bin" \
    "$repetitions")
  read -r osmesa_ms osmesa_cpu osmesa_drawn < <(echo "$osmesa" | tr '=' ' ' | awk '{print $2, $4, $6}')
  awk -v t="$threads" -v a="$ours" -v ac="$ours_cpu" -v d="$drawn" -v b="$osmesa_ms" \
    -v bc="$osmesa_cpu" -v o="$osmesa_drawn" 'BEGIN {
      printf "%d thread(s): wall: ours %.1f ms, OSMesa %.1f ms, OSMesa / ours %.2f", t, a, b, b / a
      if (t == 1) printf "; CPU: ours %.1f ms, OSMesa %.1f ms, OSMesa / ours %.2f", ac, bc, bc / ac
      printf "; pixels drawn: ours %d, OSMesa %d\n", d, o
    }'
done
