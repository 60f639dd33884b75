// message_pieces (the MPI plug-in's messages of 2 GiB or more): pieces cover a message in order,
// each within the limit and an int count; a message cut with a small limit and put back
// together from its pieces is the same bytes; MAQUETTE_MPI_PIECE_BYTES values outside 1..INT_MAX
// are refused, naming the variable and the value.
#include "runtime/message_pieces.h"

#include <gtest/gtest.h>

#include <climits>
#include <cstdint>
#include <string>

#include "core/error.h"

namespace maquette {
namespace {

TEST(MessagePieces, CoverTheMessageInOrderWithinTheLimit) {
  EXPECT_TRUE(message_pieces(0, 7).empty());
  for (const size_t size : {size_t(1), size_t(6), size_t(7), size_t(8), size_t(14), size_t(99)}) {
    const std::vector<MessagePiece> pieces = message_pieces(size, 7);
    ASSERT_EQ(pieces.size(), (size + 6) / 7) << size;
    size_t next = 0;
    for (const MessagePiece& p : pieces) {
      EXPECT_EQ(p.offset, next);
      EXPECT_GT(p.bytes, 0);
      EXPECT_LE(p.bytes, 7);
      next += size_t(p.bytes);
    }
    EXPECT_EQ(next, size);
  }
}

// 5 GiB (not allocated) at the default limit: 5 pieces of 1 GiB, each count an int; at INT_MAX,
// the largest limit, 3 pieces, the last of 5 GiB - 2 (2^31 - 1) bytes.
TEST(MessagePieces, BeyondIntCountsEveryPieceFitsAnInt) {
  const size_t size = size_t(5) << 30;
  const std::vector<MessagePiece> pieces = message_pieces(size, kDefaultPieceLimit);
  ASSERT_EQ(pieces.size(), 5u);
  EXPECT_EQ(pieces.back().offset, size_t(4) << 30);
  EXPECT_EQ(pieces.back().bytes, 1 << 30);
  const std::vector<MessagePiece> widest = message_pieces(size, size_t(INT_MAX));
  ASSERT_EQ(widest.size(), 3u);
  EXPECT_EQ(widest[1].offset, size_t(INT_MAX));
  EXPECT_EQ(widest[2].bytes, int64_t(size) - 2 * int64_t(INT_MAX));
}

TEST(MessagePieces, SplitAndJoinedGiveTheSameBits) {
  std::string message(100003, '\0');
  uint32_t state = 1;
  for (char& c : message) c = char((state = state * 1664525u + 1013904223u) >> 24);
  for (const size_t limit : {size_t(1), size_t(4093), size_t(65536), size_t(1) << 20}) {
    std::string joined;
    for (const MessagePiece& p : message_pieces(message.size(), limit))
      joined += message.substr(p.offset, size_t(p.bytes));
    EXPECT_EQ(joined, message) << limit;
  }
}

TEST(MessagePieces, LimitFromTheEnvironment) {
  EXPECT_EQ(piece_limit(nullptr), kDefaultPieceLimit);
  EXPECT_EQ(piece_limit("4093"), 4093u);
  EXPECT_EQ(piece_limit("2147483647"), size_t(INT_MAX));
  for (const char* bad : {"0", "2147483648", "-5", "4k", "", "12 "}) {
    try {
      piece_limit(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), std::string("MAQUETTE_MPI_PIECE_BYTES=") + bad +
                                           ": not a number of bytes from 1 to 2147483647");
    }
  }
}

}  // namespace
}  // namespace maquette
