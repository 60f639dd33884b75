// deform.water through the real program, as a user runs it: a paraboloid basin z = r^2 / a
// (r: metres from its centre in the local tangent plane, GeographicLib) written as a lon/lat
// GeoTIFF and ingested as a DEM, a circular stroke (tool "water") ingested as features, the
// pipeline run by `maquette run`. The stored depths are level - terrain on the stored DEM, the
// wet pixels those below the level, the volume the paraboloid's closed form within 0.5 %, the
// lake's mesh and its fog volume stored once (the volume decoded with OpenVDB: the raster's
// volume within 1 %, the lake's extent), the bodies' artifact agreeing; a level above the rim fails
// naming the feature and the leak, writing nothing; overlapping strokes fail naming both; the same
// bits for 1 and 2 threads.
#include <gtest/gtest.h>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "circle_ring.h"
#include "content/content_blob.h"
#include "core/grid.h"
#include "egm96_oracle.h"
#include "gltf/mesh_glb.h"
#include "gpu_instancing_check.h"
#include "run_cli.h"
#include "store/store.h"
#include "stored_layers.h"
#include "synthetic_raster.h"

namespace maquette {
namespace {

using nlohmann::json;
using test::CliResult;
using test::run_maquette;

// The basin's centre.
struct Site {
  double lon = 0, lat = 0;
};
constexpr Site kZion{-112.0, 37.0};
constexpr double kA = 22500;                // z = 1000 + r^2 / kA: 100 m deep at 1500 m
constexpr double kHalfDeg = 0.04;           // the DEM: +-0.04 degrees (~3.5 x 4.4 km)
constexpr double kSourcePixelDeg = 1e-4;    // ~10 m
constexpr int kLevel = 12, kTileSize = 64;  // pixels of ~35 m

// Where the meridian `lon` leaves rHEALPix face N southwards (bisection on the latitude): a basin
// centred there lies on N and the face below it there.
Site seam_below_face_n(double lon) {
  double south = 30, north = 50;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (south + north);
    (default_grid().cell_from_point({lon, mid}, 0).face() == 0 ? north : south) = mid;
  }
  return {lon, 0.5 * (south + north)};
}

void write_dem(const std::string& path, const Site& site) {
  const GeographicLib::LocalCartesian frame(site.lat, site.lon, 0);
  test::write_raster(path,
                     test::lonlat_raster(site.lon - kHalfDeg, site.lat + kHalfDeg,
                                         int(std::lround(2 * kHalfDeg / kSourcePixelDeg)),
                                         kSourcePixelDeg, "Float32"),
                     [&](int, double lon, double lat) {
                       double x = 0, y = 0, h = 0;
                       frame.Forward(lat, lon, 0, x, y, h);
                       return 1000 + (x * x + y * y) / kA;
                     });
}

// A circle of `radius_m` around the basin's centre, tool "water", with `properties` added.
json stroke(double radius_m, const json& properties, const Site& site = kZion) {
  const json ring = test::circle_ring(site.lon, site.lat, radius_m, 72);
  json props = {{"tool", "water"}};
  props.update(properties);
  return {{"type", "FeatureCollection"},
          {"features",
           {{{"type", "Feature"},
             {"properties", props},
             {"geometry", {{"type", "Polygon"}, {"coordinates", {ring}}}}}}}};
}

// deform.water, then deform.water_bodies on its depths.
json water_steps() {
  return {
      {{"op", "deform.water"},
       {"inputs", {{"dem", "dem"}, {"strokes", "strokes"}}},
       {"outputs", {{"depth", "water_depth"}, {"mesh", "water_mesh"}, {"volume", "water_volume"}}}},
      {{"op", "deform.water_bodies"},
       {"inputs", {{"dem", "dem"}, {"depth", "water_depth"}, {"strokes", "strokes"}}},
       {"outputs", {{"bodies", "water_bodies"}}}}};
}

// Two strokes (features 1 and 2): circles of radii `a_m` and `b_m` around the basin's centre.
json two_strokes(double a_m, double b_m) {
  json strokes = stroke(a_m, json::object());
  strokes["features"].push_back(stroke(b_m, json::object())["features"][0]);
  return strokes;
}

// A store with the basin's DEM and the strokes, and the pipeline running `steps` on it.
struct Basin {
  std::string dir = test::temp_dir();
  std::string store = dir + "/basin.mqt";

