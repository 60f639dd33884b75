#include "content/instances_thin.h"

#include <algorithm>
#include <map>

#include "content/enu_transform.h"
#include "core/splitmix64.h"

namespace maquette {
namespace {

// FNV-1a 64 over bytes, for instances without an object id.
uint64_t fnv1a(uint64_t h, const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 0x100000001b3ULL;
  return h;
}

}  // namespace

uint64_t instance_key(const InstancesContent& c, size_t i) {
  if (!c.provenance.empty()) return c.provenance[i].object_id;
  const std::string& name = c.prototypes[c.prototype[i]];
  uint64_t h = fnv1a(0xcbf29ce484222325ULL, name.data(), name.size());
  h = fnv1a(h, &c.position[3 * i], 3 * sizeof(float));
  h = fnv1a(h, &c.rotation[4 * i], 4 * sizeof(float));
  h = fnv1a(h, &c.scale[3 * i], 3 * sizeof(float));
  return fnv1a(h, &c.colour[i], sizeof(uint32_t));
}

bool instance_survives(uint64_t key, int depth) {
  const int pair = (depth - 1) % 32, round = (depth - 1) / 32;
  return ((splitmix64_mix(key + uint64_t(round) * kSplitMix64Gamma) >> (2 * pair)) & 3) == 0;
}

InstancesContent thin_instances(std::span<const InstancesContent> children, const EnuOrigin& origin,
                                int depth) {
  InstancesContent out;
  out.origin = origin;
  const bool provenance = std::any_of(children.begin(), children.end(),
                                      [](const auto& c) { return !c.provenance.empty(); });
  std::map<std::string, uint16_t> names;
  for (const InstancesContent& c : children) {
    const EnuTransform to_parent(c.origin, origin);
    for (size_t i = 0; i < c.size(); ++i) {
      if (!instance_survives(instance_key(c, i), depth)) continue;
      const std::string& name = c.prototypes[c.prototype[i]];
      const auto [it, added] = names.try_emplace(name, uint16_t(out.prototypes.size()));
      if (added) out.prototypes.push_back(name);
      out.prototype.push_back(it->second);
      const auto p =
          to_parent.point(c.position[3 * i], c.position[3 * i + 1], c.position[3 * i + 2]);
      for (double v : p) out.position.push_back(float(v));
      const float* q = &c.rotation[4 * i];
      for (double v : to_parent.rotation(q[0], q[1], q[2], q[3])) out.rotation.push_back(float(v));
      out.scale.insert(out.scale.end(), &c.scale[3 * i], &c.scale[3 * i + 3]);
      out.colour.push_back(c.colour[i]);
      if (provenance)
        out.provenance.push_back(c.provenance.empty() ? ObjectProvenance{} : c.provenance[i]);
    }
  }
  return out;
}

}  // namespace maquette
