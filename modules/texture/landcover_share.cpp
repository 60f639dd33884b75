// texture.landcover_share: the share of a window's land-cover pixels whose code is one of a set
// (e.g. NLCD barren land), a continuous quantity for texture.fit and texture.procedural: the
// land cover's composition at the scale of the observed classes' minimum mapping unit, where a
// pixel's own code is speckle.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "majority_filter.h"
#include "operators.h"
#include "runtime/params_schema.h"
#include "window_counts.h"

namespace maquette::texture {
namespace {

OperatorSpec landcover_share_spec() {
  OperatorSpec s;
  s.name = "texture.landcover_share";
  s.description =
      "Share of the land-cover pixels of the (2r+1)^2 window around each pixel whose code is "
      "one of params.codes (pixels without land cover do not count)";
  s.kind = OperatorKind::Cell;
  s.inputs = {single_channel_input("landcover", "categorical land cover (e.g. NLCD codes)",
                                   Semantics::Categorical)};
  s.outputs = {{"share", "share of the window's land cover in params.codes, 0..1 (NaN: none known)",
                DType::F32, 1, Semantics::Continuous, "", std::nullopt}};
  s.halo = kMaxMajorityRadius;
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"codes"}},
      {"properties",
       {{"codes",
         {{"type", "array"},
          {"minItems", 1},
          {"items", {{"type", "integer"}, {"minimum", 0}, {"maximum", 255}}},
          {"description", "land-cover codes counted (e.g. [31]: NLCD barren land)"}}},
        {"radius",
         integer_param(0, kMaxMajorityRadius, kMaxMajorityRadius, "window radius in pixels")}}}};
  return s;
}

class LandcoverShareOp : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const json& p = *ctx.params;
    const std::vector<int> codes = p.at("codes").get<std::vector<int>>();
    const int radius = p.at("radius").get<int>(), n = ctx.tile_size, side = n + 2 * radius;
    const Tile<float>& lc = data.input("landcover");
    if (lc.halo() < radius)
      throw Error("texture.landcover_share: inputs.landcover: halo " + std::to_string(lc.halo()) +
                  " is narrower than params.radius " + std::to_string(radius));
    std::vector<uint8_t> known(size_t(side) * size_t(side)), counted(known.size());
    for (int r = -radius; r < n + radius; ++r)
      for (int c = -radius; c < n + radius; ++c) {
        const size_t i = size_t(r + radius) * size_t(side) + size_t(c + radius);
        const float code = lc.at(c, r);
        known[i] = !std::isnan(code);
        counted[i] = known[i] && std::find(codes.begin(), codes.end(), int(code)) != codes.end();
      }
    const std::vector<uint32_t> in_window = window_counts(known, n, radius);
    const std::vector<uint32_t> of_codes = window_counts(counted, n, radius);
    Tile<float>& out = data.output("share") = Tile<float>(n, 1, 0, NAN);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        if (const size_t k = size_t(r) * size_t(n) + size_t(c); in_window[k] > 0)
          out.at(c, r) = float(double(of_codes[k]) / double(in_window[k]));
  }

 private:
  OperatorSpec spec_ = landcover_share_spec();
};

}  // namespace

std::unique_ptr<Operator> make_landcover_share() { return std::make_unique<LandcoverShareOp>(); }

}  // namespace maquette::texture