  // `datum`: the DEM's vertical datum (maquette ingest --vertical-datum).
  explicit Basin(const json& strokes, const json& steps = water_steps(),
                 const std::string& datum = "ellipsoid", const Site& site = kZion) {
    write_dem(dir + "/dem.tif", site);
    std::ofstream(dir + "/strokes.geojson") << strokes.dump();
    const json pipeline = {
        {"store", store},
        {"region",
         {{"bbox",
           {site.lon - kHalfDeg, site.lat - kHalfDeg, site.lon + kHalfDeg, site.lat + kHalfDeg}}}},
        {"level", kLevel},
        {"steps", steps}};
    std::ofstream(dir + "/pipeline.json") << pipeline.dump(2);
    for (const std::string& args :
         {"ingest " + store + " " + dir + "/dem.tif --layer dem --as dem --vertical-datum " +
              datum + " --level " + std::to_string(kLevel) + " --tile-size " +
              std::to_string(kTileSize),
          "ingest " + store + " " + dir + "/strokes.geojson --layer strokes --as features"}) {
      const CliResult r = run_maquette("-q " + args);
      EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    }
  }
  CliResult run(const std::string& options = "") const {
    return run_maquette("-q run " + options + " " + dir + "/pipeline.json");
  }
};

// The lake's mesh as stored: the blob of its one holder cell.
std::string stored_lake_blob(const std::string& store) {
  const auto st = Store::open(store, Store::Mode::ReadOnly);
  const std::vector<CellId> holders = st->content_cells("water_mesh");
  if (holders.size() != 1)
    throw std::runtime_error("the lake's mesh is in " + std::to_string(holders.size()) +
                             " cells, not 1");
  return *st->get_content("water_mesh", holders[0]);
}

// The same, decoded (GLB).
MeshContent stored_lake_mesh(const std::string& store) {
  const std::string blob = stored_lake_blob(store);
  return decode_mesh_glb(content_payload(blob), read_content_envelope(blob, "water_mesh").origin,
                         "water_mesh");
}

struct Lake {
  size_t wet = 0;
  double volume_m3 = 0;
};

// The paraboloid basin centred at `site`, filled to 1100 m (the shore at r = 1500 m, the stroke
// at 2000 m), checked against the stored DEM and the closed form.
Lake expect_paraboloid_lake(const Site& site) {
  const double level = 1100;
  const Basin basin(stroke(2000, {{"level", level}}, site), water_steps(), "ellipsoid", site);
  const CliResult r = basin.run();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return {};

  const auto st = Store::open(basin.store, Store::Mode::ReadOnly);
  const double pixel_area = default_grid().area(0) / std::ldexp(1.0, 2 * (kLevel + 6));
  double volume = 0;
  size_t wet = 0;
  float lowest_bed = INFINITY;
  for (const CellId cell : st->tile_cells("dem")) {
    const Tile<float> dem = test::float_tile(*st, "dem", cell),
                      depth = test::float_tile(*st, "water_depth", cell);
    for (int row = 0; row < kTileSize; ++row)
      for (int col = 0; col < kTileSize; ++col) {
        const float z = dem.at(col, row), d = depth.at(col, row);
        EXPECT_EQ(std::isnan(d), std::isnan(z)) << cell.ToText();  // 0 on dry known terrain
        if (std::isnan(z)) continue;
        if (d > 0) {
          ++wet;
          volume += d;
          lowest_bed = std::min(lowest_bed, z);
          EXPECT_NEAR(d, level - z, 1e-4);
        } else {
          EXPECT_EQ(d, 0);
          EXPECT_GE(z, level);  // the basin has one lake: every pixel below the level is wet
        }
      }
  }
  volume *= pixel_area;
  const double h = level - 1000, expected = std::numbers::pi * kA * h * h / 2;
  EXPECT_GT(wet, 5000u);
  EXPECT_NEAR(volume, expected, 0.005 * expected);
  // The artifact of deform.water_bodies: the level within float32 rounding of the depths.
  const json bodies = json::parse(st->get_artifact("water_bodies")->text());
  EXPECT_EQ(bodies.size(), 1u) << bodies.dump();
  if (bodies.size() != 1) return {};
  EXPECT_EQ(bodies[0]["feature"], 1);
  EXPECT_NEAR(bodies[0]["level"].get<double>(), level, 1e-3);
  EXPECT_NEAR(bodies[0]["area_m2"].get<double>(), double(wet) * pixel_area, 1e-6);
  EXPECT_NEAR(bodies[0]["volume_m3"].get<double>(), volume, 1e-9 * volume);
  // One closed mesh (water_mesh_test.cpp checks its shape), stored once, in its owner cell: the
  // prism of the shoreline (no triangle per wet pixel), every vertex at the level or on the flat
  // bottom 1 m below the lowest bed (the DEM's heights: ellipsoidal here; the GLB's millimetres).
  const ContentLayerStats mesh = st->content_stats("water_mesh");
  EXPECT_EQ(mesh.cells, 1u);
  EXPECT_EQ(mesh.content.objects, 1u);
  EXPECT_LT(mesh.content.triangles, wet / 4);
  const MeshContent stored = stored_lake_mesh(basin.store);
  const GeographicLib::LocalCartesian mesh_frame(stored.origin.lat, stored.origin.lon,
                                                 stored.origin.height);
  size_t off_level_and_floor = 0;
  for (size_t k = 0; k + 2 < stored.objects.at(0).positions.size(); k += 3) {
    const float* p = &stored.objects[0].positions[k];
    double lat = 0, lon = 0, height = 0;
    mesh_frame.Reverse(p[0], p[1], p[2], lat, lon, height);
    off_level_and_floor +=
        std::abs(height - level) > 0.01 && std::abs(height - (double(lowest_bed) - 1)) > 0.01;
  }
  EXPECT_EQ(off_level_and_floor, 0u) << "of " << stored.objects[0].positions.size() / 3;

  // The lake's fog volume, stored once, decoded with OpenVDB: its active voxels hold the raster's
  // volume within 1 %; their bounding box is the lake: the disk of radius 1500 m around the
  // basin's centre, from the bottom (1000 m) to the level, within a voxel or two.
  const std::vector<CellId> holders = st->content_cells("water_volume");
  EXPECT_EQ(holders.size(), 1u);
  if (holders.size() != 1) return {};
  const std::string blob = *st->get_content("water_volume", holders[0]);
  const EnuOrigin origin = read_content_envelope(blob, "water_volume").origin;
  openvdb::initialize();
  std::istringstream in{std::string(content_payload(blob)), std::ios::binary};
  const openvdb::GridPtrVecPtr grids = openvdb::io::Stream(in).getGrids();
  EXPECT_EQ(grids->size(), 1u);
  const openvdb::FloatGrid::Ptr fog = openvdb::gridPtrCast<openvdb::FloatGrid>(grids->front());
  EXPECT_TRUE(fog);
  if (!fog) return {};
  EXPECT_EQ(fog->getGridClass(), openvdb::GRID_FOG_VOLUME);
  EXPECT_EQ(fog->getName(), "water");
  // The voxels are the pixels' lattice (turned by 90 degrees on face P), a voxel's volume its
  // transform's determinant.
  const double fog_volume = double(fog->activeVoxelCount()) * fog->transform().voxelVolume();
  EXPECT_NEAR(fog_volume, volume, 0.01 * volume);
  const openvdb::Vec3d sides = fog->voxelSize();
  const openvdb::Vec3d voxel(std::max(sides[0], sides[1]), std::max(sides[0], sides[1]), sides[2]);
  // The frame's box of the active voxels' centres (each tile's corner voxels).
  openvdb::Vec3d lo(INFINITY), hi(-INFINITY);
  for (auto v = fog->cbeginValueOn(); v; ++v) {
    openvdb::CoordBBox box;
    v.getBoundingBox(box);
    for (int corner = 0; corner < 8; ++corner) {
      const openvdb::Coord c((corner & 1 ? box.max() : box.min()).x(),
                             (corner & 2 ? box.max() : box.min()).y(),
                             (corner & 4 ? box.max() : box.min()).z());
      const openvdb::Vec3d p = fog->indexToWorld(c);
      lo = openvdb::math::minComponent(lo, p);
      hi = openvdb::math::maxComponent(hi, p);
    }
  }
  const GeographicLib::LocalCartesian frame(origin.lat, origin.lon, origin.height);
  double x = 0, y = 0, top = 0, bottom = 0;
  frame.Forward(site.lat, site.lon, level, x, y, top);
  frame.Forward(site.lat, site.lon, 1000, x, y, bottom);
  const double shore = std::sqrt(kA * h);  // 1500 m
  for (const int axis : {0, 1}) {
    EXPECT_NEAR((lo[axis] + hi[axis]) / 2, axis == 0 ? x : y, voxel[axis]) << "axis " << axis;
    EXPECT_NEAR(hi[axis] - lo[axis], 2 * shore, 3 * voxel[axis]) << "axis " << axis;
  }
  EXPECT_NEAR(hi[2], top, 2 * voxel[2]);
  EXPECT_NEAR(lo[2], bottom, 2 * voxel[2]);
  return {wet, volume};
}

TEST(DeformWater, ParaboloidBasinThroughTheProgram) { expect_paraboloid_lake(kZion); }

// The same basin centred on the seam of face N with O (unturned in the plane unfolded around N)
// and with P (turned by 90 degrees): the region's cells on both faces, pasted into one mosaic. The
// same checks, one body, its mesh and volume stored once (its voxels' box the lake's disk around
// the site: the lake's corners placed on the faces holding them), and the same lake as away from
// the seams (rHEALPix pixels are equal-area: the same wet count and volume within the
// pixelation's noise).
TEST(DeformWater, ParaboloidBasinAcrossFaceSeams) {
  const Lake away = expect_paraboloid_lake(kZion);
  for (const auto& [lon, beyond] : {std::pair{-130.0, 1}, {-40.0, 2}}) {
    const Site seam = seam_below_face_n(lon);
    const auto face = [&](double dlat) {
      return default_grid().cell_from_point({seam.lon, seam.lat + dlat}, 0).face();
    };
    ASSERT_EQ(face(0.005), 0);  // the lake (0.0135 degrees of latitude in radius) on both faces
    ASSERT_EQ(face(-0.005), beyond);
    const Lake across = expect_paraboloid_lake(seam);
    std::printf("lake across the seam of N and %c: %zu wet pixels, %.6g m3; away: %zu, %.6g m3\n",
                CellId::kFaceLetters[size_t(beyond)], across.wet, across.volume_m3, away.wet,
                away.volume_m3);
    EXPECT_NEAR(double(across.wet), double(away.wet), 0.005 * double(away.wet));
    EXPECT_NEAR(across.volume_m3, away.volume_m3, 0.005 * away.volume_m3);
  }
}

// On a DEM of EGM96 heights the lake's surface is at the level plus the geoid height N there, as
// the exported terrain is (N from PROJ: EGM96 height -> WGS 84 ellipsoidal, about -22 m here).
TEST(DeformWater, OnAnEgm96DemTheLakeSitsOnTheEllipsoidalTerrain) {
  const double level = 1100;
  const Basin basin(stroke(2000, {{"level", level}}), water_steps(), "egm96");
  const CliResult r = basin.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::Egm96ToEllipsoid to_ellipsoid;

  const MeshContent mesh = stored_lake_mesh(basin.store);
  ASSERT_EQ(mesh.objects.size(), 1u);
  const GeographicLib::LocalCartesian frame(mesh.origin.lat, mesh.origin.lon, mesh.origin.height);
  const std::vector<float>& p = mesh.objects[0].positions;
  // No vertex above the water's surface (level + N at its place), and the highest on it.
  double top = -INFINITY, top_surface = 0;
  for (size_t k = 0; k < p.size(); k += 3) {
    double lat = 0, lon = 0, h = 0;
    frame.Reverse(p[k], p[k + 1], p[k + 2], lat, lon, h);
    const double surface = to_ellipsoid(lon, lat, level);
    EXPECT_LT(surface, level - 10);  // N < 0 here: a lake left on the geoid would be far off
    EXPECT_LE(h, surface + 0.01);
    if (h > top) std::tie(top, top_surface) = std::pair(h, surface);
  }
  EXPECT_NEAR(top, top_surface, 0.01);
}

// The lake's mesh carries facet normals (CesiumJS draws a mesh without normals unlit): one unit
// normal per vertex, each triangle's corners holding its own face's normal (computed here from
// the decoded positions) within 2 degrees, so the surface's normals face up and the bottom's down
// (the flat bottom mirrors the surface: as many triangles);
// welded by position (a corner copied once per face orientation), the mesh is still closed and
// oriented: each edge once in each direction.
TEST(DeformWater, LakeMeshCarriesFacetNormals) {
  const double level = 1100;
  const Basin basin(stroke(2000, {{"level", level}}));
  const CliResult r = basin.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const MeshContent mesh = stored_lake_mesh(basin.store);
  ASSERT_EQ(mesh.objects.size(), 1u);
  const MeshObject& lake = mesh.objects[0];
  ASSERT_EQ(lake.normals.size(), lake.positions.size());
  const auto at = [](const std::vector<float>& v, uint32_t i) {
    return std::array<double, 3>{v[3 * i], v[3 * i + 1], v[3 * i + 2]};
  };
  for (size_t i = 0; i < lake.normals.size() / 3; ++i) {
    const auto n = at(lake.normals, uint32_t(i));
    ASSERT_NEAR(std::hypot(n[0], n[1], n[2]), 1, 1e-5) << "vertex " << i;
  }
  // A face within kFacetNormalTurnDeg (1 degree) of the first face of its group at a corner
  // shares that face's normal; the GLB rounds positions to the millimetre: 2 degrees.
  const double min_dot = std::cos(2 * std::numbers::pi / 180);
  size_t up = 0, down = 0;
  std::map<std::array<float, 3>, uint32_t> welded;
  const auto weld = [&](uint32_t i) {
    return welded
        .emplace(
            std::array{lake.positions[3 * i], lake.positions[3 * i + 1], lake.positions[3 * i + 2]},
            uint32_t(welded.size()))
        .first->second;
  };
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t + 2 < lake.indices.size(); t += 3) {
    const auto a = at(lake.positions, lake.indices[t]), b = at(lake.positions, lake.indices[t + 1]),
               c = at(lake.positions, lake.indices[t + 2]);
    const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
        w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    std::array<double, 3> face{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                               u[0] * w[1] - u[1] * w[0]};
    const double length = std::hypot(face[0], face[1], face[2]);
    ASSERT_GT(length, 0) << "triangle " << t / 3;
    for (double& x : face) x /= length;
    for (size_t k = 0; k < 3; ++k) {
      const auto n = at(lake.normals, lake.indices[t + k]);
      EXPECT_GT(n[0] * face[0] + n[1] * face[1] + n[2] * face[2], min_dot) << "triangle " << t / 3;
    }
    up += face[2] > 0.999;  // the surface (walls face sideways, the bottom down)
    down += face[2] < -0.5;
    const std::array<uint32_t, 3> v{weld(lake.indices[t]), weld(lake.indices[t + 1]),
                                    weld(lake.indices[t + 2])};
    for (size_t k = 0; k < 3; ++k) ++edges[{v[k], v[(k + 1) % 3]}];
  }
  EXPECT_GT(up, 100u);  // the surface's strips
  EXPECT_EQ(down, up);  // the flat bottom: the surface's triangles facing down
  for (const auto& [edge, count] : edges) {
    ASSERT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    ASSERT_EQ(edges.count({edge.second, edge.first}), 1u)
        << "edge " << edge.first << "-" << edge.second;
  }
  EXPECT_GT(lake.positions.size() / 3, welded.size());  // corners copied per orientation
  std::printf("lake mesh: %zu vertices with normals, %zu positions, %zu triangles\n",
              lake.positions.size() / 3, welded.size(), lake.indices.size() / 3);
}

