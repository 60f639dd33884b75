// The features of one features layer as a step delivers them to its operators: read from the
// store once per step, parsed (runtime/vector_feature.h), each with its edges' pieces for
// distances (core/geo_distance.h), so that finding those within reach of a cell measures only
// the features whose bounding spheres come near it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/geo_distance.h"
#include "runtime/vector_feature.h"
#include "store/store.h"

namespace maquette {

class FeatureIndex {
 public:
  // Every feature of the features layer `layer`. Throws maquette::Error prefixed with `where`
  // (e.g. "step 2 (deform.carve): inputs.strokes") naming the feature and layer of bad WKB.
  FeatureIndex(const Store& store, const std::string& layer, const std::string& where);

  // The features within `reach_m` of the cell (distance from the cell, 0 inside it), by id.
  FeatureList within(const CellOutline& cell, double reach_m) const;
  size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    explicit Entry(VectorFeature f) : feature(std::move(f)), pieces(feature.geometry) {}
    VectorFeature feature;
    GeometryPieces pieces;  // refers to feature.geometry: entries never move
  };
  std::vector<std::unique_ptr<Entry>> entries_;  // by id
};

}  // namespace maquette
