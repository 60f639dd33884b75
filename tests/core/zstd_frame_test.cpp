// One zstd frame with its content size and checksum (core/zstd_frame.h): what it writes libzstd's
// own one-shot decoder reads back; a frame claiming a huge size that it does not hold (made by hand
// from the format, RFC 8878) is refused as an Error, never allocated; frames a writer never makes
// (no content size, trailing bytes, truncated, another checksum) are refused naming the fault.
#include "core/zstd_frame.h"

#include <gtest/gtest.h>
#include <zstd.h>

#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/splitmix64.h"

namespace maquette {
namespace {

// `size` pseudo-random bytes (incompressible: zstd stores them as raw blocks of at most 128 KiB).
std::string random_bytes(size_t size, uint64_t seed) {
  std::string out(size, '\0');
  for (char& c : out) c = char(splitmix64_next(seed) >> 56);
  return out;
}

// libzstd's one-shot decoder, sized from the frame's header: the oracle for honest frames.
std::string one_shot(const std::string& frame) {
  std::string out(ZSTD_getFrameContentSize(frame.data(), frame.size()), '\0');
  EXPECT_EQ(ZSTD_decompress(out.data(), out.size(), frame.data(), frame.size()), out.size());
  return out;
}

std::string error_of(std::string_view frame) {
  try {
    zstd_frame_content(frame);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// A frame made by hand (RFC 8878 section 3.1.1): its header declares `declared` bytes in an
// 8-byte content size field with a 1 KiB window (not single segment, so the window is not the
// content size), then one last raw block of `content`, no checksum.
std::string hand_made_frame(uint64_t declared, const std::string& content) {
  std::string f = {'\x28', '\xb5', '\x2f', '\xfd'};  // magic number 0xFD2FB528, little endian
  f += '\xc0';                                       // content size field of 8 bytes
  f += '\x00';                                       // window log 10
  for (int i = 0; i < 8; ++i) f += char(declared >> (8 * i));
  const uint32_t block = 1 | uint32_t(content.size()) << 3;  // last, raw, its size
  for (int i = 0; i < 3; ++i) f += char(block >> (8 * i));
  return f + content;
}

TEST(ZstdFrame, WhatItWritesTheOneShotDecoderReads) {
  for (const size_t size : {size_t(0), size_t(1), size_t(1000), 3 * ZSTD_DStreamOutSize() + 17}) {
    const std::string content = random_bytes(size, size) + std::string(size, 'a');
    std::string out = "header";
    append_zstd_frame(content, 3, out);
    ASSERT_EQ(out.substr(0, 6), "header") << size;
    const std::string frame = out.substr(6);
    EXPECT_EQ(ZSTD_getFrameContentSize(frame.data(), frame.size()), content.size()) << size;
    ASSERT_GT(frame.size(), 4u);
    EXPECT_TRUE(frame[4] & 0x04) << size;  // the frame header's Content_Checksum_flag
    EXPECT_EQ(one_shot(frame), content) << size;
    EXPECT_EQ(zstd_frame_content(frame), content) << size;
  }
}

TEST(ZstdFrame, AFrameClaimingAHugeSizeIsRefusedNotAllocated) {
  ASSERT_EQ(zstd_frame_content(hand_made_frame(5, "hello")), "hello");  // the frame is well made
  // 2^60 bytes (one-shot decoding allocates them first: std::bad_alloc or length_error, not an
  // Error), 2^33 and one byte more than it holds.
  for (const uint64_t claim : {uint64_t(1) << 60, uint64_t(1) << 33, uint64_t(6)})
    EXPECT_THROW(zstd_frame_content(hand_made_frame(claim, "hello")), Error) << claim;
  // Less than it holds.
  EXPECT_THROW(zstd_frame_content(hand_made_frame(4, "hello")), Error);
}

TEST(ZstdFrame, FramesAWriterNeverMakesAreRefused) {
  const std::string content = random_bytes(2 * ZSTD_DStreamOutSize() + 5, 7);
  std::string frame;
  append_zstd_frame(content, 1, frame);

  std::string unsized(ZSTD_compressBound(content.size()), '\0');
  ZSTD_CCtx* z = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(z, ZSTD_c_contentSizeFlag, 0);
  unsized.resize(ZSTD_compress2(z, unsized.data(), unsized.size(), content.data(), content.size()));
  ZSTD_freeCCtx(z);
  ASSERT_EQ(ZSTD_getFrameContentSize(unsized.data(), unsized.size()), ZSTD_CONTENTSIZE_UNKNOWN);
  EXPECT_EQ(error_of(unsized), "not a zstd frame with its content size");
  EXPECT_EQ(error_of("MQCT"), "not a zstd frame with its content size");
  EXPECT_EQ(error_of(frame + "xyz"), "3 bytes after the zstd frame");
  // Every prefix: the header's content size, then the blocks, then the checksum missing.
  for (size_t size = 0; size < frame.size(); size += size < 64 ? 1 : 997)
    EXPECT_NE(error_of(frame.substr(0, size)), "") << size;
  // A content byte changed in a raw block: only the checksum (XXH64) catches it.
  std::string changed = frame;
  changed[frame.size() / 2] = char(changed[frame.size() / 2] ^ 1);
  EXPECT_EQ(error_of(changed).rfind("zstd frame: ", 0), 0u) << error_of(changed);
}

}  // namespace
}  // namespace maquette
