#!/usr/bin/env bash
# Peak memory and time of `maquette cells cover` over the whole globe at level 10 (6,291,456
# cells), as lines and as JSON, for one or more builds of the program (e.g. before and after a
# change): cover_memory.sh BIN [BIN...]. Output goes to /dev/null.
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 MAQUETTE_BIN [MAQUETTE_BIN...]" >&2; exit 2; }
for bin in "$@"; do
  for format in "" "--json"; do
    /usr/bin/time -f "$bin cells cover (level 10 globe) ${format:-lines}: %M KB peak RSS, %e s" \
      "$bin" cells cover --bbox -180 -90 180 90 --level 10 $format >/dev/null
  done
done
