#!/usr/bin/env bash
# The synthesis README's picture of synthesis.inpaint (docs/synthesis-inpaint.jpg): Zion's Landsat
# under modules/synthesis/tests/inpaint_operator_test.cpp's deck footprint (6.3 km long, ~110 m
# wide, south-west to north-east), run as a user runs it: ingest, synthesis.inpaint, `export
# gtiff` in the grid's plane (one pixel a sample). Three panels at 3x: the photo, its samples under
# the deck in magenta (those whose centre the polygon holds: the hole), the filled layer.
#
#   bash tests/bridge/inpaint_picture.sh BUILD_DIR SHARED_DATA_DIR OUT.jpg
# shellcheck source=tests/bridge/picture.sh
source "$(dirname "$0")/picture.sh"

# The test's deck: west -113.03 at 37.255, east -112.98 at 37.295, 0.0007 degrees either side.
cat >"$work/deck.geojson" <<JSON
{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
 "geometry": {"type": "Polygon", "coordinates": [[[-113.03, 37.2543], [-112.98, 37.2943],
  [-112.98, 37.2957], [-113.03, 37.2557], [-113.03, 37.2543]]]}}]}
JSON
bbox="-113.03 37.25 -112.98 37.30"
cat >"$work/pipeline.json" <<JSON
{"store": "$work/zion.mqt", "region": {"bbox": [${bbox// /, }]}, "level": 10,
 "steps": [
  {"op": "ingest", "outputs": {"layer": "landsat"},
   "params": {"sources": ["$data/zion/landsat_rgb_b4b3b2_8bit.tif"], "as": "imagery",
              "level": 10}},
  {"op": "ingest", "outputs": {"layer": "deck"},
   "params": {"sources": ["$work/deck.geojson"], "as": "features"}},
  {"op": "synthesis.inpaint", "inputs": {"image": "landsat", "footprints": "deck"},
   "outputs": {"rgb": "filled"}}]}
JSON
"$maquette" -q run "$work/pipeline.json"
for layer in landsat filled; do
  # shellcheck disable=SC2086
  "$maquette" -q export gtiff "$work/zion.mqt" "$work/$layer.tif" --layer "$layer" --bbox $bbox
done

# The hole: the deck (its edges straight in degrees, densified; gdal_rasterize takes it into the
# grid's plane) burnt in magenta.
gdal_translate -q "$work/landsat.tif" "$work/hole.tif"
ogr2ogr -segmentize 0.0001 "$work/deck_dense.geojson" "$work/deck.geojson"
gdal_rasterize -q -b 1 -b 2 -b 3 -burn 255 -burn 0 -burn 255 "$work/deck_dense.geojson" \
  "$work/hole.tif"

size=$(gdalinfo "$work/landsat.tif" | sed -n 's/^Size is \([0-9]*\), \([0-9]*\)/\1 \2/p')
# shellcheck disable=SC2086
side_by_side "$out" 0 0 $size 3 12 "$work/landsat.tif" "$work/hole.tif" "$work/filled.tif"
