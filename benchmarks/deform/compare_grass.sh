#!/usr/bin/env bash
# The deform examples' edits beside GRASS on the same data, each on a region of 16 tiles of
# 256 x 256 samples (1,048,576 samples of 8.8 m, level 12), in one run:
# - deform.features (examples/deform-virgin-river.json: the Virgin River, 7.4 km) through
#   `maquette run`, against r.carve on the same DEM exported to UTM 12N at 8.8 m with the same
#   stream (20 m wide, 3 m deep);
# - deform.water (examples/deform-rainier.json: the lake behind the road embankment) through
#   `maquette run`, against r.lake on the same dammed DEM exported to UTM 10N at 8.8 m, at the
#   level deform.water found and a seed in the lake (by default its deepest point, -121.6741
#   46.5959: another lake of the region, or another dam, wants a seed of its own).
# Prints the step's time as the run logs it, the whole program's wall and CPU time, GRASS's
# command's (not its import and export), and the ratios. Needs ../shared/data and grass-core.
# Usage: benchmarks/deform/compare_grass.sh BUILD_DIR [SEED_LON SEED_LAT]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
examples=$root/examples shared=$root/../shared
maquette=$(realpath "$1")/bin/maquette
seed_lon=${2:--121.6741} seed_lat=${3:-46.5959}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# pipeline NAME BBOX OPS: the example's steps of the operators OPS (a JSON array) on the region
# BBOX (a JSON array), its store in the temporary directory, its sources absolute.
pipeline() {
  jq --argjson bbox "$2" --argjson ops "$3" --arg store "$tmp/$1.mqt" --arg shared "$shared" \
    --arg examples "$examples" '
    .store = $store | .region.bbox = $bbox
    | .steps |= map(select(.op as $o | $ops | index($o))
        | if .op == "ingest" then
            .params.sources |= map(if startswith("../../shared") then $shared + ltrimstr("../../shared")
                                   else $examples + "/" + . end)
          else . end)' "$examples/$1.json" >"$tmp/$1-$(echo "$3" | tr -dc a-z).json"
  echo "$tmp/$1-$(echo "$3" | tr -dc a-z).json"
}

# timed_run PIPELINE OP: runs it; prints "OP seconds STEP wall WALL cpu CPU" (the step as the
# run logs it, the program's wall and CPU time).
timed_run() {
  local times step
  times=$({ TIMEFORMAT='%R %U %S'; time "$maquette" run "$1" 2>"$tmp/log" >/dev/null; } 2>&1)
  step=$(sed -n "s/.*step [0-9]* ($2): .* in \([0-9.]*\) s$/\1/p" "$tmp/log")
  read -r wall user sys <<<"$times"
  printf '%s seconds %s wall %s cpu %.3f\n' "$2" "$step" "$wall" "$(echo "$user + $sys" | bc)"
}

# seconds LINE, cpu LINE: the wall time after "seconds", the CPU time (the sum of the values
# after "cpu") in a timing line.
seconds() { awk '{for (i = 1; i < NF; ++i) if ($i == "seconds") print $(i + 1)}' <<<"$1"; }
cpu() { awk '{for (i = 1; i < NF; ++i) if ($i == "cpu") { s = $(i + 1); if ($(i + 2) ~ /^[0-9.]+$/) s += $(i + 2); print s }}' <<<"$1"; }

# ratio OURS GRASS: the wall times' ratio (our step's) and the CPU times' (our whole program's,
# start, module loading and store included, against the GRASS command's).
ratio() {
  printf 'ratio wall (step / command) %.2f, cpu (program / command) %.2f\n' \
    "$(echo "scale=4; $(seconds "$1") / $(seconds "$2")" | bc)" \
    "$(echo "scale=4; $(cpu "$1") / $(cpu "$2")" | bc)"
}

echo "== deform.features beside r.carve (Virgin River)"
virgin_bbox='[-113.04, 37.15, -112.97, 37.22]'
"$maquette" -q run "$(pipeline deform-virgin-river "$virgin_bbox" '["ingest"]')"
echo "region: $("$maquette" cells cover --bbox -113.04 37.15 -112.97 37.22 --level 12 | wc -l) tiles of 65,536 samples"
ours=$(timed_run "$(pipeline deform-virgin-river "$virgin_bbox" '["deform.features"]')" deform.features)
echo "$ours"
"$maquette" -q export gtiff "$tmp/deform-virgin-river.mqt" "$tmp/zion.tif" --layer dem \
  --crs EPSG:32612 --resolution 8.8 --bbox -113.04 37.15 -112.97 37.22
ogr2ogr -f GeoJSON -dim XY -t_srs EPSG:32612 "$tmp/stream.geojson" \
  "$examples/deform-virgin-river/river.geojson"
grass=$("$here/../grass_job.sh" "$tmp/zion.tif" "$tmp/rcarve.tif" <<JOB
v.in.ogr -o --quiet input="$tmp/stream.geojson" output=stream
TIMEFORMAT='r.carve seconds %R cpu %U %S'
time r.carve --quiet raster=dem vector=stream output=carved width=20 depth=3
r.out.gdal --quiet -f input=carved output="$tmp/rcarve.tif" format=GTiff type=Float32
JOB
)
echo "$grass"
echo "deform.features / r.carve: $(ratio "$ours" "$grass")"

echo "== deform.water beside r.lake (Rainier)"
rainier_bbox=$(jq -c .region.bbox "$examples/deform-rainier.json")
"$maquette" -q run "$(pipeline deform-rainier "$rainier_bbox" '["ingest", "deform.features"]')"
ours=$(timed_run "$(pipeline deform-rainier "$rainier_bbox" '["deform.water"]')" deform.water)
echo "$ours"
"$maquette" -q run "$(pipeline deform-rainier "$rainier_bbox" '["deform.water_bodies"]')"
level=$(sqlite3 "$tmp/deform-rainier.mqt" "select data from artifacts where name = 'lakes'" |
  jq '.[0].level')
read -r x y _ < <(echo "$seed_lon $seed_lat" | gdaltransform -s_srs EPSG:4326 -t_srs EPSG:32610)
read -r w s e n < <(jq -r 'map(tostring) | join(" ")' <<<"$rainier_bbox")
"$maquette" -q export gtiff "$tmp/deform-rainier.mqt" "$tmp/rainier.tif" --layer dammed_dem \
  --crs EPSG:32610 --resolution 8.8 --bbox "$w" "$s" "$e" "$n"
grass=$("$here/rlake.sh" "$tmp/rainier.tif" "$tmp/lake.tif" "$level" "$x" "$y")
echo "$grass (level $level m)"
echo "deform.water / r.lake: $(ratio "$ours" "$grass")"
