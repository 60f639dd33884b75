#!/usr/bin/env bash
# climate.solar side by side with GRASS r.sun on the Zion SRTM DEM (../shared/data/zion): the
# clear-sky beam irradiation (Linke turbidity 3, half-hour steps, cast shadows) of one day or of
# a period sampled every n-th day, on the same DEM: the store's, exported in UTM zone 12 (70 m)
# for r.sun. r.sun computes one day per run, so a period takes it one run per sampled day
# (weighted by the days each stands for, as climate.solar weights them). Prints both run times
# (wall and CPU, r.sun's summed over its runs), their ratios and both mean irradiations
# (tests/srtm/solar_rsun_test.cpp checks the agreement pixel by pixel).
# Usage: benchmarks/climate/solar_vs_rsun.sh [THREADS] [OUT] [DIRECTIONS] [FIRST LAST STEP]
#   defaults: 1 thread, a temporary directory, 36 horizon directions, June 21 (172 172 1);
#   the Zion example's summer: 152 243 15 (7 days). After scripts/build.sh.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${MAQUETTE_BIN_DIR:-$root/build/bin}  # another build to compare with
threads=${1:-1}
out=${2:-$(mktemp -d)}
directions=${3:-36}
first=${4:-172} last=${5:-172} step=${6:-1}
mkdir -p "$out"
mq() { "$bin/maquette" --quiet "$@"; }

rm -f "$out/zion.mqt"
mq ingest "$out/zion.mqt" "$root/../shared/data/zion/srtm.tif" --layer dem --as dem
cat >"$out/solar.json" <<JSON
{"store": "zion.mqt", "region": {"bbox": [-113.24, 37.13, -112.85, 37.51]}, "level": 0,
 "steps": [{"op": "climate.solar", "inputs": {"dem": "dem"}, "outputs": {"radiation": "beam"},
            "params": {"atmosphere": "linke", "linke_turbidity": 3, "first_day": $first,
                       "last_day": $last, "day_step": $step, "minutes": 30,
                       "horizon_directions": $directions}}]}
JSON
read -r ours_wall ours_user ours_sys < <({ /usr/bin/time -f "%e %U %S" "$bin/maquette" --quiet \
  run "$out/solar.json" --threads "$threads"; } 2>&1)
mq export gtiff "$out/zion.mqt" "$out/dem.tif" --layer dem --crs EPSG:32612 --resolution 70
mq export gtiff "$out/zion.mqt" "$out/beam.tif" --layer beam --crs EPSG:32612 --resolution 70
# (statistics left in an .aux.xml by an earlier run would be read back as they are)
mean() { rm -f "$1.aux.xml" && gdalinfo -stats "$1" | awk -F= '/STATISTICS_MEAN/ {print $2}'; }
rsun_wall=0 rsun_cpu=0 rsun_mean=0 runs=0
for ((day = first; day <= last; day += step)); do
  read -r wall user sys < <("$root/benchmarks/climate/rsun_beam.sh" "$out/dem.tif" \
    "$out/rsun.tif" "$day" 0.5 3 "$threads" | awk '{print $3, $5, $6}')
  days=$((last - day + 1 < step ? last - day + 1 : step))
  rsun_wall=$(echo "$rsun_wall + $wall" | bc)
  rsun_cpu=$(echo "$rsun_cpu + $user + $sys" | bc)
  rsun_mean=$(echo "$rsun_mean + $days * $(mean "$out/rsun.tif")" | bc)
  runs=$((runs + 1))
done
ours_cpu=$(echo "$ours_user + $ours_sys" | bc)
echo "DEM $(gdalinfo "$out/dem.tif" | awk '/Size is/ {print $3 $4}') pixels, $threads thread(s)," \
  "days $first..$last every $step ($runs sampled), $directions horizon directions"
echo "climate.solar (maquette run, whole step): wall $ours_wall s, cpu $ours_cpu s"
echo "r.sun ($runs runs): wall $rsun_wall s, cpu $rsun_cpu s"
echo "r.sun / maquette: wall $(echo "scale=2; $rsun_wall / $ours_wall" | bc)," \
  "cpu $(echo "scale=2; $rsun_cpu / $ours_cpu" | bc)"
echo "mean beam: climate.solar $(mean "$out/beam.tif") Wh/m2, r.sun $rsun_mean Wh/m2"
