// The instances payload (content/instances_codec.h): bit-exact round trips of random columns
// (NaN payloads, -0 and subnormals included), the layout as documented (read with libzstd and
// this test's own unshuffling), hostile bytes refused without reading out of bounds, and the
// writer's preconditions checked on encode.
#include "content/instances_codec.h"

#include <gtest/gtest.h>
#include <zstd.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <random>

#include "content/content_blob.h"
#include "core/error.h"

namespace maquette {
namespace {

// Random instances: positions of any bits (NaN with payloads, infinities, subnormals), unit
// rotations, finite scales of any sign and size, provenance with nested attributes.
InstancesContent random_instances(size_t n, bool provenance, uint32_t seed) {
  std::mt19937_64 rng(seed);
  InstancesContent c;
  c.origin = {151.2093, -33.8688, 12.5};
  c.prototypes = {"builtin:conifer", "builtin:broadleaf", "oaks"};
  std::normal_distribution<float> gauss;
  for (size_t i = 0; i < n; ++i) {
    c.prototype.push_back(uint16_t(rng() % c.prototypes.size()));
    for (int k = 0; k < 3; ++k) c.position.push_back(std::bit_cast<float>(uint32_t(rng())));
    float q[4], length = 0;
    for (float& v : q) {
      v = gauss(rng);
      length += v * v;
    }
    for (float v : q) c.rotation.push_back(v / std::sqrt(length));
    for (int k = 0; k < 3; ++k) {
      float s = std::bit_cast<float>(uint32_t(rng()));
      c.scale.push_back(std::isfinite(s) ? s : -0.0f);
    }
    c.colour.push_back(uint32_t(rng()));
    if (provenance)
      c.provenance.push_back(
          {rng(),
           int64_t(rng()),
           i % 2 ? "vegetation.trees" : "",
           {{"height", double(rng() % 1000) / 7},
            {"species", i % 3 ? "Quercus robur" : "Pinus sylvestris, \xc3\xa9t\xc3\xa9"},
            {"nested", {{"list", {1, -2, 3.5}}, {"none", nullptr}}}}});
  }
  // NaN with a payload and a signalling NaN, an infinity, a subnormal and -0 for certain.
  if (n >= 2) {
    c.position[0] = std::bit_cast<float>(0x7fc12345u);
    c.position[1] = std::bit_cast<float>(0xff800001u);
    c.position[2] = -std::numeric_limits<float>::infinity();
    c.scale[3] = std::bit_cast<float>(0x00000001u);
    c.scale[4] = -0.0f;
  }
  return c;
}

// Bit for bit, floats included (== would fail on NaN and pass -0 for 0).
template <typename T>
void expect_same_bits(const std::vector<T>& a, const std::vector<T>& b, const char* column) {
  ASSERT_EQ(a.size(), b.size()) << column;
  // memcmp of an empty column's null pointers is undefined (UBSan), so none is made.
  EXPECT_TRUE(a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0) << column;
}

void expect_same(const InstancesContent& a, const InstancesContent& b) {
  EXPECT_EQ(a.prototypes, b.prototypes);
  expect_same_bits(a.prototype, b.prototype, "prototype");
  expect_same_bits(a.position, b.position, "position");
  expect_same_bits(a.rotation, b.rotation, "rotation");
  expect_same_bits(a.scale, b.scale, "scale");
  expect_same_bits(a.colour, b.colour, "colour");
  EXPECT_EQ(a.provenance, b.provenance);
}

std::string decompressed(const std::string& frame) {
  std::string body(ZSTD_getFrameContentSize(frame.data(), frame.size()), '\0');
  EXPECT_EQ(ZSTD_decompress(body.data(), body.size(), frame.data(), frame.size()), body.size());
  return body;
}

std::string compressed(const std::string& body, bool content_size = true) {
  ZSTD_CCtx* z = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(z, ZSTD_c_contentSizeFlag, content_size ? 1 : 0);
  std::string frame(ZSTD_compressBound(body.size()), '\0');
  frame.resize(ZSTD_compress2(z, frame.data(), frame.size(), body.data(), body.size()));
  ZSTD_freeCCtx(z);
  return frame;
}

uint32_t u32_at(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int b = 3; b >= 0; --b) v = (v << 8) | uint8_t(s[at + size_t(b)]);
  return v;
}
void set_u32(std::string& s, size_t at, uint32_t v) {
  for (int b = 0; b < 4; ++b) s[at + size_t(b)] = char(v >> (8 * b));
}

std::string decode_error(const std::string& payload) {
  try {
    decode_instances(payload, "layer 'trees', cell N1");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(InstancesCodec, RandomColumnsRoundTripBitExact) {
  for (bool provenance : {false, true})
    for (size_t n : {size_t(0), size_t(1), size_t(7), size_t(5000)}) {
      const InstancesContent c = random_instances(n, provenance, uint32_t(n * 2 + provenance));
      const std::string payload = encode_instances(c);
      SCOPED_TRACE(std::to_string(n) + (provenance ? " with provenance" : ""));
      expect_same(decode_instances(payload, "here"), c);
      EXPECT_EQ(encode_instances(c), payload);  // the same bytes every time
      const InstancesContent back = unwrap_instances(wrap_instances(c), "here");
      expect_same(back, c);
      EXPECT_EQ(back.origin, c.origin);
      EXPECT_EQ(read_content_envelope(wrap_instances(c), "here").stats.objects, n);
    }
}

TEST(InstancesCodec, PayloadFollowsTheDocumentedLayout) {
  const InstancesContent c = random_instances(10, true, 3);
  const std::string body = decompressed(encode_instances(c));
  EXPECT_EQ(u32_at(body, 0), 10u);
  EXPECT_EQ(u32_at(body, 4), 3u);
  EXPECT_EQ(body[8], 1);
  size_t at = 9;
  for (const std::string& name : c.prototypes) {
    ASSERT_EQ(u32_at(body, at), name.size());
    EXPECT_EQ(body.substr(at + 4, name.size()), name);
    at += 4 + name.size();
  }
  // prototype: 10 u16, low bytes then high bytes.
  for (size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(uint8_t(body[at + i]), c.prototype[i] & 0xff);
    EXPECT_EQ(uint8_t(body[at + 10 + i]), c.prototype[i] >> 8);
  }
  at += 20;
  // position: 30 f32 ordered x0..x9, y0..y9, z0..z9, shuffled as bytes 0 of all, bytes 1, ...
  for (size_t i = 0; i < 10; ++i)
    for (size_t k = 0; k < 3; ++k) {
      uint32_t bits = 0;
      for (size_t b = 0; b < 4; ++b)
        bits |= uint32_t(uint8_t(body[at + b * 30 + k * 10 + i])) << (8 * b);
      EXPECT_EQ(bits, std::bit_cast<uint32_t>(c.position[3 * i + k])) << i << " " << k;
    }
}

TEST(InstancesCodec, EveryPrefixFailsCleanly) {
  const InstancesContent c = random_instances(5, true, 11);
  const std::string blob = wrap_instances(c);
  const std::string payload = std::string(content_payload(blob));
  for (size_t size = 0; size < blob.size(); ++size) {
    // A copy of exactly `size` bytes, so that a read past it is an error under sanitizers.
    const std::string prefix = blob.substr(0, size);
    EXPECT_THROW(unwrap_instances(prefix, "here"), Error) << size;
  }
  for (size_t size = 0; size < payload.size(); ++size)
    EXPECT_NE(decode_error(payload.substr(0, size)), "") << size;
}

// A flipped bit is refused (the frame's checksum covers the content), except in the few bits
// zstd does not interpret (the frame header's unused bit, padding), which decode to the same
// content: never to other values.
TEST(InstancesCodec, EveryFlippedBitOfThePayloadIsCaughtOrHarmless) {
  const InstancesContent c = random_instances(5, true, 12);
  const std::string payload = encode_instances(c);
  size_t harmless = 0;
  for (size_t i = 0; i < payload.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      std::string bad = payload;
      bad[i] = char(bad[i] ^ (1 << bit));
      try {
        const InstancesContent back = decode_instances(bad, "here");
        SCOPED_TRACE("byte " + std::to_string(i) + " bit " + std::to_string(bit));
        expect_same(back, c);
        ++harmless;
      } catch (const Error&) {
      }
    }
  EXPECT_LE(harmless, 8u) << "of " << payload.size() * 8 << " flipped bits";
}

TEST(InstancesCodec, HostileBodiesAreRefused) {
  const InstancesContent c = random_instances(4, true, 13);
  const std::string body = decompressed(encode_instances(c));
  const auto error = [&](const std::function<void(std::string&)>& damage) {
    std::string b = body;
    damage(b);
    return decode_error(compressed(b));
  };
  const std::string where = "corrupt instances payload (layer 'trees', cell N1): ";
  ASSERT_EQ(error([](std::string&) {}), "");
  // Counts that would allocate far more than the payload holds.
  EXPECT_EQ(error([](std::string& b) {
              set_u32(b, 0, 0xffffffffu);
            }).rfind(where + "column prototype needs 8589934590 bytes", 0),
            0u);
  EXPECT_EQ(error([](std::string& b) { set_u32(b, 4, 70000); }),
            where + "70000 prototypes, more than 65536");
  EXPECT_EQ(error([](std::string& b) {
              set_u32(b, 9, 0xfffffff0u);
            }).rfind(where + "a prototype name needs 4294967280 bytes", 0),
            0u);
  EXPECT_EQ(error([](std::string& b) { b[8] = 2; }), where + "provenance flag 2");
  EXPECT_EQ(error([](std::string& b) { b.push_back('\0'); }),
            where + "trailing bytes after offset " + std::to_string(body.size()));
  EXPECT_NE(error([](std::string& b) { b.pop_back(); }).find("attributes needs"),
            std::string::npos);
  // Values breaking the writer's contract.
  const size_t prototype_column = 9 + 4 * 3 + 15 + 17 + 4;  // after the three names
  EXPECT_EQ(error([&](std::string& b) { b[prototype_column] = 3; }),
            where + "instance 0 (feature " + std::to_string(c.provenance[0].feature_id) +
                "): prototype index 3, there are 3 prototypes");
  const size_t rotation_column = prototype_column + 8 + 48;
  EXPECT_NE(
      error([&](std::string& b) { b[rotation_column + 3 * 16 + 1] ^= 0x40; }).find("): rotation ("),
      std::string::npos);
  EXPECT_NE(error([&](std::string& b) {
              const size_t at = b.rfind('{');  // the last instance's attributes
              b[at] = '[';
            }).find("instance 3 (feature "),
            std::string::npos);
  // Frames a writer of this format never makes.
  EXPECT_EQ(decode_error(compressed(body, false)),
            where + "not a zstd frame with its content size");
  EXPECT_EQ(decode_error(compressed(body) + compressed(body)),
            where + std::to_string(compressed(body).size()) + " bytes after the zstd frame");
  EXPECT_EQ(decode_error("MQCT"), where + "not a zstd frame with its content size");
}

TEST(InstancesCodec, EncodeChecksTheWritersPreconditions) {
  const auto error = [](const std::function<void(InstancesContent&)>& damage) -> std::string {
    InstancesContent c = random_instances(6, true, 14);
    damage(c);
    try {
      encode_instances(c);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  ASSERT_EQ(error([](InstancesContent&) {}), "");
  EXPECT_EQ(error([](InstancesContent& c) { c.position.pop_back(); }),
            "cannot encode instances: column position has 17 values for 6 instances (3 each)");
  EXPECT_EQ(error([](InstancesContent& c) { c.colour.push_back(0); }),
            "cannot encode instances: column colour has 7 values for 6 instances (1 each)");
  EXPECT_EQ(error([](InstancesContent& c) { c.provenance.pop_back(); }),
            "cannot encode instances: column provenance has 5 values for 6 instances (1 each)");
  EXPECT_EQ(error([](InstancesContent& c) {
              c.provenance[4].feature_id = 77;
              c.rotation[16] = 0.5f;
              c.rotation[17] = 0.5f;
              c.rotation[18] = 0.5f;
              c.rotation[19] = 0.6f;
            }),
            "cannot encode instances: instance 4 (feature 77): rotation (0.500000, 0.500000, "
            "0.500000, 0.600000) is not a unit quaternion");
  EXPECT_EQ(error([](InstancesContent& c) {
              c.provenance.clear();
              c.scale[7] = std::nanf("");
            }).rfind("cannot encode instances: instance 2: scale (", 0),
            0u);
  EXPECT_NE(error([](InstancesContent& c) { c.scale[17] = INFINITY; }).find("instance 5 ("),
            std::string::npos);
  EXPECT_NE(error([](InstancesContent& c) { c.prototype[1] = 3; }).find("prototype index 3"),
            std::string::npos);
  EXPECT_NE(
      error([](InstancesContent& c) { c.prototypes[2].clear(); }).find("prototype 2 has no name"),
      std::string::npos);
  EXPECT_NE(error([](InstancesContent& c) {
              c.provenance[0].attributes = 5;
            }).find("attributes are not a JSON object"),
            std::string::npos);
  EXPECT_NE(error([](InstancesContent& c) {
              c.provenance[2].attributes["bad"] = "\xff\xfe";
            }).find("instance 2 ("),
            std::string::npos);
  // A rotation within the tolerance of unit length is taken.
  EXPECT_EQ(error([](InstancesContent& c) {
              c.rotation[0] = 1 + 5e-6f;
              c.rotation[1] = c.rotation[2] = c.rotation[3] = 0;
            }),
            "");
}

}  // namespace
}  // namespace maquette
