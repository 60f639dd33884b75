// Operators of the fixture module writing 3D content (runtime/operator.h: CellContent), for the
// runtime tests. From the features of "strokes" (within kFixtureReachM of the cell):
//   - each polygon's outer ring extruded into a prism (mesh port "mesh"): the ring's corners at
//     height 0 and at the attribute "height" (metres above the ellipsoid), in the content's ENU
//     frame (GeographicLib::LocalCartesian), sides, a top and a bottom fanned from the first
//     corner; the anchor is the first corner;
//   - each point an instance (instances port "trees"): "builtin:conifer" (or the attribute
//     "prototype"), scaled by "height", RGBA colour "colour";
//   - a level-set sphere of kSphereRadiusM at the first point the cell owns (volume port
//     "volume", vdb/volume_vdb.h's stream);
// each with provenance (object id = feature id, the feature id, the tool, the attributes), and
// only for the features the cell owns (CellContext::owns of the anchor).
// An attribute "fault" breaks an object to test the runner's checks: "outside" moves it 50 km
// east (its anchor out of the cell), "nan" makes its first coordinate NaN, "volume_outside" (a
// point) makes the cell's sphere at it, 50 km east.
// Both leave out the features whose "height" is below params.min_height (default 0: none), so a
// re-run can empty cells.
//   fixture.content          cell operator (params.sleep_ms: a pause per cell, for kill tests);
//   fixture.region_content   region operator, each object in the content of the cell owning it,
//                            with fixture.content's provenance (the same objects, the same blobs).
#include <openvdb/tools/LevelSetSphere.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include "fixture_features.h"
#include "vdb/volume_vdb.h"

namespace {

using maquette::CellContent;
using maquette::GeometryType;
using maquette::LayerKind;
using maquette::LonLat;
using maquette::OperatorSpec;
using maquette::VectorFeature;

constexpr double kFaultShiftM = 50000;

maquette::OutputSpec content_port(const std::string& name, LayerKind kind) {
  maquette::OutputSpec out;
  out.name = name;
  out.description = "content";
  out.kind = kind;
  return out;
}

OperatorSpec content_spec(const std::string& name, maquette::OperatorKind kind) {
  OperatorSpec s;
  s.name = name;
  s.description = "prisms of polygons, trees at points";
  s.kind = kind;
  maquette::InputSpec in;
  in.name = "strokes";
  in.description = "features layer";
  in.kind = LayerKind::Features;
  in.reach_m = kFixtureReachM;
  s.inputs.push_back(in);
  s.params_schema = {{"type", "object"},
                     {"properties",
                      {{"sleep_ms", {{"type", "integer"}, {"minimum", 0}, {"default", 0}}},
                       {"min_height", {{"type", "number"}, {"default", 0}}}}},
                     {"additionalProperties", false}};
  s.outputs.push_back(content_port("mesh", LayerKind::Mesh));
  s.outputs.push_back(content_port("trees", LayerKind::Instances));
  s.outputs.push_back(content_port("volume", LayerKind::Volume));
  return s;
}

maquette::ObjectProvenance provenance(const VectorFeature& f, const std::string& tool) {
  return {uint64_t(f.id), f.id, tool, f.attributes};
}

// The feature's attribute `key`, or `fallback` when absent or null (a field of other features).
template <class T>
T attribute(const VectorFeature& f, const char* key, T fallback) {
  const auto it = f.attributes.find(key);
  return it == f.attributes.end() || it->is_null() ? fallback : it->template get<T>();
}

// The feature's object in `content` (its mesh or instance), for the ports it maps.
void add_object(const VectorFeature& f, const std::string& tool, CellContent& content) {
  const std::string fault = attribute<std::string>(f, "fault", "");
  const double shift = fault == "outside" ? kFaultShiftM : 0;
  const double height = attribute(f, "height", 10.0);
  if (f.geometry.type == GeometryType::Polygon && content.wants("mesh")) {
    maquette::MeshContent& mesh = content.mesh("mesh");
    const GeographicLib::LocalCartesian frame(mesh.origin.lat, mesh.origin.lon, mesh.origin.height);
    const auto& ring = f.geometry.polygons.front().rings.front();
    const uint32_t n = uint32_t(ring.size() - 1);  // closed: the last point repeats the first
    maquette::MeshObject o;
    o.provenance = provenance(f, tool);
    for (const double h : {0.0, height})
      for (uint32_t i = 0; i < n; ++i) {
        double x = 0, y = 0, z = 0;
        frame.Forward(ring[i].lat, ring[i].lon, h, x, y, z);
        o.positions.insert(o.positions.end(), {float(x + shift), float(y), float(z)});
      }
    if (fault == "nan") o.positions[0] = NAN;
    for (uint32_t i = 0; i < n; ++i) {  // sides: bottom i, i+1, top i+1, i
      const uint32_t j = (i + 1) % n;
      o.indices.insert(o.indices.end(), {i, j, n + j, i, n + j, n + i});
    }
    for (uint32_t i = 1; i + 1 < n; ++i) {
      o.indices.insert(o.indices.end(), {n, n + i, n + i + 1});  // top
      o.indices.insert(o.indices.end(), {0, i + 1, i});          // bottom
    }
    mesh.objects.push_back(std::move(o));
  }
  if (f.geometry.type == GeometryType::Point && content.wants("trees")) {
    maquette::InstancesContent& trees = content.instances_of("trees");
    const GeographicLib::LocalCartesian frame(trees.origin.lat, trees.origin.lon,
                                              trees.origin.height);
    const std::string name = attribute<std::string>(f, "prototype", "builtin:conifer");
    auto it = std::find(trees.prototypes.begin(), trees.prototypes.end(), name);
    if (it == trees.prototypes.end()) it = trees.prototypes.insert(it, name);
    double x = 0, y = 0, z = 0;
    frame.Forward(f.geometry.points[0].lat, f.geometry.points[0].lon, 0, x, y, z);
    trees.prototype.push_back(uint16_t(it - trees.prototypes.begin()));
    trees.position.insert(trees.position.end(),
                          {fault == "nan" ? NAN : float(x + shift), float(y), float(z)});
    trees.rotation.insert(trees.rotation.end(), {0, 0, 0, 1});
    trees.scale.insert(trees.scale.end(), {float(height), float(height), float(height)});
    trees.colour.push_back(attribute(f, "colour", uint32_t(0xff00ff00)));
    trees.provenance.push_back(provenance(f, tool));
    if (content.wants("volume") &&
        (content.volume("volume").vdb.empty() || fault == "volume_outside")) {
      maquette::VolumeContent& volume = content.volume("volume");
      const double volume_shift = fault == "volume_outside" ? kFaultShiftM : 0;
      const auto sphere = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
          float(kSphereRadiusM), openvdb::Vec3f(float(x + volume_shift), float(y), float(z)),
          float(kSphereVoxelM));
      volume = maquette::encode_volume({sphere}, volume.origin);
    }
  }
}

