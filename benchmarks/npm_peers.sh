#!/bin/sh
# Installs a benchmark's npm peers, pinned by its node/package-lock.json, into the build tree
# (`npm ci`, again only when the lock changed), and copies its scripts beside them.
# Usage: benchmarks/npm_peers.sh SOURCE_NODE_DIR TARGET_DIR SCRIPT...
set -eu
SOURCE=$1 TARGET=$2
shift 2
mkdir -p "$TARGET"
if ! cmp -s "$SOURCE/package-lock.json" "$TARGET/node_modules/.maquette-lock"; then
  cp "$SOURCE/package.json" "$SOURCE/package-lock.json" "$TARGET/"
  (cd "$TARGET" && npm ci --no-audit --no-fund --prefer-offline --loglevel=error)
  cp "$SOURCE/package-lock.json" "$TARGET/node_modules/.maquette-lock"
fi
for script in "$@"; do cp "$SOURCE/$script" "$TARGET/"; done
