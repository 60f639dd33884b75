// Instances payload (instances_codec.h). The body compressed into the zstd frame:
//
//   u32 instances N    u32 prototypes P    u8 provenance (0: none, 1: one per instance)
//   P strings: the prototype names
//   columns, each byte shuffled: prototype (N u16), position (3N f32: N x, N y, N z),
//   rotation (4N f32: x, y, z, w), scale (3N f32), colour (N u32);
//   with provenance: object_id (N u64), feature_id (N i64), then N tool strings and N
//   attribute strings (JSON text)
//
// A string is its byte count (u32) and its bytes. All numbers little endian.
#include "content/instances_codec.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <span>

#include "content/content_blob.h"
#include "content/little_endian.h"
#include "core/error.h"
#include "core/zstd_frame.h"
#include "store/codec.h"

namespace maquette {
namespace {

constexpr int kZstdLevel = 3;
constexpr size_t kMaxPrototypes = size_t(std::numeric_limits<uint16_t>::max()) + 1;

std::span<const std::byte> bytes_of(std::string_view s) {
  return {reinterpret_cast<const std::byte*>(s.data()), s.size()};
}
std::span<std::byte> bytes_of(std::string& s) {
  return {reinterpret_cast<std::byte*>(s.data()), s.size()};
}

std::string instance_text(const InstancesContent& c, size_t i) {
  std::string s = "instance " + std::to_string(i);
  if (!c.provenance.empty()) s += " (feature " + std::to_string(c.provenance[i].feature_id) + ")";
  return s;
}

template <typename T>
std::string values_text(const std::vector<T>& v, size_t first, size_t count) {
  std::string s = "(";
  for (size_t k = 0; k < count; ++k) s += (k ? ", " : "") + std::to_string(v[first + k]);
  return s + ")";
}

// Appends `values` (`components` per instance) component by component, little endian, shuffled.
template <typename T>
void append_column(std::string& body, const std::vector<T>& values, size_t components) {
  const size_t n = values.size() / components;
  std::string plain(values.size() * sizeof(T), '\0');
  for (size_t c = 0; c < components; ++c)
    for (size_t i = 0; i < n; ++i)
      le::put(plain.data() + (c * n + i) * sizeof(T), values[i * components + c]);
  const size_t at = body.size();
  body.resize(at + plain.size());
  shuffle_bytes(bytes_of(plain), sizeof(T), bytes_of(body).subspan(at));
}

void append_string(std::string& body, std::string_view s) {
  le::append(body, uint32_t(s.size()));
  body.append(s);
}

[[noreturn]] void corrupt(const std::string& where, const std::string& fault) {
  throw Error("corrupt instances payload (" + where + "): " + fault);
}

// Reads a body from its start, failing (naming `where`) instead of reading past its end.
class BodyReader {
 public:
  BodyReader(std::string_view body, const std::string& where) : body_(body), where_(where) {}

  [[noreturn]] void fail(const std::string& fault) const { corrupt(where_, fault); }
  std::string_view take(size_t bytes, const char* what) {
    if (bytes > body_.size() - pos_)
      fail(std::string(what) + " needs " + std::to_string(bytes) + " bytes at offset " +
           std::to_string(pos_) + ", the payload has " + std::to_string(body_.size() - pos_));
    const std::string_view out = body_.substr(pos_, bytes);
    pos_ += bytes;
    return out;
  }
  template <typename T>
  T value(const char* what) {
    return le::get<T>(take(sizeof(T), what).data());
  }
  std::string string(const char* what) {
    const auto bytes = value<uint32_t>(what);
    return std::string(take(bytes, what));
  }
  template <typename T>
  std::vector<T> column(size_t n, size_t components, const char* what) {
    const std::string_view shuffled = take(n * components * sizeof(T), what);
    std::string plain(shuffled.size(), '\0');
    unshuffle_bytes(bytes_of(shuffled), sizeof(T), bytes_of(plain));
    std::vector<T> values(n * components);
    for (size_t c = 0; c < components; ++c)
      for (size_t i = 0; i < n; ++i)
        values[i * components + c] = le::get<T>(plain.data() + (c * n + i) * sizeof(T));
    return values;
  }
  bool at_end() const { return pos_ == body_.size(); }
  size_t position() const { return pos_; }

 private:
  std::string_view body_;
  size_t pos_ = 0;
  const std::string& where_;
};

// The frame's content (core/zstd_frame.h), its faults named as the payload's.
std::string decompress(std::string_view frame, const std::string& where) {
  try {
    return zstd_frame_content(frame);
  } catch (const Error& e) {
    corrupt(where, e.what());
  }
}

}  // namespace

void check_instances(const InstancesContent& c, const std::string& where) {
  const auto fail = [&](const std::string& fault) { throw Error(where + ": " + fault); };
  const size_t n = c.size();
  if (n > std::numeric_limits<uint32_t>::max())
    fail(std::to_string(n) + " instances, more than 2^32 - 1");
  if (c.prototypes.size() > kMaxPrototypes)
    fail(std::to_string(c.prototypes.size()) + " prototypes, more than 65536");
  for (size_t p = 0; p < c.prototypes.size(); ++p)
    if (c.prototypes[p].empty()) fail("prototype " + std::to_string(p) + " has no name");
  const auto column = [&](const char* name, size_t size, size_t components) {
    if (size != n * components)
      fail("column " + std::string(name) + " has " + std::to_string(size) + " values for " +
           std::to_string(n) + " instances (" + std::to_string(components) + " each)");
  };
  column("position", c.position.size(), 3);
  column("rotation", c.rotation.size(), 4);
  column("scale", c.scale.size(), 3);
  column("colour", c.colour.size(), 1);
  if (!c.provenance.empty()) column("provenance", c.provenance.size(), 1);
  for (size_t i = 0; i < n; ++i) {
    if (c.prototype[i] >= c.prototypes.size())
      fail(instance_text(c, i) + ": prototype index " + std::to_string(c.prototype[i]) +
           ", there are " + std::to_string(c.prototypes.size()) + " prototypes");
    const float* q = &c.rotation[4 * i];
    const double length = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] +
                                    double(q[2]) * q[2] + double(q[3]) * q[3]);
    if (!(std::abs(length - 1) <= kUnitQuaternionTolerance))
      fail(instance_text(c, i) + ": rotation " + values_text(c.rotation, 4 * i, 4) +
           " is not a unit quaternion");
    const float* s = &c.scale[3 * i];
    if (!std::isfinite(s[0]) || !std::isfinite(s[1]) || !std::isfinite(s[2]))
      fail(instance_text(c, i) + ": scale " + values_text(c.scale, 3 * i, 3) + " is not finite");
    if (!c.provenance.empty() && !c.provenance[i].attributes.is_object())
      fail(instance_text(c, i) + ": attributes are not a JSON object");
  }
}

