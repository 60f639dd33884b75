// synthesis.inpaint run by the real program on Zion's Landsat imagery (../shared/data) with a
// bridge-like footprint crossing cells: the same tile bytes on one thread and two; every sample
// farther than the band from the footprint keeps the ingested bytes; the samples under it are
// filled (changed, none left nodata); a footprint that is no polygon is refused, naming it. And
// paper 002's Fig. 16 end to end: an orthophoto showing a bridge's deck, the deck removed under
// structures.bridge's mask, the filled photo draped by the 3D Tiles export.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <string>

#include "burn_deck.h"
#include "core/geo_distance.h"
#include "core/halo.h"
#include "core/polygon_set.h"
#include "core/tile.h"
#include "gltf/gltf_document.h"
#include "ring_feature.h"
#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"
#include "zion_ingest.h"

namespace maquette::synthesis {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kLandsat = kShared + "/zion/landsat_rgb_b4b3b2_8bit.tif";

// A 6.3 km deck, 0.0014 degrees of latitude (~110 m) wide, south-west to north-east across the
// region.
constexpr double kWest = -113.03, kEast = -112.98, kSouth = 37.255, kNorth = 37.295;
constexpr double kHalfWidth = 0.0007;  // degrees of latitude: ~78 m

PolygonRings deck_rings() {
  return {{{kWest, kSouth - kHalfWidth},
           {kEast, kNorth - kHalfWidth},
           {kEast, kNorth + kHalfWidth},
           {kWest, kSouth + kHalfWidth},
           {kWest, kSouth - kHalfWidth}}};
}

Geometry deck_geometry() {
  Geometry deck;
  deck.type = GeometryType::Polygon;
  const PolygonRings rings = deck_rings();
  GeoPath outline;
  for (const LonLat& q : rings[0]) outline.push_back({q.lon, q.lat});
  deck.polygons.push_back({{outline}});
  return deck;
}

std::string footprint(const std::string& type) {
  const PolygonRings rings = deck_rings();
  json ring = json::array();
  for (const LonLat& q : rings[0]) ring.push_back({q.lon, q.lat});
  return test::ring_feature(ring, type);
}

// The land cover: stripes 0.005 degrees (~440 m) wide running north-south, across the deck,
// of classes 11 (water) and 90 (woody wetlands) in turn.
constexpr double kStripesWest = -113.13;
int stripe_class(double lon) {
  return int(std::floor((lon - kStripesWest) / 0.005)) % 2 == 0 ? 11 : 90;
}

// The region's bbox the deck crosses.
json deck_region() { return {-113.03, 37.25, -112.98, 37.30}; }

struct InpaintRun {
  fs::path dir;
  std::string store;
  test::CliResult result;
};

// `inputs` and `outputs`: the inpaint step's (layers: "landsat", "landcover", the footprint
// "bridge"); `bbox` the region's.
InpaintRun run_inpaint(const std::string& name, int threads, const std::string& type = "Polygon",
                       const json& inputs = {{"image", "landsat"}, {"footprints", "bridge"}},
                       const json& outputs = {{"rgb", "filled"}},
                       const json& bbox = deck_region()) {
  InpaintRun run{
      fs::temp_directory_path() / ("maquette-inpaint-" + std::to_string(getpid()) + name), "", {}};
  fs::remove_all(run.dir);
  fs::create_directories(run.dir);
  run.store = (run.dir / "zion.mqt").string();
  std::ofstream(run.dir / "bridge.geojson") << footprint(type);
  test::write_raster((run.dir / "stripes.tif").string(),
                     test::lonlat_raster(kStripesWest, 37.40, 1100, 2e-4, "Byte"),
                     [](int, double lon, double) { return stripe_class(lon); });
  const json pipeline = {
      {"store", run.store},
      {"region", {{"bbox", bbox}}},
      {"level", 10},
      {"steps",
       {{{"op", "ingest"},
         {"outputs", {{"layer", "landsat"}}},
         {"params", {{"sources", {kLandsat}}, {"as", "imagery"}, {"level", 10}}}},
        {{"op", "ingest"},
         {"outputs", {{"layer", "landcover"}}},
         {"params",
          {{"sources", {(run.dir / "stripes.tif").string()}}, {"as", "landcover"}, {"level", 10}}}},
        {{"op", "ingest"},
         {"outputs", {{"layer", "bridge"}}},
         {"params", {{"sources", {(run.dir / "bridge.geojson").string()}}, {"as", "features"}}}},
        {{"op", "synthesis.inpaint"}, {"inputs", inputs}, {"outputs", outputs}}}}};
  std::ofstream(run.dir / "pipeline.json") << pipeline.dump(1);
  run.result = test::run_maquette("run " + (run.dir / "pipeline.json").string() + " --threads " +
                                  std::to_string(threads));
  return run;
}

TEST(InpaintOperator, FillsTheFootprintAcrossCellsKeepsTheRestSameBitsOnTwoThreads) {
  if (!fs::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const InpaintRun one = run_inpaint("-1", 1), two = run_inpaint("-2", 2);
  ASSERT_EQ(one.result.exit_code, 0) << one.result.err;
  ASSERT_EQ(two.result.exit_code, 0) << two.result.err;
  const auto a = Store::open(one.store, Store::Mode::ReadOnly);
  const auto b = Store::open(two.store, Store::Mode::ReadOnly);
  const std::vector<CellId> cells = a->tile_cells("filled");
  ASSERT_GE(cells.size(), 2u);
  const PolygonRings deck = deck_rings();
  const Geometry deck_outline = deck_geometry();
  size_t under = 0, changed_under = 0, nodata_under = 0, changed_far = 0, cells_with_deck = 0;
  for (const CellId cell : cells) {
    const RawTile filled = *a->get_tile("filled", cell);
    EXPECT_EQ(filled.bytes, b->get_tile("filled", cell)->bytes) << cell.ToText();
    const auto original = a->get_tile("landsat", cell);
    ASSERT_TRUE(original.has_value());
    const int n = filled.size, level = cell.level() + log2_tile_size(n);
    bool deck_here = false;
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const LonLat p = pixel_centre(
            default_grid(), {cell.face(), global_col(cell, n, c), global_row(cell, n, r)}, level);
        const size_t i = (size_t(r) * n + size_t(c)) * 3;
        bool differs = false, nodata = true;
        for (int k = 0; k < 3; ++k) {
          differs = differs || filled.bytes[i + k] != original->bytes[i + k];
          nodata = nodata && filled.bytes[i + k] == std::byte{0};
        }
        if (polygon_contains(deck, p)) {
          deck_here = true;
          ++under;
          changed_under += differs;
          nodata_under += nodata;
        } else if (differs) {
          // The band (3 samples of ~35 m) and rounding: nothing beyond 150 m of the deck.
          changed_far += distance_m(p, deck_outline) > 150;
        }
      }
    }
    cells_with_deck += deck_here;
  }
  EXPECT_GE(cells_with_deck, 2u);
  EXPECT_GT(under, 300u);
  EXPECT_GE(double(changed_under), 0.9 * double(under));
  EXPECT_EQ(nodata_under, 0u);
  EXPECT_EQ(changed_far, 0u);
  fs::remove_all(one.dir);
  fs::remove_all(two.dir);
}

