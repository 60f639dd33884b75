#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "bridge_deck.h"
#include "bridge_stroke.h"
#include "content/enu_transform.h"
#include "content/facet_normals.h"
#include "core/error.h"
#include "core/mosaic_geometry.h"
#include "core/polygon_set.h"
#include "core/tile_bilinear.h"
#include "gdal/vertical_datum.h"
#include "operators.h"

namespace maquette::structures {
namespace {

OperatorSpec bridge_spec() {
  OperatorSpec s;
  s.name = "structures.bridge";
  s.description =
      "Bridges from their two edge strokes (paper 002 §7, Fig. 16, tool 'bridge'): a deck whose "
      "ends meet the terrain where the edges do, slanted along its length, with a thickness; and "
      "its footprint as a mask for the clone brush";
  s.kind = OperatorKind::Region;
  // A bridge across a seam of the grid's faces is built in the plane unfolded around one face
  // (core/mosaic_geometry.h): the DEM's samples and the mask's pixels beyond the seam are the
  // neighbour face's, laid beside it.
  s.spans_faces = true;
  s.inputs.push_back(single_channel_input(
      "dem", "terrain heights (m above the layer's vertical datum)", Semantics::Continuous));
  InputSpec strokes;
  strokes.name = "strokes";
  strokes.description =
      "features layer: MultiLineStrings of two edges with tool 'bridge' (others left out)";
  strokes.kind = LayerKind::Features;
  s.inputs.push_back(strokes);
  OutputSpec mesh;
  mesh.name = "mesh";
  mesh.description = "one closed mesh per bridge, in the cell owning its first edge's first point";
  mesh.kind = LayerKind::Mesh;
  s.outputs.push_back(mesh);
  OutputSpec mask;
  mask.name = "mask";
  mask.description = "1 on the pixels whose centre lies under a deck, 0 elsewhere";
  mask.dtype = DType::U8;
  mask.semantics = Semantics::Categorical;
  s.outputs.push_back(mask);
  s.params_schema = {
      {"type", "object"},
      {"properties",
       {{"thickness_m",
         {{"type", "number"},
          {"exclusiveMinimum", 0},
          {"maximum", kMaxDeckThicknessM},
          {"default", 1},
          {"description", "the deck's thickness (m) of strokes without thickness_m"}}}}},
      {"additionalProperties", false}};
  return s;
}

// Fractional sample coordinates (sample centres at integers) of a point of a bridge the mosaic
// places (Bridge::check_placed).
std::array<double, 2> sample_of(const MosaicGeometry& samples, LonLat p) {
  return *samples.sample(p);
}

// The deck's outline in lon/lat: the first edge, the second reversed, closed.
PolygonRings outline(const BridgeStroke& b) {
  std::vector<LonLat> ring;
  for (const GeoPoint& p : b.first_edge) ring.push_back({p.lon, p.lat});
  for (auto p = b.second_edge.rbegin(); p != b.second_edge.rend(); ++p)
    ring.push_back({p->lon, p->lat});
  ring.push_back(ring.front());
  return {ring};
}

// Sets to 1 the mask's samples whose centre (core/mosaic_geometry.h) lies in the deck's outline
// (edges straight in degrees, core/polygon_set.h), looking within 2 samples of its points.
void mark_deck(const BridgeStroke& b, const MosaicGeometry& samples, Tile<float>& mask) {
  const PolygonRings ring = outline(b);
  const PolygonSet deck({ring});
  double c0 = INFINITY, r0 = INFINITY, c1 = -INFINITY, r1 = -INFINITY;
  for (const LonLat& p : ring.front()) {
    const auto [c, r] = sample_of(samples, p);
    c0 = std::min(c0, c), r0 = std::min(r0, r), c1 = std::max(c1, c), r1 = std::max(r1, r);
  }
  const int side = mask.size();
  for (int r = std::max(0, int(std::floor(r0)) - 2);
       r <= std::min(side - 1, int(std::floor(r1)) + 2); ++r)
    for (int c = std::max(0, int(std::floor(c0)) - 2);
         c <= std::min(side - 1, int(std::floor(c1)) + 2); ++c)
      if (const auto centre = samples.sample_lonlat(c, r); centre && deck.contains(*centre))
        mask.at(c, r) = 1;
}

class Bridge : public RegionOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = bridge_spec();
    return s;
  }

  void run(const StepContext& ctx, const Mosaic& input, Mosaic& output) const override {
    const auto mask = output.layers.find("mask");  // when the step maps it
    if (mask != output.layers.end())
      for (int r = 0; r < mask->second.size(); ++r)
        for (int c = 0; c < mask->second.size(); ++c) mask->second.at(c, r) = 0;
    const bool wants_mesh = output.content.begin()->second.wants("mesh");
    const double default_thickness = ctx.params->at("thickness_m").get<double>();
    const MosaicGeometry samples(*ctx.grid, input.face, input.level, input.origin_col,
                                 input.origin_row);
    // Set up at the first bridge stroke, when the mesh is mapped (PROJ's set-up takes
    // milliseconds).
    std::optional<EllipsoidalHeights> to_ellipsoid;
    for (const VectorFeature* f : input.features.at("strokes")) {
      if (!is_bridge_stroke(*f)) continue;
      if (wants_mesh && !to_ellipsoid)
        to_ellipsoid.emplace(ellipsoidal_heights(ctx.input_layer("dem")));
      try {  // the stroke's faults, each naming the feature and field
        const BridgeStroke b = bridge_stroke(*f, default_thickness);
        check_placed(b, *ctx.grid, samples);
        if (mask != output.layers.end()) mark_deck(b, samples, mask->second);
        if (wants_mesh) add_deck(b, ctx, input.layers.at("dem"), samples, *to_ellipsoid, output);
      } catch (const Error& e) {
        throw Error("structures.bridge: inputs.strokes: " + std::string(e.what()));
      }
    }
  }

