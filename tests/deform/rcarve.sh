#!/usr/bin/env bash
# GRASS r.carve on a DEM GeoTIFF in a projected CRS in metres, for a stream given as GeoJSON in
# the same CRS, in a temporary GRASS location as a separate process (GRASS is GPL: a test
# oracle only, never linked). Usage: rcarve.sh DEM STREAM OUT WIDTH_M DEPTH_M
set -euo pipefail
dem=$(realpath "$1")
stream=$(realpath "$2")
out=$(realpath -m "$3")
width=$4 depth=$5
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/job.sh" <<JOB
set -e
r.in.gdal --quiet input="$dem" output=dem
v.in.ogr -o --quiet input="$stream" output=stream
g.region raster=dem
r.carve --quiet raster=dem vector=stream output=carved width=$width depth=$depth
r.out.gdal --quiet -f input=carved output="$out" format=GTiff type=Float32
JOB
rm -f "$out"
# grass --exec does not pass the job's exit status on: the output tells whether it ran.
HOME=$tmp grass --tmp-location "$dem" --exec bash "$tmp/job.sh" >"$tmp/stdout" 2>"$tmp/stderr" || true
[ -f "$out" ] || { cat "$tmp/stderr" >&2; exit 1; }