std::string encode_instances(const InstancesContent& c) {
  check_instances(c, "cannot encode instances");
  std::string body;
  le::append(body, uint32_t(c.size()));
  le::append(body, uint32_t(c.prototypes.size()));
  le::append(body, uint8_t(c.provenance.empty() ? 0 : 1));
  for (const std::string& name : c.prototypes) append_string(body, name);
  append_column(body, c.prototype, 1);
  append_column(body, c.position, 3);
  append_column(body, c.rotation, 4);
  append_column(body, c.scale, 3);
  append_column(body, c.colour, 1);
  if (!c.provenance.empty()) {
    std::vector<uint64_t> object_ids;
    std::vector<int64_t> feature_ids;
    for (const ObjectProvenance& p : c.provenance) {
      object_ids.push_back(p.object_id);
      feature_ids.push_back(p.feature_id);
    }
    append_column(body, object_ids, 1);
    append_column(body, feature_ids, 1);
    for (const ObjectProvenance& p : c.provenance) append_string(body, p.tool);
    for (size_t i = 0; i < c.size(); ++i) try {
        append_string(body, c.provenance[i].attributes.dump());
      } catch (const nlohmann::json::exception& e) {  // e.g. a string that is not UTF-8
        throw Error("cannot encode instances: " + instance_text(c, i) +
                    ": attributes: " + e.what());
      }
  }

  std::string frame;
  try {
    append_zstd_frame(body, kZstdLevel, frame);
  } catch (const Error& e) {
    throw Error(std::string("cannot compress instances: ") + e.what());
  }
  return frame;
}

InstancesContent decode_instances(std::string_view payload, const std::string& where) {
  const std::string body = decompress(payload, where);
  BodyReader r(body, where);
  InstancesContent c;
  const size_t n = r.value<uint32_t>("the instance count");
  const size_t prototypes = r.value<uint32_t>("the prototype count");
  if (prototypes > kMaxPrototypes)
    r.fail(std::to_string(prototypes) + " prototypes, more than 65536");
  const auto provenance = r.value<uint8_t>("the provenance flag");
  if (provenance > 1) r.fail("provenance flag " + std::to_string(provenance));
  for (size_t p = 0; p < prototypes; ++p) c.prototypes.push_back(r.string("a prototype name"));
  c.prototype = r.column<uint16_t>(n, 1, "column prototype");
  c.position = r.column<float>(n, 3, "column position");
  c.rotation = r.column<float>(n, 4, "column rotation");
  c.scale = r.column<float>(n, 3, "column scale");
  c.colour = r.column<uint32_t>(n, 1, "column colour");
  if (provenance) {
    const auto object_ids = r.column<uint64_t>(n, 1, "column object_id");
    const auto feature_ids = r.column<int64_t>(n, 1, "column feature_id");
    c.provenance.resize(n);
    for (size_t i = 0; i < n; ++i) {
      c.provenance[i].object_id = object_ids[i];
      c.provenance[i].feature_id = feature_ids[i];
    }
    for (auto& p : c.provenance) p.tool = r.string("a tool name");
    for (size_t i = 0; i < n; ++i) {
      const std::string text = r.string("attributes");
      try {
        c.provenance[i].attributes = nlohmann::json::parse(text);
      } catch (const nlohmann::json::exception& e) {
        r.fail(instance_text(c, i) + ": attributes are not JSON: " + e.what());
      }
    }
  }
  if (!r.at_end()) r.fail("trailing bytes after offset " + std::to_string(r.position()));
  check_instances(c, "corrupt instances payload (" + where + ")");
  return c;
}

std::string wrap_instances(const InstancesContent& content) {
  ContentEnvelope e;
  e.kind = ContentKind::Instances;
  e.origin = content.origin;
  e.stats.objects = content.size();
  return wrap_content(e, encode_instances(content));
}

InstancesContent unwrap_instances(std::string_view blob, const std::string& where) {
  const ContentEnvelope e = read_content_envelope(blob, where);
  if (e.kind != ContentKind::Instances)
    throw Error("content blob (" + where + ") holds " + std::string(content_kind_name(e.kind)) +
                " content, not instances");
  InstancesContent c = decode_instances(content_payload(blob), where);
  if (e.stats.objects != c.size())
    throw Error("corrupt content blob (" + where + "): its header counts " +
                std::to_string(e.stats.objects) + " instances, the payload holds " +
                std::to_string(c.size()));
  c.origin = e.origin;
  return c;
}

}  // namespace maquette
