// Coarser levels of an instances layer (content/content_overviews.h, instances_thin.h): exactly
// the instances the rule keeps, bit for bit but re-origined (positions and rotations) and
// widened, their expected cover kept, whatever order cells are written in.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <bit>
#include <cmath>
#include <random>
#include <set>

#include "../store/store_test_util.h"
#include "content/content_blob.h"
#include "content/content_overviews.h"
#include "content/instances_codec.h"
#include "content/instances_thin.h"
#include "content/prototypes.h"
#include "core/grid.h"
#include "gltf/mesh_glb.h"
#include "lod_fixture.h"

namespace maquette::test {
namespace {

constexpr size_t kPerCell = 625;  // 10,000 instances over the 16 cells

// The instances of one base cell: random positions within 150 m of its centre, provenance with
// random object ids (`provenance` false: none, thinned by their bits).
InstancesContent cell_instances(CellId cell, bool provenance) {
  std::mt19937_64 random(cell.id());
  std::uniform_real_distribution<float> xy(-150, 150), z(-5, 40), unit(-1, 1);
  InstancesContent c;
  c.origin = base_origin(cell);
  c.prototypes = {"builtin:conifer", "builtin:broadleaf", "builtin:shrub"};
  for (size_t i = 0; i < kPerCell; ++i) {
    c.prototype.push_back(uint16_t(random() % 3));
    c.position.insert(c.position.end(), {xy(random), xy(random), z(random)});
    const float angle = unit(random) * 3.14159f;
    c.rotation.insert(c.rotation.end(), {0, 0, std::sin(angle / 2), std::cos(angle / 2)});
    const float s = 0.5f + 0.5f * std::abs(unit(random));
    c.scale.insert(c.scale.end(), {s, s, s * 1.5f});
    c.colour.push_back(uint32_t(random()));
    if (provenance) c.provenance.push_back({random(), int64_t(i), "test.trees", {{"n", i}}});
  }
  return c;
}

void write_cells(Store& store, const std::vector<CellId>& cells, bool provenance) {
  Store::Batch batch(store);
  for (CellId cell : cells)
    batch.put_content("trees", cell, wrap_instances(cell_instances(cell, provenance)));
  batch.commit();
}

InstancesContent read(const Store& store, CellId cell) {
  return unwrap_instances(*store.get_content("trees", cell), "trees " + cell.ToText());
}

// Keeps an instance of the base (with provenance) at `depth` levels above: the rule of
// instances_thin.h, recomputed from its definition.
// `v` turned by the unit quaternion q (x, y, z, w): v + 2w (q x v) + 2 q x (q x v).
std::array<double, 3> rotate(const float* q, const std::array<double, 3>& v) {
  const auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                 a[0] * b[1] - a[1] * b[0]};
  };
  const std::array<double, 3> u{q[0], q[1], q[2]};
  const auto t = cross(u, v), tt = cross(u, t);
  return {v[0] + 2 * q[3] * t[0] + 2 * tt[0], v[1] + 2 * q[3] * t[1] + 2 * tt[1],
          v[2] + 2 * q[3] * t[2] + 2 * tt[2]};
}

// The level `depth` levels above the base's sample.
double sample_at(int depth) {
  return default_grid().level_info(kBaseLevel - depth, 1).cell_side_m / kContentSamples;
}

// The larger side of a built-in prototype's horizontal bounding box (metres at scale 1).
double prototype_extent(const std::string& name) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const MeshObject& o : make_builtin_prototype(name).objects)
    for (size_t v = 0; v < o.positions.size(); v += 3)
      for (size_t k = 0; k < 2; ++k)
        lo[k] = std::min(lo[k], double(o.positions[v + k])),
        hi[k] = std::max(hi[k], double(o.positions[v + k]));
  return std::max(hi[0] - lo[0], hi[1] - lo[1]);
}