// Land cover through the program (review C-R-S2): stripes of classes 11 and 90 across the deck,
// filled under it as classes into a uint16 layer: every sample under the deck one of the two (an
// average of their codes would be neither), >= 90 % of them the class of the stripe they lie in
// (the stripes, wider than the deck, continued across it), nothing changed beyond 150 m.
TEST(InpaintOperator, LandCoverStripesAreContinuedAcrossTheFootprintAsClasses) {
  if (!fs::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const InpaintRun run =
      run_inpaint("-classes", 2, "Polygon", {{"landcover", "landcover"}, {"footprints", "bridge"}},
                  {{"classes", "filled_classes"}});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
  const auto s = Store::open(run.store, Store::Mode::ReadOnly);
  const LayerInfo info = s->require_layer("filled_classes");
  EXPECT_EQ(info.dtype, DType::U16);
  EXPECT_EQ(info.semantics, Semantics::Categorical);
  const PolygonRings rings = deck_rings();
  const Geometry deck = deck_geometry();
  size_t under = 0, other_class = 0, its_stripe = 0, changed_far = 0;
  for (const CellId cell : s->tile_cells("filled_classes")) {
    const Tile<uint16_t> filled = to_tile<uint16_t>(*s->get_tile("filled_classes", cell));
    const Tile<uint16_t> original = to_tile<uint16_t>(*s->get_tile("landcover", cell));
    const int n = filled.size(), level = cell.level() + log2_tile_size(n);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const LonLat p = pixel_centre(
            default_grid(), {cell.face(), global_col(cell, n, c), global_row(cell, n, r)}, level);
        const uint16_t got = filled.at(c, r);
        if (polygon_contains(rings, p)) {
          ++under;
          other_class += got != 11 && got != 90;
          its_stripe += got == stripe_class(p.lon);
        } else if (distance_m(p, deck) > 150) {
          changed_far += got != original.at(c, r);
        }
      }
    }
  }
  std::cout << "land cover under the deck: " << its_stripe << " of " << under
            << " samples the class of their stripe\n";
  EXPECT_GT(under, 300u);
  EXPECT_EQ(other_class, 0u);
  EXPECT_GE(double(its_stripe), 0.9 * double(under));
  EXPECT_EQ(changed_far, 0u);
  fs::remove_all(run.dir);
}

