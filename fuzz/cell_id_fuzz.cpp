// Cell ids as users write them (maquette cells, a pipeline's "cells"): CellId::FromText and
// CellId::Parse. An id either parses to a valid cell whose text parses back to it, or Parse
// throws maquette::Error.
#include <cstdlib>

#include "core/cell_id.h"
#include "core/error.h"
#include "fuzz_input.h"

using maquette::CellId;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text = maquette::fuzz::as_text(data, size);
  if (const auto cell = CellId::FromText(text))
    if (!cell->is_valid() || CellId::FromText(cell->ToText()) != cell) std::abort();
  try {
    const CellId cell = CellId::Parse(text);
    if (!cell.is_valid() || CellId::Parse(cell.ToText()) != cell) std::abort();
  } catch (const maquette::Error&) {
  }
  return 0;
}
