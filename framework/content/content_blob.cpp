#include "content/content_blob.h"

#include <cmath>
#include <cstring>

#include "content/little_endian.h"
#include "core/error.h"

namespace maquette {
namespace {

constexpr char kMagic[4] = {'M', 'Q', 'C', 'T'};
constexpr uint16_t kFormatVersion = 1;
constexpr uint8_t kEncoding = 1;  // the one encoding of each kind (content_blob.h)

// The kind's name, or null for a byte that is no ContentKind.
const char* kind_name(uint8_t kind) {
  switch (kind) {
    case uint8_t(ContentKind::Mesh):
      return "mesh";
    case uint8_t(ContentKind::Instances):
      return "instances";
    case uint8_t(ContentKind::Volume):
      return "volume";
  }
  return nullptr;
}

}  // namespace

std::string origin_fault(const EnuOrigin& o) {
  if (!std::isfinite(o.lon) || !std::isfinite(o.lat) || !std::isfinite(o.height))
    return "origin is not finite";
  if (o.lon < -180 || o.lon > 180 || o.lat < -90 || o.lat > 90)
    return "origin lon " + std::to_string(o.lon) + ", lat " + std::to_string(o.lat) +
           " is outside [-180, 180] x [-90, 90]";
  return {};
}

std::string_view content_kind_name(ContentKind kind) {
  const char* name = kind_name(uint8_t(kind));
  return name ? name : "unknown";
}

std::string wrap_content(const ContentEnvelope& envelope, std::string_view payload) {
  const char* kind = kind_name(uint8_t(envelope.kind));
  if (!kind || envelope.encoding != kEncoding)
    throw Error("cannot wrap content of kind " + std::to_string(int(envelope.kind)) +
                ", encoding " + std::to_string(envelope.encoding) + ": unknown");
  if (const std::string fault = origin_fault(envelope.origin); !fault.empty())
    throw Error(std::string("cannot wrap ") + kind + " content: " + fault);
  std::string blob(kContentHeaderBytes, '\0');
  char* h = blob.data();
  std::memcpy(h, kMagic, 4);
  le::put(h + 4, kFormatVersion);
  le::put(h + 6, uint8_t(envelope.kind));
  le::put(h + 7, envelope.encoding);
  le::put(h + 8, envelope.origin.lon);
  le::put(h + 16, envelope.origin.lat);
  le::put(h + 24, envelope.origin.height);
  le::put(h + 32, envelope.stats.objects);
  le::put(h + 40, envelope.stats.triangles);
  le::put(h + 48, envelope.stats.voxels);
  le::put(h + 56, uint64_t(payload.size()));
  blob.append(payload);
  return blob;
}

ContentEnvelope read_content_envelope(std::string_view blob, const std::string& where) {
  return read_content_header(blob, blob.size(), where);
}

ContentEnvelope read_content_header(std::string_view head, uint64_t blob_bytes,
                                    const std::string& where) {
  const auto fail = [&](const std::string& fault) -> ContentEnvelope {
    throw Error("corrupt content blob (" + where + "): " + fault);
  };
  if (blob_bytes < kContentHeaderBytes || head.size() < kContentHeaderBytes)
    return fail(std::to_string(blob_bytes) + " bytes, shorter than its " +
                std::to_string(kContentHeaderBytes) + "-byte header");
  const char* h = head.data();
  if (std::memcmp(h, kMagic, 4) != 0) return fail("no MQCT magic");
  if (const auto version = le::get<uint16_t>(h + 4); version != kFormatVersion)
    return fail("format version " + std::to_string(version) + " (this Maquette reads " +
                std::to_string(kFormatVersion) + ")");
  ContentEnvelope e;
  const auto kind = le::get<uint8_t>(h + 6);
  if (!kind_name(kind)) return fail("unknown content kind " + std::to_string(kind));
  e.kind = ContentKind(kind);
  e.encoding = le::get<uint8_t>(h + 7);
  if (e.encoding != kEncoding)
    return fail(std::string("unknown ") + kind_name(kind) + " encoding " +
                std::to_string(e.encoding));
  e.origin = {le::get<double>(h + 8), le::get<double>(h + 16), le::get<double>(h + 24)};
  if (const std::string fault = origin_fault(e.origin); !fault.empty()) return fail(fault);
  e.stats = {le::get<uint64_t>(h + 32), le::get<uint64_t>(h + 40), le::get<uint64_t>(h + 48)};
  if (const auto payload = le::get<uint64_t>(h + 56); payload != blob_bytes - kContentHeaderBytes)
    return fail("header says " + std::to_string(payload) + " payload bytes, the blob holds " +
                std::to_string(blob_bytes - kContentHeaderBytes));
  return e;
}

std::string_view content_payload(std::string_view blob) { return blob.substr(kContentHeaderBytes); }

}  // namespace maquette