// deform.water and deform.water_bodies with deform.water's params `params`.
json water_steps_with(const json& params) {
  json steps = water_steps();
  steps[0]["params"] = params;
  return steps;
}

// IEC 61966-2-1's transfer function: an sRGB component as a linear one.
double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Read from the stored GLB's own JSON (not through decode_mesh_glb): every primitive's material
// is "water", opaque, not metallic (glTF's default metallicFactor is 1), smooth (roughness at
// most 0.3, so it shows the sun's highlight), its base colour `srgb` in linear terms.
void expect_water_material(const std::string& store, const std::array<double, 3>& srgb) {
  const json gltf = test::split_glb(content_payload(stored_lake_blob(store))).json;
  size_t primitives = 0;
  for (const json& mesh : gltf.at("meshes"))
    for (const json& primitive : mesh.at("primitives")) {
      ++primitives;
      ASSERT_TRUE(primitive.contains("material"));
      const json& material = gltf.at("materials").at(primitive.at("material").get<size_t>());
      EXPECT_EQ(material.value("name", ""), "water");
      EXPECT_EQ(material.value("alphaMode", "OPAQUE"), "OPAQUE");
      const json& pbr = material.at("pbrMetallicRoughness");
      EXPECT_EQ(pbr.value("metallicFactor", 1.0), 0.0);
      EXPECT_LE(pbr.value("roughnessFactor", 1.0), 0.3);
      const json& colour = pbr.at("baseColorFactor");
      ASSERT_EQ(colour.size(), 4u);
      for (size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(colour[k].get<double>(), srgb_to_linear(srgb[k]), 1e-5) << k;
      EXPECT_EQ(colour[3].get<double>(), 1.0);
    }
  EXPECT_GE(primitives, 1u);
}

// By default the lake is a cartographer's blue-green, sRGB (0.25, 0.45, 0.55).
TEST(DeformWater, LakeMeshHasAWaterMaterial) {
  const Basin basin(stroke(2000, {{"level", 1100}}));
  const CliResult r = basin.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_water_material(basin.store, {0.25, 0.45, 0.55});
}

TEST(DeformWater, ColourParameterSetsTheLakesColour) {
  const Basin basin(stroke(2000, {{"level", 1100}}), water_steps_with({{"colour", {0.1, 0.6, 1}}}));
  const CliResult r = basin.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_water_material(basin.store, {0.1, 0.6, 1});
}

// A colour of two components, or one beyond 1, fails naming the parameter and value, and the
// step writes no mesh.
TEST(DeformWater, BadColourNamesTheParameterAndValue) {
  for (const auto& [colour, expected] :
       {std::pair{json{0.2, 0.3}, std::string("params.colour: expected 3 numbers (sRGB r, g, b in "
                                              "0..1), got [0.2,0.3]")},
        std::pair{json{0.2, 1.5, 0},
                  std::string("params.colour[1]: 1.5 is above the maximum 1")}}) {
    const Basin basin(stroke(2000, {{"level", 1100}}), water_steps_with({{"colour", colour}}));
    const CliResult r = basin.run();
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    const auto st = Store::open(basin.store, Store::Mode::ReadOnly);
    EXPECT_FALSE(st->layer("water_mesh") && !st->content_cells("water_mesh").empty());
  }
}

TEST(DeformWater, SameBitsForOneAndTwoThreads) {
  const Basin one(stroke(2000, json::object())), two(stroke(2000, json::object()));  // spill
  ASSERT_EQ(one.run("-t 1").exit_code, 0);
  ASSERT_EQ(two.run("-t 2").exit_code, 0);
  const auto a = Store::open(one.store, Store::Mode::ReadOnly);
  const auto b = Store::open(two.store, Store::Mode::ReadOnly);
  EXPECT_GT(test::expect_same_tiles(*a, *b, "water_depth"), 0u);
  EXPECT_EQ(test::expect_same_content(*a, *b, "water_mesh"), 1u);
  EXPECT_EQ(test::expect_same_content(*a, *b, "water_volume"), 1u);
}

// Under mpirun with 2 ranks (the step runs once, on rank 0; the other rank's cells are written
// through it): the same depth tiles, mesh and volume as one thread.
TEST(DeformWater, SameBitsOnTwoMpiRanks) {
#ifdef MAQUETTE_MPIEXEC
  const Basin one(stroke(2000, json::object())), two(stroke(2000, json::object()));
  ASSERT_EQ(one.run("-t 1").exit_code, 0);
  const std::string command = std::string(MAQUETTE_MPIEXEC) +
                              " --oversubscribe --allow-run-as-root -np 2 " + MAQUETTE_BIN_DIR +
                              "/maquette -q run --threads 1 " + two.dir + "/pipeline.json 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const auto a = Store::open(one.store, Store::Mode::ReadOnly);
  const auto b = Store::open(two.store, Store::Mode::ReadOnly);
  EXPECT_GT(test::expect_same_tiles(*a, *b, "water_depth"), 0u);
  EXPECT_EQ(test::expect_same_content(*a, *b, "water_mesh"), 1u);
  EXPECT_EQ(test::expect_same_content(*a, *b, "water_volume"), 1u);
#else
  GTEST_SKIP() << "built without MPI: 2 ranks not tested";
#endif
}

TEST(DeformWater, LevelAboveTheRimFailsNamingTheLeak) {
  const Basin basin(stroke(2000, {{"level", 1250}}));  // the rim is at ~1178 m
  const CliResult r = basin.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("feature 1 (tool water): at level 1250"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("leaks out of the stroke at lon -112."), std::string::npos) << r.err;
  const auto st = Store::open(basin.store, Store::Mode::ReadOnly);
  EXPECT_FALSE(st->layer("water_depth") && !st->tile_cells("water_depth").empty());
}

TEST(DeformWater, BadLevelRuleNamesTheFieldAndValue) {
  const Basin basin(stroke(2000, {{"level_rule", "percentile:x"}}));
  const CliResult r = basin.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("feature 1 (tool water): field 'level_rule'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\"percentile:x\""), std::string::npos) << r.err;
}

