#!/usr/bin/env bash
# The synthesis README's picture of synthesis.transfer across a polar face's turned edge
# (docs/synthesis-polar-edge.jpg): Zion's NLCD land cover moved (its pixels as they are, its
# georeferencing replaced) to longitude -60.2 .. -59.8, latitude 41.75 .. 42.13, across the edge
# where N meets P turned (latitude ~41.9, N above), painted from The Harvesters (the Zion
# example's classes, no altitude), drawn in lon/lat (`export png`: the edge a straight row).
# Left a build before the change, right one after, the same crop.
#
#   bash modules/synthesis/tests/polar_edge_picture.sh BUILD_AFTER SHARED_DATA_DIR OUT.jpg \
#     BUILD_BEFORE
# shellcheck source=tests/bridge/picture.sh
source "$(dirname "$0")/../../../tests/bridge/picture.sh"
before=$(cd "$4" && pwd)

bbox="-60.2 41.75 -59.8 42.13"
gdal_translate -q -a_srs EPSG:4326 -a_ullr -60.2 42.13 -59.8 41.75 "$data/zion/nlcd.tif" \
  "$work/landcover.tif"
cat >"$work/pipeline.json" <<JSON
{"store": "$work/edge.mqt", "region": {"bbox": [${bbox// /, }]}, "level": 10,
 "steps": [
  {"op": "ingest", "outputs": {"layer": "landcover"},
   "params": {"sources": ["$work/landcover.tif"], "as": "landcover", "level": 10}},
  {"op": "synthesis.transfer", "inputs": {"landcover": "landcover"},
   "outputs": {"rgb": "painted"},
   "params": {"painting": "$data/painting/bruegel_the_harvesters_1565.png",
              "classes": 8, "exclude_classes": [0],
              "landcover_classes": {"1": 7, "2": 3, "3": 5, "4": 6, "5": 7, "6": 2, "7": 2, "8": 6},
              "exemplar_scale": 2}}]}
JSON
for side in before after; do
  program="$build/bin/maquette"
  [[ $side == before ]] && program="$before/bin/maquette"
  rm -f "$work/edge.mqt"
  MAQUETTE_CACHE_DIR=off "$program" -q run "$work/pipeline.json"
  # shellcheck disable=SC2086
  "$program" -q export png "$work/edge.mqt" "$work/$side.png" --layer painted --bbox $bbox \
    --projection lonlat --range 0 255 --bands 1,2,3 --no-legend
  gdal_translate -q -b 1 -b 2 -b 3 "$work/$side.png" "$work/$side.tif"  # no alpha
done
size=$(gdalinfo "$work/after.tif" | sed -n 's/^Size is \([0-9]*\), \([0-9]*\)/\1 \2/p')
read -r width height <<<"$size"
# 300 x 100 pixels at 3x, the edge (latitude 41.94, the picture's middle row) 49 rows down.
side_by_side "$out" $((width / 2)) $((height / 2 - 49)) 300 100 3 12 \
  "$work/before.tif" "$work/after.tif"
