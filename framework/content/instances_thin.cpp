#include "content/instances_thin.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "content/enu_transform.h"
#include "content/prototypes.h"
#include "core/splitmix64.h"

namespace maquette {
namespace {

// FNV-1a 64 over bytes, for instances without an object id.
uint64_t fnv1a(uint64_t h, const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 0x100000001b3ULL;
  return h;
}

// The larger side of a model's bounding box in x and y (its own frame).
double horizontal_extent(const MeshContent& model) {
  std::array<float, 2> lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  for (const MeshObject& o : model.objects)
    for (size_t v = 0; v + 2 < o.positions.size(); v += 3)
      for (size_t k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], o.positions[v + k]);
        hi[k] = std::max(hi[k], o.positions[v + k]);
      }
  return std::max(double(hi[0]) - lo[0], double(hi[1]) - lo[1]);
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

double instance_draw(uint64_t key, int depth) {
  return unit_interval(splitmix64_mix(key + uint64_t(depth) * kSplitMix64Gamma));
}

double instance_share(double width_m, double sample_m) {
  return std::min(1.0, (width_m / sample_m) * (width_m / sample_m));
}

double model_share(double width_m, double sample_m) {
  return instance_share(width_m, sample_m) / instance_share(width_m, sample_m / 2);
}

InstancesContent thin_instances(std::span<const InstancesContent> children,
                                const ContentLevel& level, const ModelExtent& model_extent) {
  InstancesContent out;
  out.origin = level.origin;
  const bool provenance = std::any_of(children.begin(), children.end(),
                                      [](const auto& c) { return !c.provenance.empty(); });
  std::map<std::string, uint16_t> names;
  std::map<std::string, double> extents;  // prototypes' horizontal extents, metres
  for (const InstancesContent& c : children) {
    const EnuTransform to_parent(c.origin, level.origin);
    for (size_t i = 0; i < c.size(); ++i) {
      const std::string& name = c.prototypes[c.prototype[i]];
      auto [at, new_extent] = extents.try_emplace(name, 0.0);
      if (new_extent)
        at->second = name.starts_with(kBuiltinPrototypePrefix)
                         ? horizontal_extent(builtin_prototype(name))
                         : model_extent(name);
      const double width =
          at->second * std::max(std::abs(c.scale[3 * i]), std::abs(c.scale[3 * i + 1]));
      const bool cover = name.starts_with(kBuiltinPrototypePrefix);
      const double share =
          cover ? instance_share(width, level.sample_m) : model_share(width, level.sample_m);
      const double widen = cover ? std::max(1.0, level.sample_m / width) : 1.0;
      if (!(instance_draw(instance_key(c, i), level.depth) < share)) continue;
      const auto [it, added] = names.try_emplace(name, uint16_t(out.prototypes.size()));
      if (added) out.prototypes.push_back(name);
      out.prototype.push_back(it->second);
      const auto p =
          to_parent.point(c.position[3 * i], c.position[3 * i + 1], c.position[3 * i + 2]);
      for (double v : p) out.position.push_back(float(v));
      const float* q = &c.rotation[4 * i];
      for (double v : to_parent.rotation(q[0], q[1], q[2], q[3])) out.rotation.push_back(float(v));
      for (int k = 0; k < 2; ++k) out.scale.push_back(float(c.scale[3 * i + size_t(k)] * widen));
      out.scale.push_back(c.scale[3 * i + 2]);
      out.colour.push_back(c.colour[i]);
      if (provenance)
        out.provenance.push_back(c.provenance.empty() ? ObjectProvenance{} : c.provenance[i]);
    }
  }
  return out;
}

}  // namespace maquette
