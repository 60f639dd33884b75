// Every test of this program (and every `maquette` it runs, which inherits the environment)
// caches analysed exemplars (exemplar_cache.h) in a fresh directory of its own, removed at exit:
// never in the user's cache, and never an analysis of an earlier build or run.
#include <cstdlib>

#include "run_cli.h"

namespace {

const bool kCacheDirSet = [] {
  return setenv("MAQUETTE_CACHE_DIR", maquette::test::temp_dir().c_str(), 1) == 0;
}();

}  // namespace
