#!/usr/bin/env bash
# The synthesis README's picture of synthesis.transfer across a polar face's turned edge
# (docs/synthesis-polar-edge.jpg): Zion's NLCD land cover moved (its pixels as they are, its
# georeferencing replaced) to longitude -60.2 .. -59.8, latitude 41.75 .. 42.13, across the edge
# where N meets P turned (latitude ~41.94, N above), drawn in lon/lat (`export png`: the edge a
# straight row). Top: painted from The Harvesters (the Zion example's classes, no altitude);
# bottom: from vertical stripes (one class everywhere, exemplar scale 1), which show each face's
# chart by their direction. Left a build before the change, right one after, the same crop.
# With `corner` (docs/synthesis-polar-corner.jpg): at longitude -90.2 .. -89.8 instead, the cube
# corner where N, O (west of -90) and P (east) meet in the crop's middle.
#
#   bash modules/synthesis/tests/polar_edge_picture.sh BUILD_AFTER SHARED_DATA_DIR OUT.jpg \
#     BUILD_BEFORE [corner]
if [[ $# -ne 4 && ($# -ne 5 || $5 != corner) ]]; then
  echo "usage: $0 BUILD_AFTER SHARED_DATA_DIR OUT.jpg BUILD_BEFORE [corner]" >&2
  exit 2
fi
# shellcheck source=tests/bridge/picture.sh
source "$(dirname "$0")/../../../tests/bridge/picture.sh"
before=$(cd "$4" && pwd)

# The crop: its width (its first column that much left of the middle with `corner`) and zoom.
west=-60.2 east=-59.8 crop=300 zoom=3 from=0
if [[ $# -eq 5 ]]; then west=-90.2 east=-89.8 crop=120 zoom=5 from=-60; fi
bbox="$west 41.75 $east 42.13"
gdal_translate -q -a_srs EPSG:4326 -a_ullr "$west" 42.13 "$east" 41.75 "$data/zion/nlcd.tif" \
  "$work/landcover.tif"
# 192 x 144 pixels: brown and ochre stripes 12 pixels apart, with noise.
python3 - "$work/stripes.ppm" <<'PY'
import math, random, sys
w, h = 192, 144
random.seed(1)
px = bytearray()
for y in range(h):
    for x in range(w):
        v, n = 0.5 + 0.5 * math.sin(2 * math.pi * x / 12), random.randint(-20, 20)
        px += bytes(int(max(0, min(255, a + b * v + c * n))) for a, b, c in
                    ((90, 130, 1), (70, 90, 1), (40, 30, 0.5)))
open(sys.argv[1], "wb").write(b"P6\n%d %d\n255\n" % (w, h) + px)
PY
gdal_translate -q -of PNG "$work/stripes.ppm" "$work/stripes.png"

harvesters='"painting": "'$data'/painting/bruegel_the_harvesters_1565.png", "classes": 8,
  "exclude_classes": [0], "exemplar_scale": 2,
  "landcover_classes": {"1": 7, "2": 3, "3": 5, "4": 6, "5": 7, "6": 2, "7": 2, "8": 6}'
stripes='"painting": "'$work'/stripes.png", "classes": 1, "exemplar_scale": 1,
  "landcover_classes": {"1": 0, "2": 0, "3": 0, "4": 0, "5": 0, "6": 0, "7": 0, "8": 0}'

# paint NAME PARAMS: $work/NAME_before.tif and $work/NAME_after.tif (RGB, no alpha).
paint() {
  cat >"$work/pipeline.json" <<JSON
{"store": "$work/edge.mqt", "region": {"bbox": [${bbox// /, }]}, "level": 10,
 "steps": [
  {"op": "ingest", "outputs": {"layer": "landcover"},
   "params": {"sources": ["$work/landcover.tif"], "as": "landcover", "level": 10}},
  {"op": "synthesis.transfer", "inputs": {"landcover": "landcover"},
   "outputs": {"rgb": "painted"}, "params": {$2}}]}
JSON
  for side in before after; do
    local program="$build/bin/maquette"
    [[ $side == before ]] && program="$before/bin/maquette"
    rm -f "$work/edge.mqt"
    MAQUETTE_CACHE_DIR=off "$program" -q run "$work/pipeline.json"
    # shellcheck disable=SC2086
    "$program" -q export png "$work/edge.mqt" "$work/$1_$side.png" --layer painted --bbox $bbox \
      --projection lonlat --range 0 255 --bands 1,2,3 --no-legend
    gdal_translate -q -b 1 -b 2 -b 3 "$work/$1_$side.png" "$work/$1_$side.tif"
  done
}
paint harvesters "$harvesters"
paint stripes "$stripes"

size=$(gdalinfo "$work/stripes_after.tif" | sed -n 's/^Size is \([0-9]*\), \([0-9]*\)/\1 \2/p')
read -r width height <<<"$size"
# CROP x 100 pixels at ZOOM, the edge (the picture's middle row) 49 rows down; the two rows
# stacked 12 white pixels apart.
for name in harvesters stripes; do
  side_by_side "$work/row_$name.png" $((width / 2 + from)) $((height / 2 - 49)) "$crop" 100 \
    "$zoom" 12 "$work/${name}_before.tif" "$work/${name}_after.tif"
done
row_width=$((2 * crop * zoom + 12)) row_height=$((100 * zoom))
gdal_translate -q -a_ullr 0 0 "$row_width" "-$row_height" "$work/row_harvesters.png" \
  "$work/top.tif"
gdal_translate -q -a_ullr 0 $((-row_height - 12)) "$row_width" $((-2 * row_height - 12)) \
  "$work/row_stripes.png" "$work/bottom.tif"
gdalbuildvrt -q -vrtnodata 255 "$work/rows.vrt" "$work/top.tif" "$work/bottom.tif"
gdal_translate -q --config GDAL_PAM_ENABLED NO -of JPEG -co QUALITY=90 -a_nodata none \
  "$work/rows.vrt" "$out"
