#include "runtime/message_pieces.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <charconv>
#include <climits>
#include <cstring>

#include "core/error.h"

namespace maquette {

std::vector<MessagePiece> message_pieces(size_t size, size_t limit) {
  std::vector<MessagePiece> pieces;
  for (size_t offset = 0; offset < size; offset += limit)
    pieces.push_back({offset, int(std::min(limit, size - offset))});
  return pieces;
}

size_t piece_limit(const char* value) {
  if (value == nullptr) return kDefaultPieceLimit;
  const char* end = value + std::strlen(value);
  size_t limit = 0;
  const auto [stop, error] = std::from_chars(value, end, limit);
  if (error != std::errc() || stop != end || limit == 0 || limit > size_t(INT_MAX))
    throw Error(fmt::format("{}={}: not a number of bytes from 1 to {}", kPieceLimitVariable, value,
                            INT_MAX));
  return limit;
}

}  // namespace maquette
