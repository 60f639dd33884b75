// Content outputs (runtime/operator.h: CellContent) through the real program: polygons and points
// written by the test as GeoJSON, ingested with `maquette ingest --as features`, turned by the
// fixture operators (tests/modules_fixture/fixture_content.cpp) into prisms (a mesh layer) and
// trees (an instances layer) that `maquette run` checks, encodes and stores. What is stored is
// decoded (formats/gltf's mesh GLB, the instances codec) and compared with an independent
// computation: the corners' east-north-up coordinates by PROJ (cart + topocentric) at the cell's
// origin, the owning cell from the grid; and level-set spheres (a volume layer) decoded by OpenVDB,
// centred where PROJ puts their point. Same bits with 1 and 2 threads, 1, 2 and 3 MPI ranks,
// the cell and region operators, and after SIGKILL then --resume; the contract's faults name the
// step, the cell, the port and the feature, and store nothing of the cell.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "content/content_blob.h"
#include "content/instances_codec.h"
#include "core/grid.h"
#include "fixture_features.h"
#include "gltf/mesh_glb.h"
#include "proj_enu.h"
#include "run_cli.h"
#include "store/store.h"
#include "test_util.h"
#include "vdb/volume_vdb.h"

namespace maquette {
namespace {

using nlohmann::json;
using test::CliResult;
using test::run_maquette;

constexpr int kLevel = 12;  // cells of about 2.4 km
const std::vector<double> kBox = {10.0, 45.0, 10.1, 45.1};
const std::string kEnv =
    std::string("MAQUETTE_MODULE_PATH=") + MAQUETTE_FIXTURE_MODULE_DIR + "/good";
// mesh_glb's quantization (at most 1 mm a step: within half of it) plus float32 rounding of
// coordinates within a few km of the origin.
constexpr double kMeshTolerance = 0.0005 + 0.0002;
constexpr double kInstanceTolerance = 0.0002;  // float32 rounding only: the codec is lossless

// Deterministic pseudo-random numbers in [0, 1).
struct Lcg {
  uint64_t state = 4242;
  double next() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) / double(1ull << 53);
  }
};

struct Feature {
  int64_t id = 0;
  std::vector<LonLat> corners;  // a polygon's outer ring without the closing point, or a point
  bool polygon = false;
  double height = 0;
  uint32_t colour = 0;
};

// Squares (counter-clockwise) and points over and around the region, ids 1.. (the ingest's fids:
// positions in the file); `fault` adds one faulty feature at the region's centre (its attribute
// "fault" or "prototype", fixture_content.cpp).
struct Strokes {
  json collection;
  std::vector<Feature> features;
};

Strokes make_strokes(const json& fault = nullptr) {
  Lcg rng;
  Strokes s;
  json list = json::array();
  const auto add = [&](Feature f, json properties) {
    f.id = int64_t(s.features.size()) + 1;
    json ring = json::array();
    for (const LonLat& p : f.corners) ring.push_back({p.lon, p.lat});
    json geometry = {{"type", "Point"}, {"coordinates", ring[0]}};
    if (f.polygon) {
      ring.push_back(ring[0]);
      geometry = {{"type", "Polygon"}, {"coordinates", json::array({ring})}};
    }
    properties["height"] = f.height;
    properties["colour"] = f.colour;
    list.push_back(
        {{"type", "Feature"}, {"id", f.id}, {"properties", properties}, {"geometry", geometry}});
    s.features.push_back(f);
  };
  const auto random_point = [&] {
    return LonLat{kBox[0] - 0.02 + 0.14 * rng.next(), kBox[1] - 0.02 + 0.14 * rng.next()};
  };
  for (int i = 0; i < 40; ++i) {
    const LonLat c = random_point();
    const double h = 0.0003 + 0.0008 * rng.next();
    Feature f;
    f.polygon = true;
    f.corners = {{c.lon - h, c.lat - h},
                 {c.lon + h, c.lat - h},
                 {c.lon + h, c.lat + h},
                 {c.lon - h, c.lat + h}};
    f.height = 5 + std::floor(40 * rng.next());
    f.colour = 0xff000000u | uint32_t(rng.next() * 0xffffff);
    add(f, {{"kind", "building"}});
  }
  for (int i = 0; i < 40; ++i) {
    Feature f;
    f.corners = {random_point()};
    f.height = 3 + std::floor(20 * rng.next());
    f.colour = 0xff000000u | uint32_t(rng.next() * 0xffffff);
    add(f, {{"kind", "tree"}});
  }
  if (!fault.is_null()) {
    Feature f;
    f.polygon = fault.value("polygon", false);
    const LonLat c{0.5 * (kBox[0] + kBox[2]), 0.5 * (kBox[1] + kBox[3])};
    f.corners = {c};
    if (f.polygon) f.corners = {c, {c.lon + 0.0005, c.lat}, {c.lon + 0.0005, c.lat + 0.0005}};
    f.height = 10;
    add(f, fault.at("properties"));
  }
  s.collection = {{"type", "FeatureCollection"}, {"features", list}};
  return s;
}

