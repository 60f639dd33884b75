# shellcheck shell=bash
# Sourced by the pictures' scripts in this folder (bridge_drape_picture.sh, inpaint_picture.sh),
# whose first arguments are BUILD_DIR SHARED_DATA_DIR OUT: sets build, data and out (absolute),
# maquette (the program), work (a scratch folder, removed at exit); and defines side_by_side.
set -euo pipefail
# shellcheck disable=SC2034  # used by the scripts sourcing this
build=$(cd "$1" && pwd) data=$(cd "$2" && pwd) out=$(realpath "$3")
# shellcheck disable=SC2034
maquette="$build/bin/maquette"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# side_by_side OUT X0 Y0 WIDTH HEIGHT ZOOM GAP RASTER...
#
# The same WIDTH x HEIGHT window at (X0, Y0) (pixels) of each RASTER (its values as they are: no
# nodata), enlarged ZOOM times (nearest), left to right with GAP white pixels between them, written
# to OUT: a PNG or a JPEG by its suffix, without georeferencing.
side_by_side() {
  local out=$1 x0=$2 y0=$3 width=$4 height=$5 zoom=$6 gap=$7
  shift 7
  local w=$((zoom * width)) h=$((zoom * height)) x=0 i=0 panels=() format=PNG options=()
  if [[ $out == *.jpg ]]; then format=JPEG options=(-co QUALITY=90); fi
  for raster in "$@"; do
    gdal_translate -q -srcwin "$x0" "$y0" "$width" "$height" -outsize "$w" "$h" -r nearest \
      -a_nodata none -a_ullr "$x" 0 $((x + w)) "-$h" "$raster" "$work/panel$i.tif"
    panels+=("$work/panel$i.tif")
    x=$((x + w + gap)) i=$((i + 1))
  done
  gdalbuildvrt -q -vrtnodata 255 "$work/panels.vrt" "${panels[@]}"
  gdal_translate -q --config GDAL_PAM_ENABLED NO -of "$format" "${options[@]}" -a_nodata none \
    "$work/panels.vrt" "$out"
}