// Paper 002's Fig. 16 in the pipeline: an orthophoto showing a bridge's deck (the Landsat image
// with the deck painted on it in magenta, a colour the scene lacks), the bridge's edge strokes ->
// structures.bridge (its deck and the footprint mask) -> synthesis.inpaint of the photo under the
// mask -> `export tiles3d` of the terrain draped with the filled photo and the deck's mesh. Run
// once for the suite's tests.
class BridgeRemoved : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!fs::exists(kLandsat)) return;
    dir_ = fs::temp_directory_path() / ("maquette-inpaint-bridge-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    store_ = (dir_ / "zion.mqt").string();
    const std::string photo = (dir_ / "photo_with_deck.tif").string();
    paint_deck(photo);
    std::ofstream(dir_ / "strokes.geojson")
        << json{{"type", "FeatureCollection"},
                {"features",
                 {{{"type", "Feature"},
                   {"properties", {{"tool", "bridge"}}},
                   {"geometry", {{"type", "MultiLineString"}, {"coordinates", kEdges}}}}}}};
    json steps = zion_ingest_steps();
    steps.push_back({{"op", "ingest"},
                     {"outputs", {{"layer", "landsat"}}},
                     {"params", {{"sources", {photo}}, {"as", "imagery"}, {"level", 10}}}});
    steps.push_back(
        {{"op", "ingest"},
         {"outputs", {{"layer", "strokes"}}},
         {"params", {{"sources", {(dir_ / "strokes.geojson").string()}}, {"as", "features"}}}});
    steps.push_back({{"op", "structures.bridge"},
                     {"inputs", {{"dem", "dem"}, {"strokes", "strokes"}}},
                     {"outputs", {{"mesh", "bridges"}, {"mask", "bridge_mask"}}}});
    steps.push_back({{"op", "synthesis.inpaint"},
                     {"inputs", {{"image", "landsat"}, {"mask", "bridge_mask"}}},
                     {"outputs", {{"rgb", "filled"}}}});
    const json pipeline = {
        {"store", store_}, {"region", {{"bbox", deck_region()}}}, {"level", 10}, {"steps", steps}};
    std::ofstream(dir_ / "pipeline.json") << pipeline.dump(1);
    run_ = test::run_maquette("run " + (dir_ / "pipeline.json").string() + " --quiet --threads 2");
  }
  static void TearDownTestSuite() {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  void SetUp() override {
    if (!fs::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
    ASSERT_EQ(run_.exit_code, 0) << run_.err;
  }

  // Edges 2 km long, ~130 m apart.
  inline static const json kEdges = {{{-113.02, 37.27}, {-113.0, 37.28}},
                                     {{-113.02, 37.2712}, {-113.0, 37.2812}}};

  // The Landsat image with the deck's outline (straight in degrees, as structures.bridge's)
  // rasterized onto it in magenta by GDAL, in the image's own grid.
  static void paint_deck(const std::string& path) {
    GDALAllRegister();
    const GDALDatasetUniquePtr source(GDALDataset::Open(kLandsat.c_str(), GDAL_OF_RASTER));
    const GDALDatasetUniquePtr photo(GetGDALDriverManager()->GetDriverByName("GTiff")->CreateCopy(
        path.c_str(), source.get(), FALSE, nullptr, nullptr, nullptr));
    ASSERT_TRUE(maquette::test::burn_deck(*photo, kEdges[0], kEdges[1], {255, 0, 255}));
  }

  // The deck's colour, as the ingest's resampling leaves it (measured on the scene outside the
  // deck: no sample comes near).
  static bool deck_coloured(int r, int g, int b) { return r >= 160 && b >= 160 && g <= 100; }

  // The deck's samples (the mask's) by global face pixel.
  static std::set<std::array<int64_t, 3>> deck_samples(const Store& s) {
    std::set<std::array<int64_t, 3>> deck;
    for (const CellId cell : s.tile_cells("bridge_mask")) {
      const Tile<float> mask = to_tile<float>(*s.get_tile("bridge_mask", cell));
      for (int row = 0; row < mask.size(); ++row)
        for (int col = 0; col < mask.size(); ++col)
          if (mask.at(col, row) == 1)
            deck.insert({cell.face(), global_col(cell, mask.size(), col),
                         global_row(cell, mask.size(), row)});
    }
    return deck;
  }

  inline static fs::path dir_;
  inline static std::string store_;
  inline static test::CliResult run_;
};

// Every sample under the deck filled, none deck-coloured left in the filled photo (the photo had
// them under the deck), none changed beyond the band.
TEST_F(BridgeRemoved, ThePhotoUnderTheDeckShowsGround) {
  const auto s = Store::open(store_, Store::Mode::ReadOnly);
  const std::set<std::array<int64_t, 3>> deck = deck_samples(*s);
  size_t under = 0, changed_under = 0, deck_coloured_under = 0, deck_coloured_filled = 0,
         deck_coloured_far = 0, changed_beyond_band = 0;
  for (const CellId cell : s->tile_cells("filled")) {
    const RawTile filled = *s->get_tile("filled", cell);
    const RawTile original = *s->get_tile("landsat", cell);
    const int n = filled.size;
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const size_t i = (size_t(row) * n + size_t(col)) * 3;
        const auto at = [&](const RawTile& t, int k) { return int(t.bytes[i + size_t(k)]); };
        const bool differs = filled.bytes[i] != original.bytes[i] ||
                             filled.bytes[i + 1] != original.bytes[i + 1] ||
                             filled.bytes[i + 2] != original.bytes[i + 2];
        const bool deck_before = deck_coloured(at(original, 0), at(original, 1), at(original, 2));
        deck_coloured_filled += deck_coloured(at(filled, 0), at(filled, 1), at(filled, 2));
        const int64_t gc = global_col(cell, n, col), gr = global_row(cell, n, row);
        if (deck.count({cell.face(), gc, gr}) != 0) {
          ++under;
          changed_under += differs;
          deck_coloured_under += deck_before;
          continue;
        }
        bool near = false;
        for (int dy = -3; dy <= 3 && !near; ++dy)
          for (int dx = -3; dx <= 3 && !near; ++dx)
            near = deck.count({cell.face(), gc + dx, gr + dy}) != 0;
        changed_beyond_band += differs && !near;
        deck_coloured_far += deck_before && !near;
      }
    }
  }
  EXPECT_GT(under, 100u);
  EXPECT_GE(double(deck_coloured_under), 0.9 * double(under));
  EXPECT_EQ(deck_coloured_far, 0u);
  EXPECT_GE(double(changed_under), 0.9 * double(under));
  EXPECT_EQ(deck_coloured_filled, 0u);
  EXPECT_EQ(changed_beyond_band, 0u);
}

