// Thinning instances for the coarser levels of an instances layer (content_overviews.h), so that
// a view from afar still shows about the canopy cover a view from near does: where instances are
// smaller than the level's sample, fewer are kept and each kept plant is widened, chosen by a rule
// of the instance alone, never of its cell or of the order instances were written in. Placed
// models (buildings) are thinned too but never widened: a building is not a canopy.
//
// An instance's width: the larger of its horizontal scales (x, y; absolute) times its prototype's
// horizontal extent (the larger side of its bounding box in x and y: a built-in prototype's,
// content/prototypes.h, or a model layer's, given by the caller: model_extent.h). Into a parent
// whose sample is S, an instance of width w survives with the share min(1, (w / S)^2), widened
// (x and y scales, not the height) by S / w when w < S: the expected area the kept instances
// cover stays the children's, level after level (an instance widened to S at one level survives
// 1 in 4 into the next). An instance at least S wide always survives, its scale unchanged.
// Instances of a model layer (any prototype not built-in) keep their scale: one survives from
// the child level (sample S / 2) into the parent with model_share(w, S), so that of the layer's
// own level min(1, (w / S)^2) survive in all, each at its true size.
//
// The draw: an instance's key is its object id when the content has provenance, else a hash of
// its bits as its child cell stores them (prototype name, position, rotation, scale, colour); it
// survives `depth` levels above the layer's iff instance_draw(key, depth) < its share. Kept
// instances of a level are a subset of the level below's.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "content/content.h"
#include "content/content_overviews.h"

namespace maquette {

uint64_t instance_key(const InstancesContent& content, size_t i);

// A number in [0, 1) from SplitMix64 (core/splitmix64.h: unit_interval of splitmix64_mix of the
// key plus depth times its gamma): independent draws for the levels of one instance.
double instance_draw(uint64_t key, int depth);

// The share that survives into a parent of sample `sample_m` for an instance `width_m` wide.
double instance_share(double width_m, double sample_m);

// The share of a model instance `width_m` wide kept from the child level (sample `sample_m` / 2)
// into the parent: instance_share(w, S) / instance_share(w, S / 2), in (0, 1].
double model_share(double width_m, double sample_m);

// The children's instances (in child order, then their order) that survive into `level`, in its
// frame: positions re-expressed through ECEF in double and rounded to float, rotations turned
// with the frame, horizontal scales of plants widened as above; colour and prototype copied bit for
// bit. Prototype names are merged in order of first use by a kept instance. Provenance is kept when
// any child has it (instances of a child without it get an empty one: object id 0, feature
// id -1). `model_extent`: a model layer's horizontal extent in metres from its name (any
// prototype not built-in), called from one thread; its errors pass through.
using ModelExtent = std::function<double(const std::string& model)>;
InstancesContent thin_instances(std::span<const InstancesContent> children,
                                const ContentLevel& level, const ModelExtent& model_extent);

}  // namespace maquette
