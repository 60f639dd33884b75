#!/usr/bin/env bash
# Installs every Debian 12 package Maquette needs to build, test and run. Idempotent: when
# everything is there it prints nothing and changes nothing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache git ca-certificates clang-format
  curl  # scripts/onetbb-tsan.sh fetches oneTBB's source from Debian's archive
  libgeographiclib-dev libeigen3-dev libproj-dev proj-bin proj-data libgdal-dev gdal-bin
  libopenvdb-dev libboost-dev libdraco-dev draco libopencv-dev
  libspdlog-dev libfmt-dev libtbb-dev libopenmpi-dev openmpi-bin
  libsqlite3-dev sqlite3 libzstd-dev libcli11-dev nlohmann-json3-dev
  libssl-dev  # SHA-1 naming volume streams (formats/vdb; OpenSSL 3: Apache-2.0)
  libgtest-dev libgmock-dev libbenchmark-dev libs2-dev
  libcpp-httplib-dev chromium
  grass-core  # test oracle only (r.sun, run as a separate process): never linked
  libopenmesh-dev  # test oracle only (tests/instances: closed, oriented meshes; BSD-3)
  libmeshoptimizer-dev  # mesh layers' coarser levels (formats/gltf/mesh_simplify; MIT)
  libcgal-dev  # test oracle only (modules/structures: valid solids; GPL, never linked into the program)
)
# The viewer is built with npm; Debian's node is enough where the machine has none of its own.
command -v npm >/dev/null || packages+=(nodejs npm)

root=$(cd "$(dirname "$0")/.." && pwd)
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  echo "setup: done"
fi

# The demo's real data: a Landsat 7 scene and its DEM (Olinda, Brazil), shipped by Debian's
# r-cran-stars package. Only the two files are extracted (no R needed) into build/demo-data,
# where build/bin/maquette looks for them. Without them the demo uses synthetic terrain.
demo_data="$root/build/demo-data"
if [ ! -f "$demo_data/L7_ETMs.tif" ] || [ ! -f "$demo_data/olinda_dem_utm25s.tif" ]; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  # apt-get download needs package lists: fetch them once if this machine has none yet.
  if (cd "$tmp" && apt-get download -qq r-cran-stars >/dev/null 2>&1) ||
     ($sudo apt-get update -qq >/dev/null 2>&1 && cd "$tmp" && apt-get download -qq r-cran-stars >/dev/null 2>&1); then
    dpkg-deb -x "$tmp"/r-cran-stars_*.deb "$tmp/x"
    mkdir -p "$demo_data"
    cp "$tmp"/x/usr/lib/R/site-library/stars/tif/{L7_ETMs.tif,olinda_dem_utm25s.tif} "$demo_data/"
    echo "setup: demo data (Debian r-cran-stars: L7_ETMs.tif, olinda_dem_utm25s.tif) in $demo_data"
  else
    echo "setup: could not download r-cran-stars (the demo will use synthetic terrain)"
  fi
fi

# A second painting for synthesis.transfer's several exemplars (issue 18): Van Gogh's The Starry
# Night (1889, public domain), 752 x 600, shipped by Debian's opencv-doc among OpenCV's sample
# data (a ~96 MB package: only the JPEG is extracted into build/demo-data; its class polygons:
# examples/starry-night-classes.geojson). Without it the tests that need it are skipped.
if [ ! -f "$demo_data/starry_night.jpg" ]; then
  tmp_doc=$(mktemp -d)
  painting=usr/share/doc/opencv-doc/examples/data/starry_night.jpg
  if (cd "$tmp_doc" && apt-get download -qq opencv-doc >/dev/null 2>&1 &&
    dpkg-deb --fsys-tarfile opencv-doc_*.deb | tar -x "./$painting"); then
    mkdir -p "$demo_data"
    cp "$tmp_doc/$painting" "$demo_data/"
    echo "setup: second painting (Debian opencv-doc: starry_night.jpg) in $demo_data"
  else
    echo "setup: could not get starry_night.jpg from opencv-doc (no second painting for synthesis.transfer)"
  fi
  rm -rf "$tmp_doc"
fi
