#!/bin/sh
# Paper 000's own pipeline on Zion: the panorama rendered with its guides (land cover, altitude,
# distance, shading), Bruegel's The Harvesters transferred into the picture by maquette-paint (a
# program: its target is a picture, not the store's cells), its dark and light strokes matched to
# the render's shade and sun within each class (painting_light, w_light), the result blended with
# the render's shading. exclusion.png masks the painting's top 262 rows right of column 400 (the
# leaves of its tree against the sky, in the sky's colour class) and a blue dot in its sky at
# (24..42, 14..32): never copied. Writes
# ../panorama-bruegel-zion-output/: zion.png, zion-guides.tif, painted.png, painted-source.tif.
# Usage: examples/panorama-bruegel-zion/run.sh [BUILD_BIN_DIR [THREADS]]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
bin=${1:-$here/../../build/bin}
threads=${2:-}
data=$here/../../../shared/data
out=$here/../panorama-bruegel-zion-output
mkdir -p "$out"
store=$out/zion.mqt
rm -f "$store"
"$bin/maquette" ingest "$store" --layer dem --as dem --level 10 --resampling cubic "$data/zion/srtm.tif"
"$bin/maquette" ingest "$store" --layer rgb --as imagery --level 10 "$data/zion/landsat_rgb_b4b3b2_8bit.tif"
"$bin/maquette" ingest "$store" --layer landcover --as landcover --level 10 "$data/zion/nlcd.tif"
# The README's Zion panorama (docs/panorama-zion.png), twice the size; the land cover's class
# boundaries drawn as curves through the 30 m cells' staircase, as a painter draws them; 3 x 3
# samples a pixel, whose coverage guide anti-aliases the painted skyline too.
"$bin/maquette" render panorama "$store" "$out/zion.png" --dem dem --texture rgb \
  --land-cover landcover --smooth-land-cover --camera -113.10 37.12 6500 \
  --look-at -112.96 37.28 1400 --fov 50 --size 1600 940 --sun 225 40 --antialias 3
# The painting's path in params.json is relative to the working directory.
cd "$here/../.."
"$bin/maquette-paint" "$out/zion.png" "$here/params.json" "$out/painted.png" ${threads:+-t "$threads"}
