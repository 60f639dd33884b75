#!/usr/bin/env bash
# Runs GRASS commands (a bash script on standard input) on the raster DEM, imported as "dem"
# with the region set to it, in a temporary GRASS location in its CRS, as a separate process
# (GRASS is GPL: a test oracle only, never linked). Prints the script's lines holding "seconds"
# (its timings); fails, with GRASS's messages, when the script left no OUT.
# Usage: grass_job.sh DEM OUT <<'JOB' ... JOB
set -euo pipefail
dem=$1 out=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
{
  echo "set -e"
  echo "r.in.gdal --quiet input=\"$dem\" output=dem"
  echo "g.region raster=dem"
  cat
} >"$tmp/job.sh"
rm -f "$out"
# grass --exec does not pass the job's exit status on: the output tells whether it ran.
HOME=$tmp grass --tmp-location "$dem" --exec bash "$tmp/job.sh" 2>"$tmp/stderr" | grep seconds ||
  grep seconds "$tmp/stderr"
[ -f "$out" ] || { cat "$tmp/stderr" >&2; exit 1; }
