// Tile blobs as the store holds them (store/codec.h): decode_tile on any bytes either gives a
// tile of the size its header names or throws maquette::Error.
#include <cstdlib>

#include "core/error.h"
#include "fuzz_input.h"
#include "store/codec.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const maquette::RawTile tile = maquette::decode_tile(std::as_bytes(std::span(data, size)));
    if (tile.bytes.size() != tile.sample_count() * maquette::dtype_size(tile.dtype)) std::abort();
  } catch (const maquette::Error&) {
  }
  return 0;
}