TEST(DeformWater, StrokeHoldingNoPixelCentreNamesTheFeature) {
  const Basin basin(stroke(0.01, json::object()));  // 1 cm around the centre; pixels of 35 m
  const CliResult r = basin.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("feature 1 (tool water): no terrain height known on the stroke's boundary"),
            std::string::npos)
      << r.err;
}

TEST(DeformWater, OverlappingStrokesFailNamingBoth) {
  const Basin basin(two_strokes(2000, 1000));  // the second inside the first
  const CliResult r = basin.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("feature 1 (tool water) and feature 2 (tool water) overlap at lon -112."),
            std::string::npos)
      << r.err;
  const auto st = Store::open(basin.store, Store::Mode::ReadOnly);
  EXPECT_FALSE(st->layer("water_depth") && !st->tile_cells("water_depth").empty());
}

// deform.water_bodies alone, on depths that deform.water did not make (the DEM's heights: every
// pixel wet), with overlapping strokes: it fails rather than count the shared water twice.
TEST(DeformWater, BodiesOfOverlappingStrokesFailNamingBoth) {
  const Basin basin(two_strokes(2000, 1000),
                    {{{"op", "deform.water_bodies"},
                      {"inputs", {{"dem", "dem"}, {"depth", "dem"}, {"strokes", "strokes"}}},
                      {"outputs", {{"bodies", "water_bodies"}}}}});
  const CliResult r = basin.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("feature 1 (tool water) and feature 2 (tool water) overlap at lon -112."),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace maquette