// An instance of the base (with provenance) as the rule of instances_thin.h, recomputed from its
// definition, keeps it `depth` levels above: whether it survives, and its width there (metres).
struct Fate {
  bool kept = true;
  double width = 0;
};
// The fate of an instance `width` metres wide at the base whose object id is `id`: a plant is
// widened to each level's sample; a model keeps its width and survives from level to level with
// the ratio of the shares of its width at the two samples.
Fate fate_of(double width, uint64_t id, int depth, bool model = false) {
  Fate f{true, width};
  const auto share = [](double w, double sample) {
    return std::min(1.0, (w / sample) * (w / sample));
  };
  for (int d = 1; d <= depth && f.kept; ++d) {
    const double sample = sample_at(d);
    f.kept =
        instance_draw(id, d) < (model ? share(f.width, sample) / share(f.width, sample_at(d - 1))
                                      : share(f.width, sample));
    if (!model) f.width = std::max(f.width, sample);
  }
  return f;
}
Fate fate(const InstancesContent& base, size_t i, int depth) {
  return fate_of(prototype_extent(base.prototypes[base.prototype[i]]) *
                     std::max(base.scale[3 * i], base.scale[3 * i + 1]),
                 base.provenance[i].object_id, depth);
}

TEST(InstancesLod, LevelsKeepExactlyTheRulesInstancesBitForBit) {
  TempDir dir;
  auto store = content_store(dir.file("a.mqs"), "trees", LayerKind::Instances);
  write_cells(*store, base_cells(), true);
  update_content_overviews(*store, "trees");

  std::set<uint64_t> stored;
  for (CellId cell : base_cells()) stored.insert(cell.id());
  // The cover (sum of widths squared) of the base: the expected cover of every level.
  double base_cover = 0;
  for (CellId base : base_cells()) {
    const InstancesContent original = cell_instances(base, true);
    for (size_t i = 0; i < original.size(); ++i)
      base_cover += std::pow(fate(original, i, 0).width, 2);
  }
  int levels_covered = 0;
  for (int level = kBaseLevel - 1; level >= 0; --level) {
    const int depth = kBaseLevel - level;
    size_t total = 0;
    double cover = 0;
    for (CellId cell : store->content_cells("trees", level)) {
      const InstancesContent got = read(*store, cell);
      // The parent's origin: its centre at the mean of its children's heights.
      const LonLat centre = default_grid().centre(cell);
      EXPECT_DOUBLE_EQ(got.origin.lon, centre.lon);
      EXPECT_DOUBLE_EQ(got.origin.lat, centre.lat);
      // The expected instances, in base cell order, then their order.
      size_t n = 0;
      for (CellId base : base_cells_under(cell)) {
        if (!stored.contains(base.id())) continue;
        const InstancesContent original = cell_instances(base, true);
        for (size_t i = 0; i < original.size(); ++i) {
          const Fate f = fate(original, i, depth);
          if (!f.kept) continue;
          ASSERT_LT(n, got.size()) << cell.ToText();
          ASSERT_EQ(got.provenance[n], original.provenance[i]) << "level " << level << " n " << n;
          EXPECT_EQ(got.prototypes[got.prototype[n]], original.prototypes[original.prototype[i]]);
          // The rotation turned with the frame: each axis the original turns, carried into the
          // parent frame through GeographicLib, is the axis the stored rotation turns.
          for (const std::array<double, 3>& axis : {std::array<double, 3>{1, 0, 0}, {0, 0, 1}}) {
            const auto was = rotate(&original.rotation[4 * i], axis);
            const auto zero = reframe(original.origin, got.origin, {0, 0, 0});
            const auto tip = reframe(original.origin, got.origin, {was[0], was[1], was[2]});
            const auto now = rotate(&got.rotation[4 * n], axis);
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(now[k], tip[k] - zero[k], 1e-6);
          }
          // Widened in x and y to the width the rule gives; the height bit for bit.
          const double widen = f.width / fate(original, i, 0).width;
          for (int k = 0; k < 2; ++k)
            EXPECT_NEAR(got.scale[3 * n + k], original.scale[3 * i + k] * widen,
                        1e-6 * original.scale[3 * i + k] * widen);
          EXPECT_EQ(std::bit_cast<uint32_t>(got.scale[3 * n + 2]),
                    std::bit_cast<uint32_t>(original.scale[3 * i + 2]));
          EXPECT_EQ(got.colour[n], original.colour[i]);
          const auto p = reframe(original.origin, got.origin,
                                 {original.position[3 * i], original.position[3 * i + 1],
                                  original.position[3 * i + 2]});
          // Within 1 mm, and the float rounding of each level's positions (half an ulp, at
          // most |p| 2^-24, per level up: tens of kilometres from a coarse level's origin).
          for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(got.position[3 * n + k], p[k], 1e-3 + depth * std::abs(p[k]) * 0x1p-24);
          cover += f.width * f.width;
          ++n;
        }
      }
      EXPECT_EQ(n, got.size()) << cell.ToText();
      total += got.size();
    }
    // The cover kept: within 20 % of the base's where at least 100 instances are left (their
    // number's noise: 10 % or less).
    if (total >= 100) {
      ++levels_covered;
      EXPECT_NEAR(cover / base_cover, 1, 0.2) << "level " << level << ", " << total;
      std::printf("level %d: %zu instances, cover %.3f of the base's\n", level, total,
                  cover / base_cover);
    }
    if (total == 0) {
      EXPECT_TRUE(store->content_cells("trees", level).empty());
    }
  }
  EXPECT_GE(levels_covered, 2);
  // `maquette info` counts the layer's level only.
  EXPECT_EQ(store->content_stats("trees").content.objects, base_cells().size() * kPerCell);
}

