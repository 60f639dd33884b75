#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds Maquette and runs every test (CTest).
# Usage: scripts/test.sh [--sanitize=address|thread] [--target NAME]... [ctest args...]
#   --sanitize=address: AddressSanitizer + UndefinedBehaviorSanitizer, in ./build-asan;
#   --sanitize=thread: ThreadSanitizer, in ./build-tsan (cmake/Sanitizers.cmake). A report fails
#   the test it comes from.
#   --target NAME: build only these targets (and what they need) before running CTest; pass
#   ctest's -R to run only their tests (a test whose executable is not built fails).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
sanitize=""
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --sanitize=*) sanitize=${1#--sanitize=} ;;
    --target) targets+=(--target "$2"); shift ;;
    *) break ;;
  esac
  shift
done

if [ -z "$sanitize" ]; then
  "$root/scripts/build.sh"
  build="$root/build"
else
  case "$sanitize" in
    address) build="$root/build-asan" ;;
    thread) build="$root/build-tsan" ;;
    *) echo "scripts/test.sh: --sanitize=$sanitize: expected address or thread" >&2; exit 2 ;;
  esac
  "$root/scripts/setup.sh"
  export CCACHE_BASEDIR="$root"
  if [ ! -f "$build/CMakeCache.txt" ]; then
    # -Og -g1: an instrumented file compiles in half the time of -O1 -g (framework/core/json_file.cpp
    # under ASan + UBSan: 7.7 s against 15.5 s of CPU), still optimized enough to run the suite, and
    # reports keep function names and line numbers; assertions kept.
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-Og -g1" -DMAQUETTE_SANITIZE="$sanitize" >/dev/null
  fi
  cmake --build "$build" --parallel "$(nproc)" "${targets[@]}"
  # The demo's data, which setup.sh puts in build/demo-data, next to this tree's bin/ too.
  [ -e "$build/demo-data" ] || ln -s "$root/build/demo-data" "$build/demo-data"
  # Reports stop the program; leaks are reported too (exit code 23 fails the test); a stack slot
  # read after its function returned too (OpenVDB's streams keep pointers to their callers' locals).
  # GCC 12's LeakSanitizer records a bogus dynamic TLS block from the __tls_get_addr it intercepts
  # (begin 0x5ba, 32 GiB long) and its tracer faults reading it at the exit's leak check
  # (`Runner.ResumeNeedsTheSameRegionCells` every time): not intercepted, dynamic TLS is not
  # scanned for pointers, which can only add leak reports, never hide one.
  export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:exitcode=23:detect_stack_use_after_return=1:intercept_tls_get_addr=0}
  export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/scripts/lsan-suppressions.txt}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
  export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1:suppressions=$root/scripts/tsan-suppressions.txt}
  if [ "$sanitize" = thread ]; then  # oneTBB built with TSan in place of Debian's libtbb
    "$root/scripts/onetbb-tsan.sh" "$build/onetbb"
    export LD_LIBRARY_PATH="$build/onetbb/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  fi
fi
cd "$build"
# Analysed exemplars (modules/synthesis/exemplar_cache.h) cached in the build, emptied at each
# run, never in the user's cache (maquette_synthesis_test gives each of its runs its own).
export MAQUETTE_CACHE_DIR="$build/test-exemplar-cache"
rm -rf "$MAQUETTE_CACHE_DIR"
# Instrumented code runs several times slower: the mesh simplification's level-of-detail test
# takes 556 s under ASan + UBSan on a loaded 2-core machine.
timeout=600
[ -n "$sanitize" ] && timeout=1800
ctest --output-on-failure --parallel "$(nproc)" --timeout "$timeout" "$@"
