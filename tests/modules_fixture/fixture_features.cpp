// Operators of the fixture module on features ports, for the runtime tests:
//   fixture.near_features    cell: per cell, the count, the sum of the ids and the sum of the
//                            attribute "w" of the features of "strokes" (within kFixtureReachM),
//                            in every sample of its 3 channels; an optional raster input "src"
//                            decides the cells when mapped;
//   fixture.region_features  region: the count of the region's features, in every sample;
//   fixture.features_total   reduce: the sum over the cells of the count of their features.
#include "fixture_features.h"

#include <string>

namespace {

using maquette::CellContext;
using maquette::CellData;
using maquette::FeatureList;
using maquette::json;
using maquette::LayerKind;
using maquette::OperatorSpec;

maquette::InputSpec strokes_port() {
  maquette::InputSpec in;
  in.name = "strokes";
  in.description = "features layer";
  in.kind = LayerKind::Features;
  in.reach_m = kFixtureReachM;
  return in;
}

OperatorSpec make_spec(const std::string& name, maquette::OperatorKind kind, int channels) {
  OperatorSpec s;
  s.name = name;
  s.description = "fixture on features";
  s.kind = kind;
  s.inputs.push_back(strokes_port());
  maquette::OutputSpec out;
  out.name = "near";
  out.description = "what the features delivered were";
  out.channels = channels;
  s.outputs.push_back(out);
  return s;
}

class NearFeatures : public maquette::CellOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = [] {
      OperatorSpec s = make_spec("fixture.near_features", maquette::OperatorKind::Cell, 3);
      s.inputs.push_back({"src", "a raster deciding the cells", true});
      return s;
    }();
    return s;
  }
  void run(const CellContext&, CellData& data) const override {
    const FeatureList& features = data.features_of("strokes");
    double ids = 0, w = 0;
    for (const maquette::VectorFeature* f : features) {
      ids += double(f->id);
      w += f->attributes.value("w", 0.0);
    }
    auto& out = data.output("near");
    for (int r = 0; r < out.size(); ++r)
      for (int c = 0; c < out.size(); ++c) {
        out.at(c, r, 0) = float(features.size());
        out.at(c, r, 1) = float(ids);
        out.at(c, r, 2) = float(w);
      }
  }
};

class RegionFeatures : public maquette::RegionOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s =
        make_spec("fixture.region_features", maquette::OperatorKind::Region, 1);
    return s;
  }
  void run(const maquette::StepContext&, const maquette::Mosaic& input,
           maquette::Mosaic& output) const override {
    auto& out = output.layers.at("near");
    for (float& v : out.data()) v = float(input.features.at("strokes").size());
  }
};

class FeaturesTotal : public maquette::ReduceOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s =
        make_spec("fixture.features_total", maquette::OperatorKind::Reduce, 1);
    return s;
  }
  json map(const CellContext&, const CellData& data) const override {
    return data.features_of("strokes").size();
  }
  json merge(const json& a, const json& b) const override {
    return a.get<int64_t>() + b.get<int64_t>();
  }
  maquette::Artifact finish(const json& merged, const maquette::StepContext&) const override {
    return maquette::Artifact::FromText("", merged.dump());
  }
};

}  // namespace

std::unique_ptr<maquette::Operator> make_near_features() {
  return std::make_unique<NearFeatures>();
}
std::unique_ptr<maquette::Operator> make_region_features() {
  return std::make_unique<RegionFeatures>();
}
std::unique_ptr<maquette::Operator> make_features_total() {
  return std::make_unique<FeaturesTotal>();
}