TEST(InstancesLod, SameBlobsForAnyOrderOfCellsAndThreads) {
  TempDir dir;
  auto a = content_store(dir.file("a.mqs"), "trees", LayerKind::Instances);
  write_cells(*a, base_cells(), true);
  update_content_overviews(*a, "trees");

  // Written in reverse order, half then the other half with an update between (only the stale
  // marks of the second half rebuild), on one thread.
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  auto b = content_store(dir.file("b.mqs"), "trees", LayerKind::Instances);
  std::vector<CellId> cells = base_cells();
  std::reverse(cells.begin(), cells.end());
  write_cells(*b, {cells.begin(), cells.begin() + 5}, true);
  update_content_overviews(*b, "trees");
  for (CellId c : std::vector<CellId>(cells.begin() + 5, cells.end())) write_cells(*b, {c}, true);
  update_content_overviews(*b, "trees");

  const auto blobs = overview_blobs(*a, "trees");
  EXPECT_EQ(blobs.size(), overview_blobs(*b, "trees").size());
  EXPECT_TRUE(blobs == overview_blobs(*b, "trees"));
  EXPECT_GE(blobs.size(), 6u);  // instances are left at least 3 levels up
}

TEST(InstancesLod, WithoutProvenanceThinnedByTheirBits) {
  TempDir dir;
  auto store = content_store(dir.file("a.mqs"), "trees", LayerKind::Instances);
  write_cells(*store, base_cells(), false);
  update_content_overviews(*store, "trees");
  // One level up: each child's instances whose stored bits the rule keeps.
  const double sample = sample_at(1);
  for (CellId cell : store->content_cells("trees", kBaseLevel - 1)) {
    const InstancesContent got = read(*store, cell);
    EXPECT_TRUE(got.provenance.empty());
    size_t n = 0;
    for (int k = 0; k < 4; ++k) {
      const InstancesContent child = cell_instances(cell.child(k), false);
      for (size_t i = 0; i < child.size(); ++i) {
        const double width = prototype_extent(child.prototypes[child.prototype[i]]) *
                             std::max(child.scale[3 * i], child.scale[3 * i + 1]);
        if (instance_draw(instance_key(child, i), 1) < std::pow(width / sample, 2)) {
          ASSERT_LT(n, got.size());
          EXPECT_EQ(got.colour[n], child.colour[i]);
          ++n;
        }
      }
    }
    EXPECT_EQ(n, got.size());
    EXPECT_GT(n, 0u);
  }
}

