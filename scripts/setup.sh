#!/usr/bin/env bash
# Installs every Debian 12 package Maquette needs to build, test and run. Idempotent: when
# everything is there it prints nothing and changes nothing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ccache git ca-certificates clang-format
  libgeographiclib-dev libeigen3-dev libproj-dev proj-bin proj-data libgdal-dev gdal-bin
  libopenvdb-dev libdraco-dev draco libopencv-dev
  libspdlog-dev libfmt-dev libtbb-dev libopenmpi-dev openmpi-bin
  libsqlite3-dev sqlite3 libzstd-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev libs2-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