// `export tiles3d` drapes the filled photo: each terrain tile's texture (decoded from its GLB) is
// the filled layer's tile within JPEG's error under the deck, far from the photo's deck, with no
// deck-coloured texel anywhere; the deck's mesh is a content of the tile of its cell.
TEST_F(BridgeRemoved, TheTilesExportDrapesTheFilledPhoto) {
  const auto s = Store::open(store_, Store::Mode::ReadOnly);
  const int level = s->require_layer("filled").level;
  const fs::path out = dir_ / "tiles";
  const test::CliResult r = test::run_maquette(
      "-q export tiles3d " + store_ + " " + out.string() + " --dem dem --texture filled" +
      " --no-stretch --content bridges --levels " + std::to_string(level) + ".." +
      std::to_string(level));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::set<std::array<int64_t, 3>> deck = deck_samples(*s);
  size_t under = 0, deck_coloured_texels = 0, tiles = 0;
  double to_filled = 0, to_photo = 0;
  for (const CellId cell : s->tile_cells("filled")) {
    const fs::path glb = out / "tiles" / std::to_string(level) / (cell.ToText() + ".glb");
    ASSERT_TRUE(fs::exists(glb)) << glb;
    std::ifstream in(glb, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const std::vector<Material> materials = read_materials(parse_gltf(bytes, glb.string(), {}));
    ASSERT_EQ(materials.size(), 1u);
    const cv::Mat texture = cv::imdecode(cv::Mat(1, int(materials[0].image.size()), CV_8U,
                                                 const_cast<char*>(materials[0].image.data())),
                                         cv::IMREAD_COLOR);
    const RawTile filled = *s->get_tile("filled", cell);
    const RawTile photo = *s->get_tile("landsat", cell);
    const int n = filled.size;
    ASSERT_EQ(texture.rows, n);
    ASSERT_EQ(texture.cols, n);
    ++tiles;
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const cv::Vec3b bgr = texture.at<cv::Vec3b>(row, col);
        deck_coloured_texels += deck_coloured(bgr[2], bgr[1], bgr[0]);
        if (deck.count({cell.face(), global_col(cell, n, col), global_row(cell, n, row)}) == 0)
          continue;
        ++under;
        const size_t i = (size_t(row) * n + size_t(col)) * 3;
        for (int k = 0; k < 3; ++k) {
          to_filled += std::abs(int(bgr[2 - k]) - int(filled.bytes[i + size_t(k)]));
          to_photo += std::abs(int(bgr[2 - k]) - int(photo.bytes[i + size_t(k)]));
        }
      }
    }
  }
  EXPECT_GE(tiles, 1u);
  ASSERT_GT(under, 100u);
  EXPECT_EQ(deck_coloured_texels, 0u);
  // Mean absolute difference per channel under the deck, measured: 3.6 to the filled layer (JPEG
  // at quality 90), 105 to the photo; the photo exported instead: 75 and 35.
  EXPECT_LT(to_filled / double(3 * under), 6.0);
  EXPECT_GT(to_photo / double(3 * under), 50.0);
  // The deck's mesh is in the export, as a content of its cell's tile.
  size_t deck_contents = 0;
  for (const CellId cell : s->content_cells("bridges"))
    deck_contents +=
        fs::exists(out / "tiles" / std::to_string(level) / (cell.ToText() + ".bridges.glb"));
  EXPECT_EQ(deck_contents, 1u);
}