LonLat anchor(const VectorFeature& f) {
  const maquette::GeoPoint& p = f.geometry.type == GeometryType::Polygon
                                    ? f.geometry.polygons.front().rings.front().front()
                                    : f.geometry.points.front();
  return {p.lon, p.lat};
}

// A polygon or point at least params.min_height high.
bool has_object(const VectorFeature& f, const nlohmann::json& params) {
  return (f.geometry.type == GeometryType::Polygon || f.geometry.type == GeometryType::Point) &&
         attribute(f, "height", 10.0) >= params.at("min_height").get<double>();
}

class Content : public maquette::CellOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = content_spec("fixture.content", maquette::OperatorKind::Cell);
    return s;
  }
  void run(const maquette::CellContext& ctx, maquette::CellData& data) const override {
    std::this_thread::sleep_for(std::chrono::milliseconds(ctx.params->at("sleep_ms").get<int>()));
    for (const VectorFeature* f : data.features_of("strokes"))
      if (has_object(*f, *ctx.params) && ctx.owns(anchor(*f)))
        add_object(*f, spec().name, data.content);
  }
};

class RegionContent : public maquette::RegionOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s =
        content_spec("fixture.region_content", maquette::OperatorKind::Region);
    return s;
  }
  void run(const maquette::StepContext& ctx, const maquette::Mosaic& input,
           maquette::Mosaic& output) const override {
    if (output.content.empty()) return;
    const int level = output.content.begin()->first.level();
    for (const VectorFeature* f : input.features.at("strokes")) {
      if (!has_object(*f, *ctx.params)) continue;
      const auto owner = output.content.find(ctx.grid->cell_from_point(anchor(*f), level));
      // The tool of fixture.content: the same objects, so that the tests compare the blobs.
      if (owner != output.content.end()) add_object(*f, "fixture.content", owner->second);
    }
  }
};

}  // namespace

std::unique_ptr<maquette::Operator> make_content() { return std::make_unique<Content>(); }
std::unique_ptr<maquette::Operator> make_region_content() {
  return std::make_unique<RegionContent>();
}
