#include "core/malloc_tuning.h"

#include <malloc.h>

namespace maquette {

void keep_tile_buffers_mapped() {
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

}  // namespace maquette
