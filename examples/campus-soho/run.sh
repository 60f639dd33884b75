#!/bin/sh
# The campus example in one command: the hotel modelled from ../shared/data/photos/building.jpg
# by maquette-prism (a program: no pipeline step runs programs, and a model layer is in no cell),
# then the pipeline, whose ingest step stores that GLB as the model layer `hotel` that
# structures.place puts into Soho. Usage: examples/campus-soho/run.sh [BUILD_BIN_DIR]
set -eu
examples=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$examples/../build/bin}
mkdir -p "$examples/campus-soho-output"
"$bin/maquette-prism" "$examples/prism-building.json" "$examples/campus-soho-output/hotel.glb"
"$bin/maquette" run "$examples/campus-soho.json"
