#!/usr/bin/env bash
# climate.solar side by side with GRASS r.sun on the Zion SRTM DEM (../shared/data/zion):
# the clear-sky beam irradiation of June 21 (Linke turbidity 3, half-hour steps, cast
# shadows) on the same DEM, the store's, exported in UTM zone 12 (70 m) for r.sun. Prints both run
# times (wall and CPU), their ratios and both mean irradiations (tests/srtm/solar_rsun_test.cpp checks the
# agreement pixel by pixel).
# Usage: benchmarks/climate/solar_vs_rsun.sh [THREADS] [OUT]   (after scripts/build.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin="$root/build/bin"
threads=${1:-1}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
mq() { "$bin/maquette" --quiet "$@"; }

rm -f "$out/zion.mqt"
mq ingest "$out/zion.mqt" "$root/../shared/data/zion/srtm.tif" --layer dem --as dem
cat >"$out/solar.json" <<JSON
{"store": "zion.mqt", "region": {"bbox": [-113.24, 37.13, -112.85, 37.51]}, "level": 0,
 "steps": [{"op": "climate.solar", "inputs": {"dem": "dem"}, "outputs": {"radiation": "beam"},
            "params": {"atmosphere": "linke", "linke_turbidity": 3, "first_day": 172,
                       "last_day": 172, "day_step": 1, "minutes": 30}}]}
JSON
ours=$( { /usr/bin/time -f "%e %U %S" "$bin/maquette" --quiet run "$out/solar.json" \
  --threads "$threads"; } 2>&1)
mq export gtiff "$out/zion.mqt" "$out/dem.tif" --layer dem --crs EPSG:32612 --resolution 70
mq export gtiff "$out/zion.mqt" "$out/beam.tif" --layer beam --crs EPSG:32612 --resolution 70
theirs=$("$root/benchmarks/climate/rsun_beam.sh" "$out/dem.tif" "$out/rsun.tif" 172 0.5 3 "$threads" |
  awk '{print $3, $5, $6}')
size=$(gdalinfo "$out/dem.tif" | awk '/Size is/ {print $3 $4}')
read -r ours_wall ours_user ours_sys <<<"$ours"
read -r rsun_wall rsun_user rsun_sys <<<"$theirs"
ours_cpu=$(echo "$ours_user + $ours_sys" | bc)
rsun_cpu=$(echo "$rsun_user + $rsun_sys" | bc)
echo "DEM $size pixels, $threads thread(s)"
echo "climate.solar (maquette run, whole step): wall $ours_wall s, cpu $ours_cpu s"
echo "r.sun: wall $rsun_wall s, cpu $rsun_cpu s"
echo "r.sun / maquette: wall $(echo "scale=2; $rsun_wall / $ours_wall" | bc), cpu $(echo "scale=2; $rsun_cpu / $ours_cpu" | bc)"
for f in beam rsun; do
  echo "$f mean $(gdalinfo -stats "$out/$f.tif" | awk -F= '/STATISTICS_MEAN/ {print $2}') Wh/m2"
done
