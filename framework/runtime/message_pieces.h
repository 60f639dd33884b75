// The pieces in which the MPI plug-in sends a message between ranks (Ranks::post): MPI counts
// are `int`, so a message of 2 GiB or more (a region step's whole output is one batch) cannot go
// in one send. A message travels as its size, then its bytes in pieces of at most the piece
// limit, in order.
#pragma once

#include <cstddef>
#include <vector>

namespace maquette {

struct MessagePiece {
  size_t offset = 0;
  int bytes = 0;
};

// The pieces of a message of `size` bytes, in order: contiguous from 0 to `size`, each of
// `limit` bytes but the last (none for an empty message). Precondition: 0 < limit <= INT_MAX.
std::vector<MessagePiece> message_pieces(size_t size, size_t limit);

inline constexpr size_t kDefaultPieceLimit = size_t(1) << 30;  // 1 GiB
inline constexpr const char* kPieceLimitVariable = "MAQUETTE_MPI_PIECE_BYTES";

// The piece limit given by the environment variable MAQUETTE_MPI_PIECE_BYTES (`value`, null when
// unset: kDefaultPieceLimit), which tests set to a few kB to split messages without sending
// 2 GiB. Throws maquette::Error, naming the variable and the value, unless it is a whole number
// of bytes from 1 to INT_MAX.
size_t piece_limit(const char* value);

}  // namespace maquette
