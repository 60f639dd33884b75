#include "runtime/feature_index.h"

#include "core/error.h"
#include "core/grid.h"

namespace maquette {

FeatureIndex::FeatureIndex(const Store& store, const std::string& layer, const std::string& where) {
  const int last_face = default_grid().num_faces() - 1;
  std::vector<Feature> features;
  try {  // each feature once, by fid
    features = store.features_in(layer, CellId::FromFace(0).range_min(),
                                 CellId::FromFace(last_face).range_max());
  } catch (const Error& e) {
    throw Error(where + ": " + e.what());
  }
  for (Feature& f : features) {
    VectorFeature v;
    v.id = f.fid;
    v.geometry = parse_wkb(
        f.wkb, where + ": feature " + std::to_string(f.fid) + " of layer '" + layer + "'");
    v.attributes = std::move(f.attributes);
    entries_.push_back(std::make_unique<Entry>(std::move(v)));
  }
}

FeatureList FeatureIndex::within(const CellOutline& cell, double reach_m) const {
  FeatureList out;
  for (const auto& e : entries_)
    if (sphere_gap_m(cell.centre(), cell.radius_m(), e->pieces.centre(), e->pieces.radius_m()) <=
            reach_m &&
        cell.distance_m(e->pieces) <= reach_m)
      out.push_back(&e->feature);
  return out;
}

}  // namespace maquette
