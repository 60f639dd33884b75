#!/usr/bin/env bash
# Runs the bash script JOB in a temporary GRASS location in the CRS of the raster DEM, as a
# separate process (GRASS is GPL: a test oracle only, never linked), and prints the job's lines
# holding "seconds" (its timings). Fails, with GRASS's messages, when the job left no OUT.
# Usage: grass_job.sh DEM JOB OUT
set -euo pipefail
dem=$1 job=$2 out=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rm -f "$out"
# grass --exec does not pass the job's exit status on: the output tells whether it ran.
HOME=$tmp grass --tmp-location "$dem" --exec bash "$job" 2>"$tmp/stderr" | grep seconds ||
  grep seconds "$tmp/stderr"
[ -f "$out" ] || { cat "$tmp/stderr" >&2; exit 1; }
