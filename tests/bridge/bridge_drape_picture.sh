#!/usr/bin/env bash
# The synthesis README's picture of a bridge removed from an orthophoto and draped by the 3D Tiles
# export (modules/synthesis/tests/inpaint_operator_test.cpp's BridgeRemoved, as a user runs it):
# Zion's Landsat with a deck painted on it in magenta, structures.bridge's footprint mask,
# synthesis.inpaint, then `export tiles3d` twice, draped with the photo and with the filled layer.
# Both panels are the exported tiles' textures, decoded from their GLB files: left the photo as
# exported, right the filled layer as exported. Shown at 3x around the deck.
#
#   bash tests/bridge/bridge_drape_picture.sh BUILD_DIR SHARED_DATA_DIR OUT.png X0 Y0 SIDE
#
# X0 Y0 SIDE: the window shown, in texels of the exported level-10 tiles' mosaic (the region's cells).
# shellcheck source=tests/bridge/picture.sh
source "$(dirname "$0")/picture.sh"

# The photo: the deck's outline (edges 2 km long, ~130 m apart) in magenta, in the image's grid.
python3 - "$work" <<'PY'
import json, sys
w = sys.argv[1]
a = [(-113.02, 37.27), (-113.0, 37.28)]
b = [(-113.02, 37.2712), (-113.0, 37.2812)]
def line(p, q, n=200):
    return [[p[0] + (q[0] - p[0]) * i / n, p[1] + (q[1] - p[1]) * i / n] for i in range(n + 1)]
ring = line(*a) + line(b[1], b[0]) + [list(a[0])]
fc = lambda g, props: {"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": props, "geometry": g}]}
json.dump(fc({"type": "Polygon", "coordinates": [ring]}, {}), open(w + "/deck.geojson", "w"))
json.dump(fc({"type": "MultiLineString", "coordinates": [a, b]}, {"tool": "bridge"}),
          open(w + "/strokes.geojson", "w"))
PY
gdal_translate -q "$data/zion/landsat_rgb_b4b3b2_8bit.tif" "$work/photo.tif"
ogr2ogr -t_srs "$(gdalsrsinfo -o wkt "$work/photo.tif" | tr -d '\n')" "$work/deck_utm.geojson" \
  "$work/deck.geojson"
gdal_rasterize -q -b 1 -b 2 -b 3 -burn 255 -burn 0 -burn 255 "$work/deck_utm.geojson" \
  "$work/photo.tif"

cat >"$work/pipeline.json" <<JSON
{"store": "$work/zion.mqt", "region": {"bbox": [-113.03, 37.25, -112.98, 37.30]}, "level": 10,
 "steps": [
  {"op": "ingest", "outputs": {"layer": "dem"},
   "params": {"sources": ["$data/zion/srtm.tif"], "as": "dem", "level": 10}},
  {"op": "ingest", "outputs": {"layer": "landsat"},
   "params": {"sources": ["$work/photo.tif"], "as": "imagery", "level": 10}},
  {"op": "ingest", "outputs": {"layer": "strokes"},
   "params": {"sources": ["$work/strokes.geojson"], "as": "features"}},
  {"op": "structures.bridge", "inputs": {"dem": "dem", "strokes": "strokes"},
   "outputs": {"mesh": "bridges", "mask": "bridge_mask"}},
  {"op": "synthesis.inpaint", "inputs": {"image": "landsat", "mask": "bridge_mask"},
   "outputs": {"rgb": "filled"}}]}
JSON
"$maquette" -q run "$work/pipeline.json"
for layer in landsat filled; do
  "$maquette" -q export tiles3d "$work/zion.mqt" "$work/$layer" --dem dem --texture "$layer" \
    --content bridges --levels 10..10 \
    --bbox -113.03 37.25 -112.98 37.30
done

# Each tile's texture out of its GLB, placed by its cell id (aperture 4: a digit's bit 0 the
# column, bit 1 the row), georeferenced in texels for GDAL's mosaic.
python3 - "$work" <<'PY'
import json, os, struct, subprocess, sys
w = sys.argv[1]
tiles = []
for layer in ("landsat", "filled"):
    d = f"{w}/{layer}/tiles/10"
    for name in sorted(os.listdir(d)):
        if name.count(".") != 1:
            continue  # a content (the deck), not terrain
        blob = open(f"{d}/{name}", "rb").read()
        n = struct.unpack_from("<I", blob, 12)[0]
        doc = json.loads(blob[20:20 + n])
        if "images" not in doc:
            continue  # a DEM cell beyond the layer's
        binary = blob[20 + n + 8:]
        view = doc["bufferViews"][doc["images"][0]["bufferView"]]
        start = view.get("byteOffset", 0)
        digits = [int(c) for c in name[1:-4]]
        col = sum((d & 1) << (len(digits) - 1 - i) for i, d in enumerate(digits))
        row = sum((d >> 1) << (len(digits) - 1 - i) for i, d in enumerate(digits))
        jpg = f"{w}/{layer}_{name[:-4]}.jpg"
        open(jpg, "wb").write(binary[start:start + view["byteLength"]])
        tiles.append((jpg, col, row))
cols, rows = min(t[1] for t in tiles), min(t[2] for t in tiles)
for jpg, col, row in tiles:
    x, y = 256 * (col - cols), 256 * (row - rows)
    subprocess.run(["gdal_translate", "-q", "-a_ullr", str(x), str(-y), str(x + 256),
                    str(-y - 256), jpg, jpg[:-4] + ".tif"], check=True)
PY
# Around the deck, each panel 3x, the photo's beside the fill's with a white gap.
for layer in landsat filled; do
  gdalbuildvrt -q "$work/$layer.vrt" "$work"/${layer}_*.tif
done
side_by_side "$out" "$4" "$5" "$6" "$6" 3 12 "$work/landsat.vrt" "$work/filled.vrt"