TEST(InstancesLod, BuiltForAnIncompleteLayerRefusedForOtherKindsAndCorruptChildren) {
  TempDir dir;
  auto store = content_store(dir.file("a.mqs"), "trees", LayerKind::Instances);
  // A run writing the layer builds its overviews before it marks the layer complete.
  store->mark_incomplete("trees", store->begin_run({{"steps", 1}}));
  write_cells(*store, base_cells(), true);
  update_content_overviews(*store, "trees");
  EXPECT_FALSE(store->content_cells("trees", kBaseLevel - 1).empty());

  LayerInfo raster;
  raster.name = "dem";
  raster.level = 5;
  store->create_layer(raster);
  expect_error([&] { update_content_overviews(*store, "dem"); }, {"'dem'", "not a content layer"});
  expect_error([&] { update_content_overviews(*store, "nope"); }, {"unknown layer 'nope'"});

  // A child whose payload is not instances: an error naming its cell, nothing written.
  const CellId bad = base_cells()[5];
  const auto before = overview_blobs(*store, "trees");
  ContentEnvelope e;
  e.kind = ContentKind::Instances;
  e.origin = base_origin(bad);
  {
    Store::Batch batch(*store);
    batch.put_content("trees", bad, wrap_content(e, "not zstd"));
    batch.commit();
  }
  expect_error([&] { update_content_overviews(*store, "trees"); }, {"cell " + bad.ToText()});
  EXPECT_TRUE(overview_blobs(*store, "trees") == before);
}