 private:
  // Throws unless every point of the bridge has a place in the mosaic's plane (its face or a
  // face across one of its edges) and the bridge stays on one side of the antimeridian (its
  // outline is straight in degrees).
  static void check_placed(const BridgeStroke& b, const Grid& grid, const MosaicGeometry& samples) {
    double west = INFINITY, east = -INFINITY;
    for (const auto* edge : {&b.first_edge, &b.second_edge})
      for (const GeoPoint& p : *edge) {
        west = std::min(west, p.lon), east = std::max(east, p.lon);
        if (!samples.sample({p.lon, p.lat}))
          throw Error(where(b) + ": geometry: the point (" + std::to_string(p.lon) + ", " +
                      std::to_string(p.lat) + ") lies on face " +
                      CellId::FromFace(grid.cell_from_point({p.lon, p.lat}, 0).face()).ToText() +
                      ", which does not meet face " + CellId::FromFace(samples.face()).ToText() +
                      " of the step's region along an edge: a bridge must lie on the region's "
                      "faces; give a region holding the whole bridge");
      }
    if (east - west > 180)
      throw Error(where(b) +
                  ": geometry: the bridge crosses the antimeridian: not handled (draw it on one "
                  "side, or split it)");
  }

  static std::string where(const BridgeStroke& b) {
    return "feature " + std::to_string(b.id) + " (tool bridge)";
  }

  // The DEM's bilinear height (above the ellipsoid) at an edge's end.
  static double end_height(const BridgeStroke& b, int edge, bool last, const Tile<float>& dem,
                           const MosaicGeometry& samples, const EllipsoidalHeights& to_ellipsoid) {
    const std::vector<GeoPoint>& points = edge == 1 ? b.first_edge : b.second_edge;
    const GeoPoint& p = last ? points.back() : points.front();
    const auto [x, y] = sample_of(samples, {p.lon, p.lat});
    const double h = bilinear(dem, x, y);
    if (std::isnan(h))
      throw Error(where(b) + ": geometry: edge " + std::to_string(edge) + "'s " +
                  (last ? "last" : "first") +
                  " point is off the DEM, on its nodata or beyond the step's region: a bridge's "
                  "ends stand on the terrain, and the region must hold the whole bridge");
    return to_ellipsoid({p.lon, p.lat}, h);
  }

  static void add_deck(const BridgeStroke& b, const StepContext& ctx, const Tile<float>& dem,
                       const MosaicGeometry& samples, const EllipsoidalHeights& to_ellipsoid,
                       Mosaic& output) {
    const std::array<double, 4> ends{end_height(b, 1, false, dem, samples, to_ellipsoid),
                                     end_height(b, 1, true, dem, samples, to_ellipsoid),
                                     end_height(b, 2, false, dem, samples, to_ellipsoid),
                                     end_height(b, 2, true, dem, samples, to_ellipsoid)};
    // The deck's frame: the tangent plane at its anchor, the first edge's first point, on the
    // terrain there.
    const GeoPoint& anchor = b.first_edge.front();
    const EnuOrigin frame_origin{anchor.lon, anchor.lat, ends[0]};
    const EnuFrame frame = enu_frame(frame_origin);
    const auto deck_edge = [&](const std::vector<GeoPoint>& edge, double start, double end) {
      std::vector<PlanePoint2> plane;
      for (const GeoPoint& p : edge) {
        const std::array<double, 3> q = frame.to_enu(p.lon, p.lat, ends[0]);
        plane.push_back({q[0], q[1]});
      }
      const std::vector<double> heights = edge_profile(plane, start, end);
      std::vector<DeckPoint> points;
      for (size_t i = 0; i < edge.size(); ++i)
        points.push_back(frame.to_enu(edge[i].lon, edge[i].lat, heights[i]));
      return points;
    };
    const std::vector<DeckPoint> first = deck_edge(b.first_edge, ends[0], ends[1]);
    const std::vector<DeckPoint> second = deck_edge(b.second_edge, ends[2], ends[3]);
    Solid solid;
    try {
      solid = deck_solid(first, second, b.thickness_m);
    } catch (const InvalidFootprint& e) {
      throw Error(where(b) + ": geometry: " + e.what());
    }

    const CellId owner =
        ctx.grid->cell_from_point({anchor.lon, anchor.lat}, output.content.begin()->first.level());
    if (!output.content.count(owner))
      throw Error(where(b) + ": its first point (the deck's anchor) is outside the step's cells");
    MeshContent& content = output.content.at(owner).mesh("mesh");
    const EnuTransform to_content(frame_origin, content.origin);
    MeshObject object;
    for (size_t v = 0; v < solid.positions.size(); v += 3) {
      const auto [x, y, z] =
          to_content.point(solid.positions[v], solid.positions[v + 1], solid.positions[v + 2]);
      object.positions.insert(object.positions.end(), {float(x), float(y), float(z)});
    }
    object.indices = solid.indices;
    object.provenance = {uint64_t(b.id),
                         b.id,
                         "structures.bridge",
                         {{"thickness_m", b.thickness_m},
                          {"volume_m3", mesh_volume(solid.positions, solid.indices)},
                          {"end_heights_m", ends}}};
    content.objects.push_back(with_facet_normals(object));
  }
};

}  // namespace

std::unique_ptr<Operator> make_bridge() { return std::make_unique<Bridge>(); }

}  // namespace maquette::structures
