#!/usr/bin/env bash
# Fails, listing the files, when a C++ source is not clang-formatted: the FILEs given (absolute
# paths), or every C++ source of the repository.
# Usage: scripts/check-format.sh [FILE...]
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check-format: clang-format is not installed" >&2; exit 2; }
if [ $# -gt 0 ]; then
  files=$(printf '%s\n' "$@")
else
  files=$(git ls-files '*.cpp' '*.h' 2>/dev/null ||
          find framework grids formats modules tests benchmarks -name '*.cpp' -o -name '*.h')
fi
# clang-format --dry-run warns "FILE:LINE:COLUMN: warning: code should be clang-formatted".
report=$(echo "$files" | xargs clang-format --dry-run 2>&1) || {
  echo "check-format: clang-format failed: $report" >&2
  exit 2
}
bad=$(echo "$report" | grep -oE '^[^:]+:[0-9]+:[0-9]+: warning' | cut -d: -f1 | sort -u || true)
if [ -n "$bad" ]; then
  echo "not clang-formatted (run: clang-format -i FILE):"
  echo "$bad"
  exit 1
fi
echo "all $(echo "$files" | wc -l) C++ files are clang-formatted"