// A layer of the wrong kind for a port (imagery as land cover or as heights, land cover as
// imagery) is refused when the pipeline is planned, naming the port, the layer and what the port
// takes, before the store is made (each inpainted as classes, heights would be a class per value).
TEST(InpaintOperator, LayersOfTheWrongKindAreRefusedBeforeAnythingRuns) {
  if (!fs::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const auto refused = [](const std::string& name, const json& inputs, const json& outputs,
                          const std::string& message) {
    const InpaintRun run = run_inpaint(name, 1, "Polygon", inputs, outputs);
    EXPECT_NE(run.result.exit_code, 0) << name;
    EXPECT_NE(run.result.err.find(message), std::string::npos) << run.result.err;
    EXPECT_FALSE(fs::exists(run.store)) << name;
    fs::remove_all(run.dir);
  };
  refused("-cover", {{"landcover", "landsat"}, {"footprints", "bridge"}}, {{"classes", "c"}},
          "(synthesis.inpaint): inputs.landcover: layer 'landsat' is continuous, but the port "
          "takes a categorical layer (land-cover classes (1 channel), for output classes)");
  refused("-dem", {{"dem", "landsat"}, {"footprints", "bridge"}}, {{"heights", "h"}},
          "(synthesis.inpaint): inputs.dem: layer 'landsat' has 3 channels, but the port takes 1");
  refused("-image", {{"image", "landcover"}, {"footprints", "bridge"}}, {{"rgb", "filled"}},
          "(synthesis.inpaint): inputs.image: layer 'landcover' has 1 channel, but the port takes "
          "3");
}

// A step without its holes is refused when the pipeline is read, before the store is made.
TEST(InpaintOperator, AStepWithoutItsHolesIsRefusedBeforeAnythingRuns) {
  if (!fs::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const InpaintRun run = run_inpaint("-holeless", 1, "Polygon", {{"image", "landsat"}});
  EXPECT_NE(run.result.exit_code, 0);
  EXPECT_NE(run.result.err.find("step 4 (synthesis.inpaint): inputs: give the holes as "
                                "'footprints' (polygons) or 'mask' (a raster)"),
            std::string::npos)
      << run.result.err;
  EXPECT_FALSE(fs::exists(run.store));
  fs::remove_all(run.dir);
}

TEST(InpaintOperator, AFootprintThatIsNoPolygonIsNamed) {
  if (!fs::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const InpaintRun run = run_inpaint("-line", 1, "LineString");
  EXPECT_NE(run.result.exit_code, 0);
  EXPECT_NE(run.result.err.find("inputs.footprints: feature 1 is a LineString, not a Polygon or "
                                "MultiPolygon"),
            std::string::npos)
      << run.result.err;
  fs::remove_all(run.dir);
}

// A footprint wholly beside the region leaves nothing to fill: said (it passed silently as a
// fill), the image written as it was.
TEST(InpaintOperator, AFootprintBesideTheRegionIsSaidAndChangesNothing) {
  if (!fs::exists(kLandsat)) GTEST_SKIP() << "../shared/data is absent";
  const InpaintRun run =
      run_inpaint("-beside", 1, "Polygon", {{"image", "landsat"}, {"footprints", "bridge"}},
                  {{"rgb", "filled"}}, {-113.20, 37.35, -113.17, 37.38});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
  EXPECT_NE(run.result.err.find("synthesis.inpaint: nothing to fill: no sample of the region lies "
                                "in inputs.footprints' polygons (0 found near it); the image is "
                                "written unchanged"),
            std::string::npos)
      << run.result.err;
  const auto s = Store::open(run.store, Store::Mode::ReadOnly);
  const std::vector<CellId> cells = s->tile_cells("filled");
  ASSERT_FALSE(cells.empty());
  for (const CellId cell : cells)
    EXPECT_EQ(s->get_tile("filled", cell)->bytes, s->get_tile("landsat", cell)->bytes)
        << cell.ToText();
  fs::remove_all(run.dir);
}

}  // namespace
}  // namespace maquette::synthesis
