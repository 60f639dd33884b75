// Thinning instances for the coarser levels of an instances layer (content_overviews.h): each
// level up keeps about 1 in 4, chosen by a rule of the instance alone, never of its cell or of
// the order instances were written in.
//
// The rule: an instance's key is its object id when the content has provenance, else a hash of
// its bits as its child cell stores them (prototype name, position, rotation, scale, colour).
// It survives into the level `depth` levels above the layer's iff bits 2(depth-1) and
// 2(depth-1)+1 of splitmix64_mix(key) (core/splitmix64.h; keys re-mixed every 32 levels) are both
// zero. With object ids the key never changes, so the instances of a level are exactly those
// whose first `depth` bit pairs are all zero, 4^-depth of the layer's, and a subset of the
// level below.
#pragma once

#include <cstdint>
#include <span>

#include "content/content.h"

namespace maquette {

uint64_t instance_key(const InstancesContent& content, size_t i);
bool instance_survives(uint64_t key, int depth);

// The children's instances (in child order, then their order) that survive at `depth`, in the
// frame of `origin`: positions re-expressed through ECEF in double and rounded to float; every
// other value copied bit for bit. Prototype names are merged in order of first use by a kept
// instance. Provenance is kept when any child has it (instances of a child without it get an
// empty one: object id 0, feature id -1).
InstancesContent thin_instances(std::span<const InstancesContent> children, const EnuOrigin& origin,
                                int depth);

}  // namespace maquette