std::set<CellId> region_cells() {
  const auto cells =
      default_grid().cover_bbox(kBox[0], kBox[1], kBox[2], kBox[3], kLevel, Containment::Overlap);
  return {cells.begin(), cells.end()};
}

struct StoreDir {
  test::TempDir dir;
  std::string store = dir.file("out.mqt");
};

void ingest(const StoreDir& s, const Strokes& strokes) {
  std::ofstream(s.dir.file("strokes.geojson")) << strokes.collection.dump();
  const CliResult r = run_maquette("-q ingest " + s.store + " --layer strokes --as features " +
                                   s.dir.file("strokes.geojson"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

json content_step(const std::string& op = "fixture.content", int sleep_ms = 0) {
  json step = {{"op", op},
               {"inputs", {{"strokes", "strokes"}}},
               {"outputs", {{"mesh", "prisms"}, {"trees", "trees"}, {"volume", "spheres"}}}};
  if (sleep_ms > 0) step["params"] = {{"sleep_ms", sleep_ms}};
  return step;
}

std::string write_pipeline(const StoreDir& s, const json& step) {
  const json doc = {{"store", "out.mqt"},
                    {"region", {{"bbox", kBox}}},
                    {"level", kLevel},
                    {"tile_size", 4},
                    {"steps", json::array({step})}};
  std::ofstream(s.dir.file("pipeline.json")) << doc.dump(2);
  return s.dir.file("pipeline.json");
}

CliResult run(const StoreDir& s, const json& step, const std::string& options = "") {
  return run_maquette("-q run " + options + " " + write_pipeline(s, step), kEnv);
}

double distance(const std::array<double, 3>& a, const float* b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

TEST(ContentOutput, StoredContentMatchesAnIndependentComputation) {
  const Strokes strokes = make_strokes();
  StoreDir s;
  ingest(s, strokes);
  const CliResult r = run(s, content_step(), "--threads 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto store = Store::open(s.store, Store::Mode::ReadOnly);
  const std::set<CellId> region = region_cells();
  // The runner built the coarser levels of every content output (content/content_overviews.h).
  for (const char* layer : {"prisms", "trees", "spheres"})
    EXPECT_FALSE(store->content_cells(layer, kLevel - 1).empty()) << layer;

  // Every feature anchored in a region cell is stored once, in that cell; no other is.
  std::map<int64_t, CellId> expected_owner;
  for (const Feature& f : strokes.features) {
    const CellId owner = default_grid().cell_from_point(f.corners.front(), kLevel);
    if (region.count(owner)) expected_owner[f.id] = owner;
  }
  std::map<int64_t, CellId> stored_owner;
  size_t polygons = 0, points = 0, cells_with_both = 0;
  for (const CellId cell : store->content_cells("prisms")) {
    const std::string blob = *store->get_content("prisms", cell);
    const ContentEnvelope envelope = read_content_envelope(blob, "prisms");
    // The runner's origin: the cell's centre at height 0.
    EXPECT_EQ(envelope.origin.lon, default_grid().centre(cell).lon);
    EXPECT_EQ(envelope.origin.lat, default_grid().centre(cell).lat);
    EXPECT_EQ(envelope.origin.height, 0);
    const MeshContent mesh = decode_mesh_glb(content_payload(blob), envelope.origin, "prisms");
    EXPECT_EQ(envelope.stats.objects, mesh.objects.size());
    const test::ProjEnu enu(envelope.origin.lon, envelope.origin.lat, envelope.origin.height);
    for (const MeshObject& o : mesh.objects) {
      const Feature& f = strokes.features.at(size_t(o.provenance.feature_id - 1));
      SCOPED_TRACE("feature " + std::to_string(f.id) + ", cell " + cell.ToText());
      ASSERT_TRUE(f.polygon);
      EXPECT_TRUE(stored_owner.emplace(f.id, cell).second) << "stored twice";
      EXPECT_EQ(o.provenance.object_id, uint64_t(f.id));
      EXPECT_EQ(o.provenance.tool, "fixture.content");
      EXPECT_EQ(o.provenance.attributes.at("height"), f.height);
      EXPECT_EQ(o.provenance.attributes.at("colour"), f.colour);
      EXPECT_EQ(o.provenance.attributes.at("kind"), "building");
      const size_t n = f.corners.size();
      // A prism: n sides of 2 triangles, a top and a bottom of n - 2.
      ASSERT_EQ(o.positions.size(), 3 * 2 * n);
      EXPECT_EQ(o.indices.size(), 3 * (2 * n + 2 * (n - 2)));
      for (const double h : {0.0, f.height})
        for (const LonLat& corner : f.corners) {
          const auto expected = enu(corner, h);
          double nearest = INFINITY;
          for (size_t v = 0; v < o.positions.size(); v += 3)
            nearest = std::min(nearest, distance(expected, &o.positions[v]));
          EXPECT_LE(nearest, kMeshTolerance) << "corner at height " << h;
        }
      ++polygons;
    }
    cells_with_both += store->get_content("trees", cell).has_value();
  }
  for (const CellId cell : store->content_cells("trees")) {
    const InstancesContent trees = unwrap_instances(*store->get_content("trees", cell), "trees");
    EXPECT_EQ(trees.origin.lon, default_grid().centre(cell).lon);
    EXPECT_EQ(trees.origin.lat, default_grid().centre(cell).lat);
    const test::ProjEnu enu(trees.origin.lon, trees.origin.lat, trees.origin.height);
    ASSERT_EQ(trees.provenance.size(), trees.size());
    EXPECT_EQ(trees.prototypes, std::vector<std::string>{"builtin:conifer"});
    for (size_t i = 0; i < trees.size(); ++i) {
      const Feature& f = strokes.features.at(size_t(trees.provenance[i].feature_id - 1));
      SCOPED_TRACE("feature " + std::to_string(f.id) + ", cell " + cell.ToText());
      ASSERT_FALSE(f.polygon);
      EXPECT_TRUE(stored_owner.emplace(f.id, cell).second) << "stored twice";
      EXPECT_LE(distance(enu(f.corners[0], 0), &trees.position[3 * i]), kInstanceTolerance);
      EXPECT_EQ(trees.scale[3 * i], float(f.height));
      EXPECT_EQ(trees.scale[3 * i + 2], float(f.height));
      EXPECT_EQ(trees.colour[i], f.colour);
      EXPECT_EQ(trees.provenance[i].attributes.at("kind"), "tree");
      ++points;
    }
  }
  EXPECT_EQ(stored_owner, expected_owner);

  // A sphere in each cell holding trees, centred on its first tree (the lowest feature id).
  const std::vector<CellId> sphere_cells = store->content_cells("spheres");
  EXPECT_EQ(sphere_cells, store->content_cells("trees"));
  for (const CellId cell : sphere_cells) {
    SCOPED_TRACE("cell " + cell.ToText());
    const std::string blob = *store->get_content("spheres", cell);
    const ContentEnvelope envelope = read_content_envelope(blob, "spheres");
    VolumeContent volume{envelope.origin, std::string(content_payload(blob))};
    const openvdb::GridPtrVec grids = decode_volume(volume, "spheres");
    ASSERT_EQ(grids.size(), 1u);
    EXPECT_EQ(envelope.stats.objects, 1u);
    EXPECT_EQ(envelope.stats.voxels, grids[0]->activeVoxelCount());
    int64_t first = INT64_MAX;
    for (const auto& [id, owner] : stored_owner)
      if (owner == cell && !strokes.features.at(size_t(id - 1)).polygon)
        first = std::min(first, id);
    const auto expected =
        test::ProjEnu(envelope.origin.lon, envelope.origin.lat, envelope.origin.height)(
            strokes.features.at(size_t(first - 1)).corners[0], 0);
    const openvdb::Vec3d centre =
        grids[0]->indexToWorld(grids[0]->evalActiveVoxelBoundingBox().getCenter());
    const float got[3] = {float(centre.x()), float(centre.y()), float(centre.z())};
    EXPECT_LE(distance(expected, got), kSphereVoxelM);
    // The active voxels: the sphere and the narrow band of OpenVDB's level sets (3 voxels a side).
    EXPECT_NEAR(grids[0]->evalActiveVoxelBoundingBox().dim().x() * kSphereVoxelM,
                2 * (kSphereRadiusM + openvdb::LEVEL_SET_HALF_WIDTH * kSphereVoxelM),
                kSphereVoxelM);
  }
  // The data covers the cases: several cells of each layer, features delivered to cells that do
  // not own them (squares across an edge: within reach of both), features outside the region.
  EXPECT_GT(polygons, 15u);
  EXPECT_GT(points, 15u);
  EXPECT_GT(cells_with_both, 3u);
  EXPECT_LT(expected_owner.size(), strokes.features.size());
  size_t across = 0;
  for (const Feature& f : strokes.features)
    if (f.polygon) {
      std::set<CellId> cells;
      for (const LonLat& p : f.corners) cells.insert(default_grid().cell_from_point(p, kLevel));
      across += cells.size() > 1;
    }
  EXPECT_GT(across, 0u);
}

// A re-run whose parameters empty cells (fixture params.min_height 25: no tree, the lower
// buildings gone) removes what the first run wrote in them, in every content layer and at the
// coarser levels: the store then holds what a first run with those parameters writes.
TEST(ContentOutput, ReRunThatEmptiesCellsRemovesTheirContent) {
  constexpr double kMinHeight = 25;  // trees are 3-22 m, buildings 5-44 m
  const Strokes strokes = make_strokes();
  StoreDir s;
  ingest(s, strokes);
  ASSERT_EQ(run(s, content_step(), "--threads 1").exit_code, 0);
  const auto cells = [&](const char* layer, int level) {
    const auto store = Store::open(s.store, Store::Mode::ReadOnly);
    const auto list = store->content_cells(layer, level);
    return std::set<CellId>(list.begin(), list.end());
  };
  const std::set<CellId> first_prisms = cells("prisms", kLevel);
  std::set<int> built;  // the levels the runner built overviews at
  for (int level = 0; level < kLevel; ++level)
    if (!cells("prisms", level).empty()) built.insert(level);
  ASSERT_TRUE(built.count(kLevel - 1));
  ASSERT_FALSE(cells("trees", kLevel).empty());
  ASSERT_FALSE(cells("spheres", kLevel - 1).empty());

  json step = content_step();
  step["params"] = {{"min_height", kMinHeight}};
  const CliResult r = run(s, step, "--threads 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;

  // The buildings of at least kMinHeight, in their owner cells; every other cell emptied.
  const std::set<CellId> region = region_cells();
  std::map<CellId, size_t> expected;
  for (const Feature& f : strokes.features)
    if (const CellId owner = default_grid().cell_from_point(f.corners.front(), kLevel);
        f.polygon && f.height >= kMinHeight && region.count(owner))
      ++expected[owner];
  std::set<CellId> expected_cells;
  for (const auto& [cell, n] : expected) expected_cells.insert(cell);
  ASSERT_FALSE(expected_cells.empty());
  ASSERT_LT(expected_cells.size(), first_prisms.size()) << "the re-run should empty some cells";
  EXPECT_EQ(cells("prisms", kLevel), expected_cells);
  {
    const auto store = Store::open(s.store, Store::Mode::ReadOnly);
    for (const auto& [cell, n] : expected) {
      const std::string blob = *store->get_content("prisms", cell);
      const MeshContent mesh = decode_mesh_glb(
          content_payload(blob), read_content_envelope(blob, "prisms").origin, "prisms");
      EXPECT_EQ(mesh.objects.size(), n) << cell.ToText();
      for (const MeshObject& o : mesh.objects)
        EXPECT_GE(o.provenance.attributes.at("height").get<double>(), kMinHeight);
    }
  }
  for (int level = kLevel; level >= 0; --level) {
    SCOPED_TRACE("level " + std::to_string(level));
    std::set<CellId> parents;
    if (built.count(level))
      for (const CellId cell : expected_cells) parents.insert(cell.parent(level));
    EXPECT_EQ(cells("prisms", level), level < kLevel ? parents : expected_cells);
    EXPECT_TRUE(cells("trees", level).empty());
    EXPECT_TRUE(cells("spheres", level).empty());
  }
  StoreDir fresh;
  ingest(fresh, strokes);
  ASSERT_EQ(run(fresh, step, "--threads 1").exit_code, 0);
  EXPECT_EQ(test::first_difference(test::snapshot(s.store), test::snapshot(fresh.store)), "");
}

TEST(ContentOutput, ThreadsRanksAndRegionOperatorsGiveTheSameBits) {
  const Strokes strokes = make_strokes();
  StoreDir one;
  ingest(one, strokes);
  const CliResult r1 = run(one, content_step(), "--threads 1");
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  const test::Snapshot expected = test::snapshot(one.store);
  ASSERT_GT(expected.size(), 10u);

  StoreDir two;
  ingest(two, strokes);
  const CliResult r2 = run(two, content_step(), "--threads 2");
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  EXPECT_EQ(test::first_difference(test::snapshot(two.store), expected), "");

  // A region operator putting each object in its owner's content writes the same blobs.
  StoreDir region;
  ingest(region, strokes);
  const CliResult rr = run(region, content_step("fixture.region_content"));
  ASSERT_EQ(rr.exit_code, 0) << rr.err;
  EXPECT_EQ(test::first_difference(test::snapshot(region.store), expected), "");
#ifdef MAQUETTE_MPIEXEC
  for (const int ranks : {2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    StoreDir s;
    ingest(s, strokes);
    const std::string command =
        std::string("env ") + kEnv + " " + MAQUETTE_MPIEXEC +
        " --oversubscribe --allow-run-as-root -x MAQUETTE_MODULE_PATH -np " +
        std::to_string(ranks) + " " + MAQUETTE_BIN_DIR + "/maquette -q run --threads 1 " +
        write_pipeline(s, content_step()) + " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << test::shell_output(command);
    EXPECT_EQ(test::first_difference(test::snapshot(s.store), expected), "");
  }
#else
  GTEST_SKIP() << "built without MPI: 2 and 3 ranks not tested";
#endif
}

// The real program killed with SIGKILL while writing content, then --resume: the same bits.
TEST(ContentOutput, ResumeAfterSigkillIsBitIdentical) {
  using Clock = std::chrono::steady_clock;
  const Strokes strokes = make_strokes();
  const json step = content_step("fixture.content", 40);  // ~30 cells: about a second a run
  StoreDir reference;
  ingest(reference, strokes);
  const auto start = Clock::now();
  const CliResult r = run(reference, step, "--threads 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto full = Clock::now() - start;
  const test::Snapshot expected = test::snapshot(reference.store);

  const auto kill_and_resume = [&](double fraction) {
    SCOPED_TRACE("killed after " + std::to_string(fraction) + " of a run");
    StoreDir s;
    ingest(s, strokes);
    const std::string pipeline = write_pipeline(s, step);
    const int pid = test::spawn_maquette("-q run --threads 1 " + pipeline, kEnv);
    std::this_thread::sleep_for(std::chrono::duration_cast<Clock::duration>(full * fraction));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    const bool killed = WIFSIGNALED(status);
    size_t partial = 0;
    {
      const auto store = Store::open(s.store, Store::Mode::ReadOnly);
      EXPECT_TRUE(store->integrity_ok());
      if (store->layer("prisms")) partial = store->content_cells("prisms").size();
    }
    const CliResult resumed = run_maquette("-q run --threads 2 --resume " + pipeline, kEnv);
    EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_EQ(test::first_difference(test::snapshot(s.store), expected), "");
    return killed && partial > 0;
  };
  int killed_mid_run = 0;
  for (const double fraction : {0.3, 0.5, 0.7}) killed_mid_run += kill_and_resume(fraction);
  for (int extra = 0; extra < 6 && killed_mid_run < 2; ++extra)
    killed_mid_run += kill_and_resume(0.35 + 0.05 * extra);
  EXPECT_GE(killed_mid_run, 2) << "the kills should have interrupted runs with some cells written";
}

// A fault of the contract fails the run naming the step, the cell, the port and the feature, and
// nothing of that cell is stored.
TEST(ContentOutput, FaultsNameStepCellPortAndFeature) {
  const LonLat centre{0.5 * (kBox[0] + kBox[2]), 0.5 * (kBox[1] + kBox[3])};
  const CellId cell = default_grid().cell_from_point(centre, kLevel);
  struct Case {
    json fault;
    std::string object;   // "outputs.PORT: OBJECT N"
    std::string message;  // after the object's index
  };
  const std::vector<Case> cases = {
      {{{"polygon", true}, {"properties", {{"fault", "outside"}}}},
       "outputs.mesh: mesh object ",
       " (feature 81): its anchor at lon 10.6"},
      {{{"polygon", true}, {"properties", {{"fault", "nan"}}}},
       "outputs.mesh: mesh object ",
       " (feature 81): vertex 0 at (nan, "},
      {{{"properties", {{"fault", "outside"}}}},
       "outputs.trees: instance ",
       " (feature 81): its anchor at lon 10.6"},
      {{{"properties", {{"fault", "nan"}}}},
       "outputs.trees: instance ",
       " (feature 81): position (nan, "},
      {{{"properties", {{"fault", "volume_outside"}}}},
       "outputs.volume: volume grid ",
       "0: its anchor at lon 10.6"},
      {{{"properties", {{"prototype", "builtin:palm"}}}},
       "outputs.trees: instance ",
       " (feature 81): unknown prototype 'builtin:palm' (known: builtin:conifer, "
       "builtin:broadleaf, builtin:shrub"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.fault.dump());
    const Strokes strokes = make_strokes(c.fault);
    ASSERT_EQ(strokes.features.size(), 81u);
    StoreDir s;
    ingest(s, strokes);
    const CliResult r = run(s, content_step(), "--threads 2");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("step 1 (fixture.content) failed on cell " + cell.ToText() + ": "),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find(c.object), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    const auto store = Store::open(s.store, Store::Mode::ReadOnly);
    EXPECT_FALSE(store->get_content("prisms", cell));
    EXPECT_FALSE(store->get_content("trees", cell));
    EXPECT_EQ(test::run_statuses(s.store).back().rfind("failed: ", 0), 0u);
  }
}

}  // namespace
}  // namespace maquette
