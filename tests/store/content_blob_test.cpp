// The envelope of content blobs (content/content_blob.h): its bytes against the documented
// layout, read back exactly, and each fault a reader must name.
#include "content/content_blob.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/error.h"

namespace maquette {
namespace {

ContentEnvelope sample_envelope() {
  ContentEnvelope e;
  e.kind = ContentKind::Volume;
  // Values whose float64 bits are all significant: a float32 on the way would lose them.
  e.origin = {-122.41941552734375 + 1e-12, 37.77492950439453 - 1e-13, -86.3125000000001};
  e.stats = {3, 1ull << 40, (1ull << 63) + 5};
  return e;
}

// The field at `offset`, read as the layout says: little endian, byte by byte.
uint64_t le_u64(const std::string& blob, size_t offset) {
  uint64_t v = 0;
  for (int b = 7; b >= 0; --b) v = (v << 8) | uint8_t(blob[offset + size_t(b)]);
  return v;
}

std::string error_of(std::string_view blob) {
  try {
    read_content_envelope(blob, "layer 'trees', cell N123, in s.mqs");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ContentEnvelope, BytesFollowTheLayout) {
  const ContentEnvelope e = sample_envelope();
  const std::string payload = "payload \0 bytes";
  const std::string blob = wrap_content(e, payload);
  ASSERT_EQ(blob.size(), 64 + payload.size());
  EXPECT_EQ(blob.substr(0, 4), "MQCT");
  EXPECT_EQ(uint8_t(blob[4]), 1);
  EXPECT_EQ(uint8_t(blob[5]), 0);
  EXPECT_EQ(uint8_t(blob[6]), 3);
  EXPECT_EQ(uint8_t(blob[7]), 1);
  EXPECT_EQ(le_u64(blob, 8), std::bit_cast<uint64_t>(e.origin.lon));
  EXPECT_EQ(le_u64(blob, 16), std::bit_cast<uint64_t>(e.origin.lat));
  EXPECT_EQ(le_u64(blob, 24), std::bit_cast<uint64_t>(e.origin.height));
  EXPECT_EQ(le_u64(blob, 32), 3u);
  EXPECT_EQ(le_u64(blob, 40), 1ull << 40);
  EXPECT_EQ(le_u64(blob, 48), (1ull << 63) + 5);
  EXPECT_EQ(le_u64(blob, 56), payload.size());
  EXPECT_EQ(blob.substr(64), payload);
}

TEST(ContentEnvelope, RoundTripsExactly) {
  for (ContentKind kind : {ContentKind::Mesh, ContentKind::Instances, ContentKind::Volume}) {
    ContentEnvelope e = sample_envelope();
    e.kind = kind;
    const std::string blob = wrap_content(e, std::string(1000, 'x'));
    const ContentEnvelope back = read_content_envelope(blob, "here");
    EXPECT_EQ(back.kind, kind);
    EXPECT_EQ(back.encoding, 1);
    EXPECT_EQ(back.origin, e.origin);
    EXPECT_EQ(back.stats, e.stats);
    EXPECT_EQ(content_payload(blob), std::string(1000, 'x'));
    // The header alone and the blob's size give the same (Store::content_stats reads so).
    const ContentEnvelope head = read_content_header(blob.substr(0, 64), blob.size(), "here");
    EXPECT_EQ(head.origin, e.origin);
    EXPECT_EQ(head.stats, e.stats);
  }
  // An empty payload is a blob of its header alone.
  EXPECT_EQ(read_content_envelope(wrap_content(sample_envelope(), ""), "here").stats,
            sample_envelope().stats);
}

TEST(ContentEnvelope, EachFaultIsNamedWithWhere) {
  const std::string good = wrap_content(sample_envelope(), "0123456789");
  ASSERT_EQ(error_of(good), "");
  const std::string where = "corrupt content blob (layer 'trees', cell N123, in s.mqs): ";
  EXPECT_EQ(error_of(good.substr(0, 63)), where + "63 bytes, shorter than its 64-byte header");
  EXPECT_EQ(error_of(""), where + "0 bytes, shorter than its 64-byte header");
  std::string b = good;
  b[3] = 'L';  // "MQCL"
  EXPECT_EQ(error_of(b), where + "no MQCT magic");
  b = good;
  b[4] = 2;
  EXPECT_EQ(error_of(b), where + "format version 2 (this Maquette reads 1)");
  b = good;
  b[6] = 4;
  EXPECT_EQ(error_of(b), where + "unknown content kind 4");
  b = good;
  b[6] = 0;
  EXPECT_EQ(error_of(b), where + "unknown content kind 0");
  b = good;
  b[7] = 2;
  EXPECT_EQ(error_of(b), where + "unknown volume encoding 2");
  b = good;
  b.push_back('!');
  EXPECT_EQ(error_of(b), where + "header says 10 payload bytes, the blob holds 11");
  b = good.substr(0, good.size() - 1);
  EXPECT_EQ(error_of(b), where + "header says 10 payload bytes, the blob holds 9");
  b = good;
  b[56] = char(0xff);  // 255 + 10 - 10: a payload size far beyond the blob
  EXPECT_EQ(error_of(b), where + "header says 255 payload bytes, the blob holds 10");
  b = good;
  b[15] = char(0x7f);  // lon's sign and exponent: +NaN
  b[14] = char(0xf8);
  EXPECT_EQ(error_of(b), where + "origin is not finite");
  b = good;
  b[23] = char(0x41);  // lat: its exponent raised by 16, ~2.5e6 degrees
  EXPECT_NE(error_of(b).find("is outside [-180, 180] x [-90, 90]"), std::string::npos)
      << error_of(b);
}

TEST(ContentEnvelope, WrapRefusesWhatNoReaderTakes) {
  ContentEnvelope e = sample_envelope();
  e.origin.lat = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(wrap_content(e, ""), Error);
  e = sample_envelope();
  e.origin.lon = 180.5;
  EXPECT_THROW(wrap_content(e, ""), Error);
  e = sample_envelope();
  e.encoding = 2;
  EXPECT_THROW(wrap_content(e, ""), Error);
  e = sample_envelope();
  e.kind = ContentKind(9);
  EXPECT_THROW(wrap_content(e, ""), Error);
}

}  // namespace
}  // namespace maquette