// A box model `east` x `north` x `up` metres (its base centred on its origin).
MeshContent box_model(float east, float north, float up) {
  MeshContent m;
  MeshObject o;
  for (float z : {0.f, up})
    for (float y : {-north / 2, north / 2})
      for (float x : {-east / 2, east / 2}) o.positions.insert(o.positions.end(), {x, y, z});
  o.indices = {0, 1, 3, 0, 3, 2, 4, 7, 5, 4, 6, 7, 0, 5, 1, 0, 4, 5,
               2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
  m.objects.push_back(o);
  return m;
}

// Placed buildings (structures.place: the prototype is a model layer's name): 40 m wide ones
// stay, bit for bit but re-origined, at every level whose sample is at most 40 m, and thin by
// the rule beyond; 2 m wide ones (the same model at scale 0.05) thin as trees do.
TEST(InstancesLod, PlacedModelsThinByTheirModelsSize) {
  TempDir dir;
  auto store = content_store(dir.file("a.mqs"), "trees", LayerKind::Instances);
  {
    Store::Batch batch(*store);
    // 40 m east, 10 m north, 60 m high: a width read on the wrong axis would be 60 m.
    batch.put_model("hotel", mesh_content_blob(box_model(40, 10, 60)));
    for (CellId cell : base_cells()) {
      std::mt19937_64 random(cell.id());
      std::uniform_real_distribution<float> xy(-150, 150), unit(-1, 1);
      InstancesContent c;
      c.origin = base_origin(cell);
      c.prototypes = {"hotel"};
      for (uint64_t i = 0; i < 40; ++i) {
        c.prototype.push_back(0);
        c.position.insert(c.position.end(), {xy(random), xy(random), 0});
        const float angle = unit(random) * 3.14159f;
        c.rotation.insert(c.rotation.end(), {0, 0, std::sin(angle / 2), std::cos(angle / 2)});
        const float s = i % 2 ? 1.f : 0.05f;
        c.scale.insert(c.scale.end(), {s, s, s});
        c.colour.push_back(0xffffffffu);
        c.provenance.push_back(
            {random(), int64_t(i), "structures.place", nlohmann::json::object()});
      }
      batch.put_content("trees", cell, wrap_instances(c));
    }
    batch.commit();
  }
  update_content_overviews(*store, "trees");

  // Every instance's fate by the rule (widths from the model's own vertices: 40 m x scale).
  int unchanged_levels = 0;
  bool thinned_big = false;
  for (int level = kBaseLevel - 1; level >= 0; --level) {
    const int depth = kBaseLevel - level;
    size_t big = 0, big_expected = 0;
    std::map<uint64_t, size_t> got_by_id;  // object id -> index in its cell's content
    std::map<uint64_t, InstancesContent> cells;
    for (CellId cell : store->content_cells("trees", level)) {
      cells[cell.id()] = read(*store, cell);
      const InstancesContent& got = cells[cell.id()];
      for (size_t n = 0; n < got.size(); ++n) got_by_id[got.provenance[n].object_id] = n;
    }
    for (CellId base : base_cells()) {
      const InstancesContent original =
          unwrap_instances(*store->get_content("trees", base), "trees " + base.ToText());
      CellId parent = base;
      for (int d = 0; d < depth; ++d) parent = parent.parent();
      for (size_t i = 0; i < original.size(); ++i) {
        const Fate f =
            fate_of(40.0 * original.scale[3 * i], original.provenance[i].object_id, depth, true);
        const auto at = got_by_id.find(original.provenance[i].object_id);
        ASSERT_EQ(f.kept, at != got_by_id.end()) << "level " << level << " instance " << i;
        if (!f.kept) continue;
        const InstancesContent& got = cells.at(parent.id());
        const size_t n = at->second;
        const double widen = f.width / (40.0 * original.scale[3 * i]);
        for (int k = 0; k < 2; ++k)
          EXPECT_NEAR(got.scale[3 * n + k], original.scale[3 * i + k] * widen,
                      1e-6 * original.scale[3 * i + k] * widen);
        if (original.scale[3 * i] == 1.f) {
          ++big;
          if (sample_at(depth) <= 40) {
            // Unchanged: scale bit for bit, position and rotation re-origined only.
            for (int k = 0; k < 3; ++k)
              EXPECT_EQ(std::bit_cast<uint32_t>(got.scale[3 * n + k]),
                        std::bit_cast<uint32_t>(original.scale[3 * i + k]));
            const auto p = reframe(original.origin, got.origin,
                                   {original.position[3 * i], original.position[3 * i + 1],
                                    original.position[3 * i + 2]});
            for (int k = 0; k < 3; ++k)
              EXPECT_NEAR(got.position[3 * n + k], p[k], 1e-3 + depth * std::abs(p[k]) * 0x1p-24);
            const std::array<double, 3> east{1, 0, 0};
            const auto was = rotate(&original.rotation[4 * i], east);
            const auto zero = reframe(original.origin, got.origin, {0, 0, 0});
            const auto tip = reframe(original.origin, got.origin, {was[0], was[1], was[2]});
            const auto now = rotate(&got.rotation[4 * n], east);
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(now[k], tip[k] - zero[k], 1e-6);
          }
        }
      }
      for (size_t i = 0; i < original.size(); ++i) big_expected += original.scale[3 * i] == 1.f;
    }
    std::printf("level %d: sample %.1f m, %zu of %zu models 40 m wide left\n", level,
                sample_at(depth), big, big_expected);
    if (sample_at(depth) <= 40) {
      EXPECT_EQ(big, big_expected) << "level " << level;  // every 40 m model is left
      ++unchanged_levels;
    } else if (big < big_expected) {
      thinned_big = true;
    }
  }
  EXPECT_EQ(unchanged_levels, 4);  // levels 13 to 10 (sample 35 m at level 10)
  EXPECT_TRUE(thinned_big);        // beyond, fewer are left

  // A prototype that is no model layer of the store, or a model whose payload is no GLB (the
  // store does not decode it): an error naming it, nothing written.
  const auto place_one = [&](const std::string& model) {
    Store::Batch batch(*store);
    InstancesContent c;
    c.origin = base_origin(base_cells()[0]);
    c.prototypes = {model};
    c.prototype = {0};
    c.position = {0, 0, 0};
    c.rotation = {0, 0, 0, 1};
    c.scale = {1, 1, 1};
    c.colour = {0xffffffffu};
    batch.put_content("trees", base_cells()[0], wrap_instances(c));
    batch.commit();
  };
  const auto before = overview_blobs(*store, "trees");
  place_one("casino");
  expect_error([&] { update_content_overviews(*store, "trees"); },
               {"layer 'trees'", "prototype 'casino'", "no model layer"});
  {
    Store::Batch batch(*store);
    batch.put_model("ruin", wrap_content(ContentEnvelope{}, "not a GLB"));
    batch.commit();
  }
  place_one("ruin");
  expect_error([&] { update_content_overviews(*store, "trees"); }, {"model 'ruin'", "GLB"});
  EXPECT_TRUE(overview_blobs(*store, "trees") == before);
}

}  // namespace
}  // namespace maquette::test
