// The fixture module's operators for region mosaics across face seams:
//   fixture.pixel_lonlat  cell: each pixel's centre (lon, lat in degrees, 2 channels), the grid's;
//   fixture.region_seams  region over several faces (OperatorSpec::spans_faces): channels 0-1
//                         the input copied, 2 how many of the sample's 4 mosaic neighbours hold a
//                         sample, 3 the largest great-circle distance (m, on the mean sphere) to
//                         them, so that a test sees what the pasted mosaic looked like.
#include "fixture_seams.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/halo.h"

namespace {

using maquette::OperatorSpec;

double great_circle_m(double lon0, double lat0, double lon1, double lat1) {
  constexpr double kDeg = std::numbers::pi / 180, kRadiusM = 6371008.8;
  const double a = std::pow(std::sin(0.5 * (lat1 - lat0) * kDeg), 2) +
                   std::cos(lat0 * kDeg) * std::cos(lat1 * kDeg) *
                       std::pow(std::sin(0.5 * (lon1 - lon0) * kDeg), 2);
  return 2 * kRadiusM * std::asin(std::sqrt(a));
}

class PixelLonLat : public maquette::CellOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = [] {
      OperatorSpec s;
      s.name = "fixture.pixel_lonlat";
      s.description = "Each pixel's centre, lon and lat";
      s.outputs.push_back({"lonlat", "lon, lat", maquette::DType::F32, 2,
                           maquette::Semantics::Continuous, "degrees", std::nullopt});
      return s;
    }();
    return s;
  }
  void run(const maquette::CellContext& ctx, maquette::CellData& data) const override {
    auto& out = data.output("lonlat");
    const int level = ctx.cell.level() + maquette::log2_tile_size(out.size());
    for (int r = 0; r < out.size(); ++r)
      for (int c = 0; c < out.size(); ++c) {
        const maquette::LonLat p =
            maquette::pixel_centre(*ctx.grid,
                                   {ctx.cell.face(), maquette::global_col(ctx.cell, out.size(), c),
                                    maquette::global_row(ctx.cell, out.size(), r)},
                                   level);
        out.at(c, r, 0) = float(p.lon);
        out.at(c, r, 1) = float(p.lat);
      }
  }
};

class RegionSeams : public maquette::RegionOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = [] {
      OperatorSpec s;
      s.name = "fixture.region_seams";
      s.description = "The mosaic's samples and their neighbours across face seams";
      s.kind = maquette::OperatorKind::Region;
      s.spans_faces = true;
      s.inputs.push_back({"src", "fixture.pixel_lonlat's layer", false});
      s.outputs.push_back({"dst", "lon, lat, neighbours, farthest (m)", maquette::DType::F32, 4,
                           maquette::Semantics::Continuous, "", std::nullopt});
      return s;
    }();
    return s;
  }
  void run(const maquette::StepContext&, const maquette::Mosaic& input,
           maquette::Mosaic& output) const override {
    const auto& in = input.layers.at("src");
    auto& out = output.layers.at("dst");
    const int n = in.size();
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        out.at(c, r, 0) = in.at(c, r, 0);
        out.at(c, r, 1) = in.at(c, r, 1);
        int present = 0;
        double farthest = 0;
        for (const auto& [dc, dr] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
          const int nc = c + dc, nr = r + dr;
          if (nc < 0 || nr < 0 || nc >= n || nr >= n || std::isnan(in.at(nc, nr, 0))) continue;
          ++present;
          farthest = std::max(farthest, great_circle_m(in.at(c, r, 0), in.at(c, r, 1),
                                                       in.at(nc, nr, 0), in.at(nc, nr, 1)));
        }
        out.at(c, r, 2) = float(present);
        out.at(c, r, 3) = float(farthest);
      }
  }
};

}  // namespace

std::unique_ptr<maquette::Operator> make_pixel_lonlat() { return std::make_unique<PixelLonLat>(); }
std::unique_ptr<maquette::Operator> make_region_seams() { return std::make_unique<RegionSeams>(); }
