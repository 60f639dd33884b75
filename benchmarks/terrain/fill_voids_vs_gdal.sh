#!/usr/bin/env bash
# terrain.fill_voids side by side with GDAL's FillNodata (gdal_fillnodata.py, inverse-distance
# interpolation, max distance raised to 2000 pixels so that it fills every void, no smoothing
# passes: its defaults otherwise) on SRTM tiles of ../shared/data/srtm3:
#  - Everest (9 % voids, -32768): the voids terrain.fill_voids leaves (none: GDAL neither) and the
#    RMSE between the two fills;
#  - Rainier with a square void of 50, 200 or 500 pixels punched at its centre: the RMSE
#    and largest error of each method against the heights removed;
#  - the mean difference of neighbouring filled samples across tile edges and elsewhere (seams).
# Both fills are compared on the store's grid: GDAL's fill of the source is ingested like the
# source. Writes the Everest picture (voids | terrain.fill_voids | GDAL) as OUT/everest.jpg.
# TILE: tile size of the ingests (default 256; the fill is the same bits for any).
# Usage: [TILE=256] benchmarks/terrain/fill_voids_vs_gdal.sh [OUT]   (after scripts/build.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin="$root/build/bin"
data="$root/../shared/data/srtm3"
out=${1:-$(mktemp -d)}
tile=${TILE:-256}
sizes=${SIZES:-50 200 500}
mkdir -p "$out"
mq() { "$bin/maquette" --quiet "$@"; }

# fill NAME SOURCE: ingests SOURCE as layer `voids`, fills it with terrain.fill_voids (`filled`)
# and with GDAL (`gdal`), and exports the three layers as GeoTIFFs in the rHEALPix plane.
fill() {
  local name=$1 source=$2 dir="$out/$1"
  rm -rf "$dir" && mkdir -p "$dir"
  mq ingest "$dir/s.mqt" "$source" --layer voids --as dem --tile-size "$tile"
  cat >"$dir/fill.json" <<EOF
{"store": "s.mqt", "region": {"cells": ["N", "O", "P", "Q", "R", "S"]}, "level": 0,
 "steps": [{"op": "terrain.fill_voids", "inputs": {"dem": "voids"},
            "outputs": {"dem": "filled"}, "params": {"pyramid": "voids"}}]}
EOF
  local start end
  start=$(date +%s.%N)
  mq run "$dir/fill.json"
  end=$(date +%s.%N)
  echo "$name: terrain.fill_voids $(echo "$end - $start" | bc) s"
  start=$(date +%s.%N)
  gdal_fillnodata.py -q -md 2000 "$source" "$dir/gdal_source.tif"
  end=$(date +%s.%N)
  echo "$name: gdal_fillnodata.py -md 2000 $(echo "$end - $start" | bc) s"
  mq ingest "$dir/s.mqt" "$dir/gdal_source.tif" --layer gdal --as dem --tile-size "$tile"
  for layer in voids filled gdal; do
    mq export gtiff "$dir/s.mqt" "$dir/$layer.tif" --layer "$layer"
  done
}

fill everest "$data/mt_everest_90m.tif"
# GDAL fills the whole tile: its fill is the reference, and its extent the tile's footprint.
"$bin/void_errors" compare "$out/everest/gdal.tif" "$out/everest/voids.tif" \
  "ours=$out/everest/filled.tif"
"$bin/void_errors" seams "$out/everest/voids.tif" "$out/everest/filled.tif" "$tile"

for size in $sizes; do
  "$bin/void_errors" punch "$data/mt_rainier_90m.tif" "$out/rainier_$size.tif" "$size"
  fill "rainier_$size" "$out/rainier_$size.tif"
  mq ingest "$out/rainier_$size/s.mqt" "$data/mt_rainier_90m.tif" --layer truth \
    --as dem --tile-size "$tile"
  mq export gtiff "$out/rainier_$size/s.mqt" "$out/rainier_$size/truth.tif" \
    --layer truth
  "$bin/void_errors" compare "$out/rainier_$size/truth.tif" "$out/rainier_$size/voids.tif" \
    "ours=$out/rainier_$size/filled.tif" "gdal=$out/rainier_$size/gdal.tif"
  "$bin/void_errors" seams "$out/rainier_$size/voids.tif" "$out/rainier_$size/filled.tif" "$tile"
done

# The picture: the hypsometric tints (fixed colours by metres, the same for the three layers) and
# a hillshade.
for layer in voids filled gdal; do
  mq export png "$out/everest/s.mqt" "$out/everest/$layer.png" --layer "$layer" \
    --hillshade --max-size 600
done
"$bin/void_errors" montage "$out/everest.jpg" "$out/everest/voids.png" \
  "$out/everest/filled.png" "$out/everest/gdal.png"
echo "picture: $out/everest.jpg"
