#!/bin/sh
# Builds oneTBB with ThreadSanitizer into DIR (its libtbb.so.12 in DIR/lib), for
# `scripts/test.sh --sanitize=thread`, which puts DIR/lib first on LD_LIBRARY_PATH.
#
# Why: Debian's libtbb is not instrumented, so TSan cannot see the synchronization of oneTBB's work
# stealing and reports a task's memory, freed or reused on another thread, as a race in every
# parallel loop. The same source as the installed package (its upstream version, from Debian's
# archive), built with oneTBB's own TBB_SANITIZE=thread, makes those reports go away without
# suppressing anything. Nothing is done when DIR/lib holds a build of the installed version.
# Usage: scripts/onetbb-tsan.sh DIR
set -eu
dir=$1
version=$(dpkg-query -W -f='${source:Upstream-Version}' libtbb12)
[ -f "$dir/lib/libtbb.so.12" ] && [ "$(cat "$dir/lib/version" 2>/dev/null)" = "$version" ] && exit 0
tarball=onetbb_$version.orig.tar.xz
mkdir -p "$dir"
cd "$dir"
echo "onetbb-tsan: building oneTBB $version with ThreadSanitizer in $dir"
curl -sSfO "https://deb.debian.org/debian/pool/main/o/onetbb/$tarball"
rm -rf src
mkdir src
tar xJf "$tarball" -C src --strip-components=1
cmake -S src -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTBB_SANITIZE=thread \
  -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBB_STRICT=OFF -DTBBMALLOC_BUILD=OFF >/dev/null
cmake --build build --parallel "$(nproc)" >/dev/null
mkdir -p lib
cp -P build/*_relwithdebinfo/libtbb.so* lib/
echo "$version" >lib/version
rm -rf src build "$tarball"
