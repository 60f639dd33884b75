// synthesis.clone (region): the clone brush (paper 002 §6, clone.h): the samples of an image under
// source polygons copied onto a destination (polygons, or an offset in metres), the band across
// the destination's edge resynthesized from both sides. With a DEM the copy is resized by the
// terrain's foreshortening at source and destination (terrain_slope.h), so that a texture keeps
// its ground size. Like synthesis.inpaint it reads the whole region as one mosaic with
// kRegionContext samples of context, runs once on one rank, and gives the same bits for any thread
// count.
#include <GeographicLib/LocalCartesian.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "clone.h"
#include "core/error.h"
#include "core/mosaic_geometry.h"
#include "operators.h"
#include "patchmatch.h"
#include "region_inputs.h"
#include "terrain_slope.h"

namespace maquette::synthesis {
namespace {

// Throws unless the copy's place is given once: the destination polygons or the offset.
void require_one_place(bool destination, bool offset) {
  if (destination == offset)
    throw Error("inputs.destination, params.offset_m: give one of them, the copy's place");
}

OperatorSpec clone_spec() {
  OperatorSpec s;
  s.name = "synthesis.clone";
  s.description =
      "Copies the samples of an image under source polygons onto a destination (polygons or an "
      "offset in metres), resized by the terrain's foreshortening with a DEM, the band across the "
      "destination's edge resynthesized (paper 002 §6)";
  s.kind = OperatorKind::Region;
  s.halo = kRegionContext;
  s.inputs = filled_layer_inputs(
      "heights (m): cloned for output heights; and the copy resized by the slopes under source "
      "and destination");
  s.inputs.push_back(
      {"source", "features layer: the polygons copied", false, LayerKind::Features, 0});
  s.inputs.push_back({"destination",
                      "features layer: polygons where the copy goes (the centres of their "
                      "samples' and of the source's bounding boxes meet); or params.offset_m",
                      true, LayerKind::Features, 0});
  s.outputs = filled_layer_outputs("with the source cloned onto the destination");
  json properties = inpaint_param_properties();
  // The band's ring needs fewer (clone.h).
  properties["em_iterations"]["default"] = kCloneEmIterations;
  properties["search_iterations"]["default"] = kCloneSearchIterations;
  properties["offset_m"] = {{"type", "array"},
                            {"items", {{"type", "number"}}},
                            {"minItems", 2},
                            {"maxItems", 2},
                            {"description", "[east, north] metres from the source to the copy"}};
  s.params_schema = {
      {"type", "object"}, {"additionalProperties", false}, {"properties", properties}};
  s.check_params = [](const json& params, const std::set<std::string>& mapped_inputs) {
    read_inpaint_params(params);
    require_one_place(mapped_inputs.count("destination") > 0, params.contains("offset_m"));
  };
  return s;
}

// The centre of the bounding box of the non-zero samples (side x side); nullopt when none.
std::optional<std::array<double, 2>> box_centre(const std::vector<uint8_t>& mask, int side) {
  int x0 = side, y0 = side, x1 = -1, y1 = -1;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      if (mask[size_t(y) * side + x] == 0) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) return std::nullopt;
  return std::array<double, 2>{(x0 + x1) / 2.0, (y0 + y1) / 2.0};
}

// The sample (col, row), rounded, as a lon/lat; throws naming `what` beyond the mosaic's faces.
LonLat lonlat_at(const MosaicGeometry& geometry, double col, double row, const char* what) {
  const auto p = geometry.sample_lonlat(std::lround(col), std::lround(row));
  if (!p) throw Error(std::string(what) + " lies beyond the mosaic's faces");
  return *p;
}

// The ground metres of a sample step at sample `at` (central differences in its tangent plane).
SampleFrame frame_at(const MosaicGeometry& geometry, std::array<double, 2> at, const char* what) {
  const LonLat centre = lonlat_at(geometry, at[0], at[1], what);
  const GeographicLib::LocalCartesian plane(centre.lat, centre.lon, 0);
  const auto east_south = [&](double dc, double dr) {
    const LonLat p = lonlat_at(geometry, at[0] + dc, at[1] + dr, what);
    double x = 0, y = 0, z = 0;
    plane.Forward(p.lat, p.lon, 0, x, y, z);
    return std::array<double, 2>{x, -y};
  };
  const auto right = east_south(1, 0), left = east_south(-1, 0);
  const auto below = east_south(0, 1), above = east_south(0, -1);
  return {{(right[0] - left[0]) / 2, (right[1] - left[1]) / 2},
          {(below[0] - above[0]) / 2, (below[1] - above[1]) / 2}};
}

// The offset in samples of the point `east_north` metres (in its tangent plane) from sample
// `from`.
std::array<double, 2> offset_samples(const MosaicGeometry& geometry, std::array<double, 2> from,
                                     const json& east_north) {
  const LonLat start = lonlat_at(geometry, from[0], from[1], "inputs.source: its centre");
  double lat = 0, lon = 0, h = 0;
  GeographicLib::LocalCartesian(start.lat, start.lon, 0)
      .Reverse(east_north[0].get<double>(), east_north[1].get<double>(), 0, lat, lon, h);
  const auto to = geometry.sample({lon, lat});
  if (!to) throw Error("params.offset_m: the copy lands beyond the mosaic's faces");
  return {(*to)[0] - std::lround(from[0]), (*to)[1] - std::lround(from[1])};
}

// The runner keeps only the region's cells of the output: a copy reaching the context ring around
// them, or beyond the mosaic, would lose that part silently. Throws naming `place` instead.
void check_lands_in_region(const CopyFootprint& copy, const std::vector<uint8_t>& region,
                           const char* place) {
  size_t outside = copy.beyond, total = copy.beyond;
  for (size_t i = 0; i < region.size(); ++i) {
    total += copy.destination[i] != 0;
    outside += copy.destination[i] != 0 && region[i] == 0;
  }
  if (outside == 0) return;
  throw Error(std::string(place) + ": " + std::to_string(outside) + " of the copy's " +
              std::to_string(total) +
              " samples land outside the region's cells (in the context around them or beyond), "
              "where they would be lost; move the copy or widen the run's region");
}

class Clone final : public RegionOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const StepContext& ctx, const Mosaic& input, Mosaic& output) const override {
    const json& p = *ctx.params;
    CloneParams params;
    params.fill = read_inpaint_params(p);
    const std::vector<FilledLayer> layers = filled_layers(ctx, input, output, "synthesis.clone");
    const int side = layers.front().picture.width;
    const auto source = polygon_mask(ctx, input, input.features.at("source"), side, "source");
    const auto from = box_centre(source, side);
    if (!from) throw Error("inputs.source: no sample of the region lies in its polygons");
    const auto destination = input.features.find("destination");
    const bool offset = p.contains("offset_m");
    require_one_place(destination != input.features.end(), offset);
    const char* place = offset ? "params.offset_m" : "inputs.destination";
    const MosaicGeometry geometry(*ctx.grid, input.face, input.level, input.origin_col,
                                  input.origin_row);
    std::array<double, 2> shift{};
    if (offset) {
      shift = offset_samples(geometry, *from, p.at("offset_m"));
    } else {
      const auto to =
          box_centre(polygon_mask(ctx, input, destination->second, side, "destination"), side);
      if (!to) throw Error("inputs.destination: no sample of the region lies in its polygons");
      shift = {(*to)[0] - (*from)[0], (*to)[1] - (*from)[1]};
    }
    params.offset_x = shift[0], params.offset_y = shift[1];
    // The copy keeps its ground size: between the two places' sample frames (rHEALPix's samples
    // change shape with latitude) and, with a DEM, off the source's slope onto the destination's.
    const std::array<double, 2> to{(*from)[0] + shift[0], (*from)[1] + shift[1]};
    const SampleFrame from_frame = frame_at(geometry, *from, "inputs.source: its centre");
    const SampleFrame to_frame = frame_at(geometry, to, "the copy's centre");
    GroundSlope from_slope, to_slope;
    const auto dem = input.layers.find("dem");
    if (dem != input.layers.end()) {
      if (dem->second.size() != side) {
        throw Error("inputs.dem: layer '" + ctx.input_layer("dem").name + "' gives " +
                    std::to_string(dem->second.size()) + " samples a side, inputs." +
                    layers.front().input + " " + std::to_string(side) +
                    "; ingest both at the same level and tile size");
      }
      const auto heights = dem->second.data();
      const std::vector<float> z(heights.begin(), heights.end());
      from_slope = ground_slope(
          region_gradient(z, side, side, source, 0, 0, "inputs.dem (under the source)"),
          from_frame);
      // Under the source's outline moved to the destination (before the resize).
      to_slope = ground_slope(
          region_gradient(z, side, side, source, int(std::lround(shift[0])),
                          int(std::lround(shift[1])), "inputs.dem (under the destination)"),
          to_frame);
    }
    params.linear = slope_resize(from_slope, from_frame, to_slope, to_frame);
    check_lands_in_region(copy_footprint(source, side, side, params),
                          region_cells(ctx, input, output, side), place);
    for (const FilledLayer& layer : layers) {
      params.fill.values = layer.values;
      write_filled(layer, clone(layer.picture, source, params, PatchMatch()), output);
    }
  }

 private:
  OperatorSpec spec_ = clone_spec();
};

}  // namespace

std::unique_ptr<Operator> make_clone() { return std::make_unique<Clone>(); }

}  // namespace maquette::synthesis
