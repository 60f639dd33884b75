// Colour classification (paper 5.2.1): grey rule, hue boxes that wrap, polygons on the colour
// wheel, the order boxes -> polygons -> centres, the snow rule, the land-cover exclusion,
// exclusion by the polygons of a features layer (and its index, core/polygon_set.h), automatic
// k-means clusters in hue-saturation and CIELAB; and CIEDE2000 against Sharma et al.'s data.
#include <gtest/gtest.h>
#include <ogr_geometry.h>
#include <unistd.h>

#include <filesystem>

#include "../colour.h"
#include "../hs_classes.h"
#include "../hs_plot.h"
#include "../illumination.h"
#include "core/polygon_set.h"
#include "texture_module.h"

namespace maquette::texture {
namespace {

using namespace texture_test;
namespace fs = std::filesystem;

const CellId kCell = CellId::FromFaceColRow(2, 10, 520, 500);

// A 4 x 4 image: rows of red, dark green, white, grey.
Tile<float> image() {
  const float colours[4][3] = {{200, 30, 20}, {30, 90, 40}, {245, 245, 250}, {120, 120, 118}};
  Tile<float> t(4, 3);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 3; ++k) t.at(c, r, k) = colours[r][k];
  return t;
}

Tile<float> classify(CellData d, const json& params) {
  return run_cell("texture.classify", kCell, 4, std::move(d), params).outputs.at("classes");
}

// The classes of up to 16 colours (a 4 x 4 image filled row by row; -1: no class).
std::vector<int> classes_of(const std::vector<std::array<float, 3>>& colours, const json& params) {
  Tile<float> rgb(4, 3);
  for (size_t i = 0; i < 16; ++i)
    for (int k = 0; k < 3; ++k)
      rgb.at(int(i % 4), int(i / 4), k) = colours[std::min(i, colours.size() - 1)][size_t(k)];
  CellData d;
  d.inputs.emplace("rgb", rgb);
  const Tile<float> out = classify(d, params);
  std::vector<int> k;
  for (size_t i = 0; i < colours.size(); ++i) {
    const float v = out.at(int(i % 4), int(i / 4));
    k.push_back(std::isnan(v) ? -1 : int(v));
  }
  return k;
}

std::string error_of(const json& params) {
  try {
    classes_of({{200, 30, 20}}, params);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

const json kBoxes = json::parse(R"({"boxes": [
  {"id": 1, "hue": [340, 20], "saturation": [0.5, 1]},
  {"id": 2, "hue": [90, 180]},
  {"id": 3, "hue": [290, 310], "value": [0.8, 1]},
  {"id": 4, "hue": [290, 310]}]})");

TEST(Classify, BoxesWrapAndGreyGetsItsHue) {
  CellData d;
  d.inputs.emplace("rgb", image());
  const Tile<float> k = classify(d, kBoxes);
  EXPECT_EQ(k.at(0, 0), 1);  // red: hue ~3 degrees, in the wrapping box [340, 20]
  EXPECT_EQ(k.at(0, 1), 2);
  EXPECT_EQ(k.at(0, 2), 3);  // white: grey, hue 300, bright
  EXPECT_EQ(k.at(0, 3), 4);  // grey: hue 300, dark
  json no_grey = kBoxes;
  no_grey["grey_threshold"] = 0;
  EXPECT_TRUE(std::isnan(classify(d, no_grey).at(0, 2)));  // hue of white is blue: no box
}

// Hand-computed on the colour wheel (s cos h, s sin h). The triangle's vertices are at
// saturation 0.8 and hues 0, 120, 240: (0.8, 0), (-0.4, +-0.69); its edges are 0.4 from the
// grey point, along hues 60, 180 and 300.
TEST(Classify, PolygonTriangleAroundTheGreyPoint) {
  const json p = json::parse(R"({"polygons": [{"id": 7, "name": "pale",
    "points": [[0, 0.8], [120, 0.8], [240, 0.8]]}]})");
  EXPECT_EQ(classes_of({{120, 120, 118},   // grey: hue 300, s 0.017
                        {200, 100, 100},   // hue 0, s 0.5: (0.5, 0)
                        {255, 0, 0},       // (1, 0): beyond the vertex
                        {255, 255, 179},   // hue 60, s 76/255 = 0.298 < 0.4
                        {255, 255, 128},   // hue 60, s 127/255 = 0.498 > 0.4
                        {170, 200, 200},   // hue 180, s 0.15
                        {100, 200, 200}},  // hue 180, s 0.5
                       p),
            (std::vector<int>{7, 7, -1, 7, -1, 7, -1}));
}

// Vertices at hues 350 and 10, saturations 0.3 and 0.9: the edges are straight in the plane,
// chords x = 0.3 cos 10 = 0.2954 and x = 0.9 cos 10 = 0.8863 and the rays at +-10 degrees, not
// the arcs of a box [350, 10] x [0.3, 0.9].
TEST(Classify, PolygonAcrossHueZero) {
  const json p = json::parse(R"({"polygons": [{"id": 2,
    "points": [[350, 0.3], [10, 0.3], [10, 0.9], [350, 0.9]]}]})");
  EXPECT_EQ(classes_of({{200, 100, 90},   // hue 5.45, s 0.55: (0.5475, 0.0523)
                        {200, 90, 100},   // hue 354.55: (0.5475, -0.0523)
                        {200, 118, 90},   // hue 15.27
                        {200, 140, 140},  // hue 0, s 0.3: x 0.3 > 0.2954
                        {200, 150, 150},  // hue 0, s 0.25
                        {200, 30, 20}},   // hue 3.33, s 0.9: x 0.8985 > 0.8863
                       p),
            (std::vector<int>{2, 2, -1, 2, -1, -1}));
}

// Polygons are drawn on texture.cluster's plot: its pixel positions, read back with the
// README's formula, are the polygon plane (s cos h, s sin h) scaled by 230.4 with y downwards.
TEST(Classify, PolygonPlaneIsThePlotsPlane) {
  for (const auto& [hue, saturation] :
       {std::pair{0.0, 1.0}, {90.0, 0.5}, {200.0, 0.25}, {355.0, 0.8}, {123.0, 0.0}}) {
    const auto xy = plot_position(hue, saturation);
    const auto w = wheel(hue, saturation);
    EXPECT_NEAR((xy[0] - 256) / 230.4, w[0], 1e-12);
    EXPECT_NEAR((256 - xy[1]) / 230.4, w[1], 1e-12);
    EXPECT_NEAR(std::hypot(xy[0] - 256, 256 - xy[1]) / 230.4, saturation, 1e-12);
    if (saturation > 0) {
      const double read = std::atan2(256 - xy[1], xy[0] - 256) * 180 / M_PI;
      EXPECT_NEAR(read < 0 ? read + 360 : read, hue, 1e-9);
    }
  }
}

// Closed polygons: points on an edge or a vertex are inside. Even-odd rule: the part of a
// self-intersecting polygon covered twice is outside.
TEST(Classify, PolygonEdgesAndSelfIntersection) {
  // The edge from hue 180 to hue 0 is the diameter through the grey point.
  const json half = json::parse(R"({"grey_threshold": 0, "polygons": [{"id": 1,
    "points": [[0, 0.5], [90, 0.5], [180, 0.5]]}]})");
  EXPECT_EQ(classes_of({{128, 128, 128},  // s 0: the grey point, on the edge
                        {138, 128, 128},  // hue 0, s 0.07: on the edge
                        {128, 128, 138},  // hue 240: below it
                        {200, 100, 100},  // (0.5, 0): a vertex
                        {150, 200, 100},  // hue 90, s 0.5: (0, 0.5), a vertex
                        {255, 0, 0}},     // (1, 0): on the edge's line, beyond the vertex
                       half),
            (std::vector<int>{1, 1, -1, 1, 1, -1}));
  // A pentagram of radius 0.8: its inner pentagon (0.8 cos 72 = 0.247 from the centre to each
  // side) is covered twice, its tips once.
  const json star = json::parse(R"({"grey_threshold": 0, "polygons": [{"id": 1,
    "points": [[90, 0.8], [234, 0.8], [18, 0.8], [162, 0.8], [306, 0.8]]}]})");
  EXPECT_EQ(classes_of({{128, 128, 128},   // the centre
                        {128, 128, 138},   // hue 240, s 0.07: inside the inner pentagon
                        {150, 200, 100}},  // hue 90, s 0.5: in the tip at hue 90
                       star),
            (std::vector<int>{-1, -1, 1}));
}

// Boxes first, then polygons in order, then the nearest centre.
TEST(Classify, BoxesThenPolygonsThenCentres) {
  const json p = json::parse(R"({
    "boxes": [{"id": 1, "hue": [340, 20], "saturation": [0.5, 1]}],
    "polygons": [{"id": 2, "points": [[350, 0.3], [10, 0.3], [10, 0.9], [350, 0.9]]},
                 {"id": 3, "points": [[0, 0.2], [0, 0.6], [90, 0.6]]}],
    "centres": [{"id": 4, "hue": 120, "saturation": 0.5}, {"id": 5, "hue": 240, "saturation": 0.5}]})");
  EXPECT_EQ(classes_of({{200, 100, 90},    // hue 5.45, s 0.55: the box and polygon 2
                        {200, 140, 140},   // (0.3, 0): polygon 2, and on polygon 3's edge
                        {200, 180, 120},   // hue 45, s 0.4: (0.283, 0.283), polygon 3 only
                        {30, 90, 40},      // hue 130, s 0.67: 0.20 from centre 4, 0.96 from 5
                        {128, 128, 138}},  // grey, hue 300: (0.036, -0.063), 0.57 and 0.47
                       p),
            (std::vector<int>{1, 2, 3, 4, 5}));
}

TEST(Classify, PolygonErrorsNameFieldAndValue) {
  const auto polygon = [](const json& points) {
    json p = {{"polygons", {{{"id", 1}, {"points", {{0, 0.5}, {120, 0.5}, {240, 0.5}}}}}}};
    p["polygons"].push_back({{"id", 2}, {"points", points}});
    return p;
  };
  EXPECT_EQ(error_of(polygon({{0, 0.5}, {120, 0.5}})),
            "texture.classify: params.polygons[1].points: expected at least 3 [hue, saturation] "
            "points, got 2");
  EXPECT_EQ(error_of(polygon({{0, 0.5}, {120, 1.5}, {240, 0.5}})),
            "texture.classify: params.polygons[1].points[1]: saturation 1.5 is outside [0, 1]");
  EXPECT_EQ(error_of(polygon({{0, 0.5}, {120, -0.1}, {240, 0.5}})),
            "texture.classify: params.polygons[1].points[1]: saturation -0.1 is outside [0, 1]");
  EXPECT_EQ(error_of(polygon({{0, 0.5}, {120, 0.5}, {400, 0.5}})),
            "texture.classify: params.polygons[1].points[2]: hue 400 is outside [0, 360]");
  EXPECT_EQ(error_of(polygon({{0, 0.5}, {120, 0.5, 1}, {240, 0.5}})),
            "texture.classify: params.polygons[1].points[1]: expected [hue, saturation], got "
            "[120,0.5,1]");
  EXPECT_EQ(error_of(polygon({{0, 0.5}, {120, 0.5}, {"red", 0.5}})),
            "texture.classify: params.polygons[1].points[2][0]: expected a number, got \"red\"");
  EXPECT_EQ(error_of(polygon({{0, 0.2}, {0, 0.5}, {180, 0.3}})),
            "texture.classify: params.polygons[1].points: the points are on one line, got "
            "[[0,0.2],[0,0.5],[180,0.3]]");
  EXPECT_EQ(error_of({{"polygons", {{{"id", 1}}}}}),
            "texture.classify: params.polygons[0]: missing required field 'points'");
}

TEST(Classify, SnowBelowMinimalAltitudeAndExcludedLandCover) {
  CellData d;
  d.inputs.emplace("rgb", image());
  Tile<float> dem(4, 1, 0, 3000), lc(4, 1, 0, 42);
  for (int r = 0; r < 4; ++r) dem.at(0, r) = 1000, lc.at(3, r) = 82;
  d.inputs.emplace("dem", dem);
  d.inputs.emplace("landcover", lc);
  json p = kBoxes;
  p["snow_class"] = 3;
  p["snow_min_altitude_m"] = 2000;
  p["exclude_landcover"] = {82, 21};
  const Tile<float> k = classify(d, p);
  EXPECT_TRUE(std::isnan(k.at(0, 2)));  // white at 1000 m: cloud
  EXPECT_EQ(k.at(1, 2), 3);             // white at 3000 m: snow
  EXPECT_EQ(k.at(1, 0), 1);
  for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isnan(k.at(3, r)));  // cultivated
}

// Illumination correction (cosine correction at the image's sun, altitude 30: sin = 0.5): a
// pixel's colour times 0.5 / max(cos i, 0.2), cos i = (hillshade - 1) / 254, capped so that no
// channel passes 255 (hue and saturation kept); unknown illumination leaves the colour as is.
TEST(Classify, IlluminationCorrection) {
  const std::array<float, 3> dark = {50, 60, 80}, blue = {100, 150, 200};
  const float cos_half = 1 + 254 * 0.5f, cos_quarter = 1 + 254 * 0.25f, cos_tiny = 1 + 254 * 0.05f;
  const struct {
    std::array<float, 3> rgb;
    float hillshade;
    int expected;
  } cases[] = {
      {dark, cos_half, 0},     // lit like flat ground: value 80 / 255 = 0.31 stays dark
      {dark, cos_quarter, 1},  // twice as bright once corrected: 0.63
      {dark, NAN, 0},          // unknown illumination: uncorrected
      {blue, cos_half, 1},     // hue 210, value 0.78
      {blue, cos_tiny, 2},     // floor 0.2: x 2.5, capped at x 1.275: value 1, hue still 210
      {{250, 250, 250}, cos_quarter, 1},  // grey: x 1.02, value 1
  };
  Tile<float> rgb(4, 3), shade(4, 1, 0, 1 + 254 * 0.5f);
  for (size_t i = 0; i < std::size(cases); ++i) {
    for (int k = 0; k < 3; ++k) rgb.at(int(i % 4), int(i / 4), k) = cases[i].rgb[size_t(k)];
    shade.at(int(i % 4), int(i / 4)) = cases[i].hillshade;
  }
  CellData d;
  d.inputs.emplace("rgb", rgb);
  d.inputs.emplace("hillshade", shade);
  json p = json::parse(R"({"boxes": [{"id": 2, "hue": [205, 215], "value": [0.999, 1]},
    {"id": 0, "value": [0, 0.4]}, {"id": 1, "value": [0.4, 1]}], "sun_altitude": 30})");
  const Tile<float> k = classify(d, p);
  for (size_t i = 0; i < std::size(cases); ++i)
    EXPECT_EQ(k.at(int(i % 4), int(i / 4)), cases[i].expected) << "case " << i;
  p["sun_altitude"] = 0;  // no correction
  EXPECT_EQ(classify(d, p).at(1, 0), 0);
  EXPECT_EQ(classify(d, p).at(0, 1), 1);
  p["sun_altitude"] = 30;
  d.inputs.erase("hillshade");
  try {
    classify(d, p);
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "texture.classify: params.sun_altitude needs inputs.hillshade");
  }
}

// The C-correction (c_correction c > 0) by hand, altitude 30 (sin = 0.5), c = 0.5: colours
// times (0.5 + 0.5) / (max(cos i, 0.2) + 0.5): x 4/3 at cos i = 0.25 (the cosine correction: x
// 2), x 1/0.7 at the floor, x 1 on flat ground, the cap at 255 as before; c = 0 is the cosine
// correction.
TEST(Classify, CCorrectionByHand) {
  Tile<float> shade(3, 1, 0, 1 + 254 * 0.5f);
  shade.at(1, 0) = 1 + 254 * 0.25f;
  shade.at(2, 0) = 1 + 254 * 0.05f;
  CellData d;
  d.inputs.emplace("hillshade", shade);
  json p = {{"sun_altitude", 30}, {"min_incidence_cos", 0.2}, {"c_correction", 0.5}};
  const std::optional<Illumination> light = illumination_of(p, d, "test");
  ASSERT_TRUE(light);
  const std::array<float, 3> rgb = {30, 60, 90};
  const auto expect_scaled = [&](int c, double f, const std::array<float, 3>& v) {
    const std::array<float, 3> out = light->corrected(v, c, 0);
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(out[k], v[k] * f, 1e-3) << "column " << c;
  };
  expect_scaled(0, 1, rgb);
  expect_scaled(1, 1 / 0.75, rgb);
  expect_scaled(2, 1 / 0.7, rgb);
  expect_scaled(2, 255.0 / 200, {100, 150, 200});  // x 1.43 capped at x 1.275
  p["c_correction"] = 0;
  const std::optional<Illumination> cosine = illumination_of(p, d, "test");
  EXPECT_NEAR(cosine->corrected(rgb, 1, 0)[2], 90 * 2, 1e-3);
}

// Majority filter (minimum mapping unit): a red 4 x 4 tile with a ring of 2 beyond it, a green
// pixel inside, a green pair on the border, a grey (unclassified) pixel.
TEST(Classify, MajorityFilter) {
  Tile<float> rgb(4, 3, 2);
  for (int r = -2; r < 6; ++r)
    for (int c = -2; c < 6; ++c) rgb.at(c, r, 0) = 200, rgb.at(c, r, 1) = 30, rgb.at(c, r, 2) = 20;
  const auto paint = [&](int c, int r, std::array<float, 3> v) {
    for (int k = 0; k < 3; ++k) rgb.at(c, r, k) = v[size_t(k)];
  };
  paint(1, 1, {30, 90, 40});
  paint(3, 3, {30, 90, 40});
  paint(4, 3, {30, 90, 40});  // in the ring: counts, but is not output
  paint(2, 0, {120, 120, 118});
  const json boxes =
      json::parse(R"({"boxes": [{"id": 1, "hue": [340, 20]}, {"id": 2, "hue": [90, 180]}]})");
  CellData d;
  d.inputs.emplace("rgb", rgb);
  const Tile<float> none = classify(d, boxes);
  EXPECT_EQ(none.at(1, 1), 2);
  json p = boxes;
  p["majority_radius"] = 1;
  const Tile<float> k = classify(d, p);
  EXPECT_EQ(k.at(1, 1), 1);             // 8 red neighbours of 8 classified
  EXPECT_EQ(k.at(3, 3), 1);             // 2 green of 9 (one from the ring)
  EXPECT_TRUE(std::isnan(k.at(2, 0)));  // unclassified stays unclassified
  EXPECT_EQ(k.at(0, 0), 1);
  // Ties keep the pixel's own class: around (1, 1), 4 red, 4 green (its own) and a grey.
  CellData t;
  paint(1, 1, {30, 90, 40});
  paint(2, 1, {30, 90, 40});
  paint(0, 2, {30, 90, 40});
  paint(1, 2, {30, 90, 40});
  paint(2, 2, {120, 120, 118});
  t.inputs.emplace("rgb", rgb);
  EXPECT_EQ(classify(t, p).at(1, 1), 2);
  p["majority_radius"] = 3;
  try {
    classify(d, p);
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "texture.classify: inputs.rgb: halo 2 is narrower than params.majority_radius 3");
  }
}

TEST(Classify, ErrorsNameTheParameter) {
  CellData d;
  d.inputs.emplace("rgb", image());
  try {
    classify(d, json::object());
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "texture.classify: params: give \"boxes\", \"polygons\" or \"centres\" "
                 "(e.g. from texture.cluster)");
  }
  json p = kBoxes;
  p["snow_class"] = 3;
  try {
    classify(d, p);
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "texture.classify: params.snow_class needs inputs.dem");
  }
}

// A store in a temporary file holding features layers written through the Store API: WKB
// encoded by GDAL from WKT, indexed in the cells the grid's cover gives at the layer's level.
class FeatureStore {
 public:
  FeatureStore()
      : path_(fs::temp_directory_path() /
              ("classify_features_" + std::to_string(::getpid()) + ".mqt")) {
    fs::remove(path_);
    store_ = Store::open(path_.string(), Store::Mode::Create);
  }
  ~FeatureStore() {
    store_.reset();
    fs::remove(path_);
  }
  const Store& store() const { return *store_; }
  std::string path() const { return path_.string(); }

  void add_layer(const std::string& name, LayerKind kind, int level) {
    LayerInfo info;
    info.name = name;
    info.kind = kind;
    info.level = level;
    if (kind == LayerKind::Features) {
      info.dtype = DType::U8;
      info.tile_size = 1;
    }
    store_->create_layer(info);
  }
  // A (multi)polygon feature: its polygons as rings of lon/lat.
  void add_polygons(const std::string& layer, int64_t fid,
                    const std::vector<PolygonRings>& polygons) {
    std::string wkt = "MULTIPOLYGON (";
    std::vector<CellId> cells;
    const int level = store_->require_layer(layer).level;
    for (const PolygonRings& rings : polygons) {
      wkt += (&rings == &polygons.front() ? "(" : ", (");
      for (const auto& ring : rings) {
        wkt += (&ring == &rings.front() ? "(" : ", (");
        for (const LonLat& p : ring)
          wkt += (&p == &ring.front() ? "" : ", ") + std::to_string(p.lon) + " " +
                 std::to_string(p.lat);
        wkt += ")";
      }
      wkt += ")";
      const auto cover = default_grid().cover_polygon(rings, level, Containment::Overlap);
      cells.insert(cells.end(), cover.begin(), cover.end());
    }
    add(layer, fid, wkt + ")", cells);
  }
  void add_point(const std::string& layer, int64_t fid, LonLat p) {
    const int level = store_->require_layer(layer).level;
    add(layer, fid, "POINT (" + std::to_string(p.lon) + " " + std::to_string(p.lat) + ")",
        {default_grid().cell_from_point(p, level)});
  }

 private:
  void add(const std::string& layer, int64_t fid, const std::string& wkt,
           std::vector<CellId> cells) {
    OGRGeometry* g = nullptr;
    ASSERT_EQ(OGRGeometryFactory::createFromWkt(wkt.c_str(), nullptr, &g), OGRERR_NONE) << wkt;
    Feature f;
    f.fid = fid;
    f.wkb.resize(size_t(g->WkbSize()));
    g->exportToWkb(wkbNDR, reinterpret_cast<unsigned char*>(f.wkb.data()), wkbVariantIso);
    OGREnvelope e;
    g->getEnvelope(&e);
    f.bbox = {e.MinX, e.MinY, e.MaxX, e.MaxY};
    OGRGeometryFactory::destroyGeometry(g);
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    Store::Batch batch(*store_);
    batch.put_feature(layer, f, cells);
    batch.commit();
  }

  fs::path path_;
  std::unique_ptr<Store> store_;
};

// texture.classify of `rgb` on `cell`, reading features layers from `store`.
Tile<float> classify_with(const Store* store, CellId cell, const Tile<float>& rgb,
                          const json& params) {
  const auto& op = static_cast<const CellOperator&>(texture_operator("texture.classify"));
  const json full = full_params("texture.classify", params);
  CellData d;
  d.inputs.emplace("rgb", rgb);
  d.outputs.emplace("classes", Tile<float>(rgb.size(), 1));
  op.run({.cell = cell,
          .tile_size = rgb.size(),
          .grid = &default_grid(),
          .params = &full,
          .store = store},
         d);
  return d.outputs.at("classes");
}

// One colour everywhere, halo included.
Tile<float> uniform(int size, int halo, std::array<float, 3> rgb) {
  Tile<float> t(size, 3, halo);
  for (int r = -halo; r < size + halo; ++r)
    for (int c = -halo; c < size + halo; ++c)
      for (int k = 0; k < 3; ++k) t.at(c, r, k) = rgb[size_t(k)];
  return t;
}

// Pixel centres of kCell's tile of `size`: on the equatorial face P a column has one longitude
// and a row one latitude, so polygons with edges half-way between centres are hand-checkable.
struct Centres {
  int size;
  LonLat at(int col, int row) const {
    return pixel_centre(default_grid(),
                        {kCell.face(), global_col(kCell, size, col), global_row(kCell, size, row)},
                        kCell.level() + log2_tile_size(size));
  }
  double lon(double col) const {  // between centres for a fractional column
    const int c = int(std::floor(col));
    return at(c, 0).lon + (col - c) * (at(c + 1, 0).lon - at(c, 0).lon);
  }
  double lat(double row) const {
    const int r = int(std::floor(row));
    return at(0, r).lat + (row - r) * (at(0, r + 1).lat - at(0, r).lat);
  }
};

// Features exclude the pixels whose centre is inside: a rectangle over columns 0..5 with a hole
// over columns 2..3 of rows 7..8, and a triangle in the east (a multipolygon of two parts, one
// of them spilling out of the tile); the result is the same whatever the level of the index.
TEST(Classify, ExcludedFeatures) {
  const int n = 16;
  const Centres at{n};
  for (int r = 0; r < n; ++r) ASSERT_EQ(at.at(3, r).lon, at.at(3, 0).lon);
  for (int c = 0; c < n; ++c) ASSERT_EQ(at.at(c, 5).lat, at.at(0, 5).lat);
  const auto box = [&](double c0, double r0, double c1, double r1) {
    return std::vector<LonLat>{{at.lon(c0), at.lat(r0)},
                               {at.lon(c1), at.lat(r0)},
                               {at.lon(c1), at.lat(r1)},
                               {at.lon(c0), at.lat(r1)},
                               {at.lon(c0), at.lat(r0)}};
  };
  const PolygonRings west = {box(-3, -3, 5.5, n + 2), box(1.5, 6.5, 3.5, 8.5)};
  const LonLat a{at.lon(7.5), at.lat(n + 3)}, b{at.lon(n + 3), at.lat(n + 3)},
      t{at.lon(n + 3), at.lat(-3)};
  const PolygonRings triangle = {{a, b, t, a}};
  // The triangle by hand: above the side a b (rows increase southward), west of b t, and on
  // the side of a t where b is.
  const auto in_triangle = [&](LonLat p) {
    const double side = (t.lon - a.lon) * (p.lat - a.lat) - (t.lat - a.lat) * (p.lon - a.lon);
    return p.lon < b.lon && p.lat > a.lat && side < 0;
  };
  const json params = {{"boxes", {{{"id", 1}, {"hue", {340, 20}}}}}, {"exclude_features", "mask"}};
  std::vector<float> first;
  for (const int level : {10, 7, 13}) {
    FeatureStore s;
    s.add_layer("mask", LayerKind::Features, level);
    s.add_polygons("mask", 4, {west, triangle});
    const Tile<float> k = classify_with(&s.store(), kCell, uniform(n, 0, {200, 30, 20}), params);
    int in_west = 0, in_hole = 0, in_tri = 0, kept = 0;
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const bool hole = c >= 2 && c <= 3 && r >= 7 && r <= 8;
        const bool tri = in_triangle(at.at(c, r));
        const bool excluded = (c <= 5 && !hole) || tri;
        EXPECT_EQ(std::isnan(k.at(c, r)), excluded) << c << " " << r << " level " << level;
        if (!excluded) {
          EXPECT_EQ(k.at(c, r), 1);
        }
        in_west += c <= 5 && !hole, in_hole += hole, in_tri += tri, kept += !excluded;
      }
    EXPECT_EQ(in_west, 6 * n - 4);
    EXPECT_EQ(in_hole, 4);
    EXPECT_GT(in_tri, 30);
    EXPECT_GT(kept, 60);
    const std::vector<float> values(k.data().begin(), k.data().end());
    if (first.empty()) first = values;
    EXPECT_TRUE(
        std::equal(values.begin(), values.end(), first.begin(),
                   [](float x, float y) { return x == y || (std::isnan(x) && std::isnan(y)); }))
        << "level " << level;
  }
}

// Excluded pixels of the ring around the tile do not vote in the majority filter: a red tile in
// a green ring of 2, the western ring excluded, radius 2.
TEST(Classify, ExcludedFeaturesInTheRing) {
  const int n = 4;
  const Centres at{n};
  Tile<float> rgb = uniform(n, 2, {30, 90, 40});
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) rgb.at(c, r, 0) = 200, rgb.at(c, r, 1) = 30, rgb.at(c, r, 2) = 20;
  FeatureStore s;
  s.add_layer("mask", LayerKind::Features, 10);
  s.add_polygons("mask", 1,
                 {{{{at.lon(-4), at.lat(-4)},
                    {at.lon(-0.5), at.lat(-4)},
                    {at.lon(-0.5), at.lat(n + 4)},
                    {at.lon(-4), at.lat(n + 4)}}}});
  json p = json::parse(
      R"({"boxes": [{"id": 1, "hue": [340, 20]}, {"id": 2, "hue": [90, 180]}], "majority_radius": 2})");
  const Tile<float> kept = classify_with(&s.store(), kCell, rgb, p);
  p["exclude_features"] = "mask";
  const Tile<float> k = classify_with(&s.store(), kCell, rgb, p);
  // Corner (0, 0): 16 green and 9 red around it; 6 green and 9 red with columns -2, -1 out.
  EXPECT_EQ(kept.at(0, 0), 2);
  EXPECT_EQ(k.at(0, 0), 1);
  EXPECT_EQ(kept.at(0, 3), 2);
  EXPECT_EQ(k.at(0, 3), 1);
  // (0, 1): 13 green and 12 red; 3 green and 12 red.
  EXPECT_EQ(kept.at(0, 1), 2);
  EXPECT_EQ(k.at(0, 1), 1);
  // The eastern ring is not excluded: corners (3, 0) and (3, 3) stay green.
  EXPECT_EQ(k.at(3, 0), 2);
  EXPECT_EQ(k.at(3, 3), 2);
}

TEST(Classify, ExcludedFeaturesErrors) {
  FeatureStore s;
  s.add_layer("dem", LayerKind::Raster, 10);
  s.add_layer("empty", LayerKind::Features, 10);
  s.add_layer("points", LayerKind::Features, 10);
  const Centres at{4};
  s.add_point("points", 3, at.at(1, 1));
  const auto error = [&](const Store* store, const std::string& layer) {
    try {
      classify_with(store, kCell, uniform(4, 0, {200, 30, 20}),
                    {{"boxes", {{{"id", 1}}}}, {"exclude_features", layer}});
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string where = "texture.classify: params.exclude_features: ";
  EXPECT_EQ(error(&s.store(), "nope"), where + "unknown layer 'nope' in " + s.path());
  EXPECT_EQ(error(&s.store(), "dem"),
            where + "layer 'dem' in " + s.path() + " is a raster layer, not a features layer");
  EXPECT_EQ(error(&s.store(), "empty"),
            where + "layer 'empty' in " + s.path() + " has no features");
  EXPECT_EQ(error(&s.store(), "points"), where + "feature 3 of 'points' is a Point, not a polygon");
  EXPECT_EQ(error(nullptr, "points"), where + "no store (the layer is read from the run's store)");
}

// The banded index gives polygon_contains's answers: a 360-vertex wavy ring with a hole, on a
// lattice of points, and by hand at points in the hole, the body and beyond the waves.
TEST(PolygonSet, SameAnswersAsPolygonContains) {
  std::vector<LonLat> outer, hole;
  for (int i = 0; i <= 360; ++i) {
    const double t = (i % 360) * M_PI / 180, r = 10 + 3 * std::sin(7 * t);
    outer.push_back({r * std::cos(t), r * std::sin(t)});
  }
  for (int i = 0; i < 4; ++i) hole.push_back({i % 3 == 0 ? -2.0 : 2.0, i < 2 ? -2.0 : 2.0});
  const PolygonRings wavy = {outer, hole};
  const PolygonSet set({wavy});
  EXPECT_FALSE(set.contains({0, 0}));   // hole
  EXPECT_TRUE(set.contains({5, 0}));    // body
  EXPECT_TRUE(set.contains({9.5, 0}));  // angle 0: radius 10
  EXPECT_FALSE(set.contains({10.5, 0}));
  EXPECT_TRUE(set.contains({0, 6.5}));  // angle 90: radius 10 + 3 sin(630 degrees) = 7
  EXPECT_FALSE(set.contains({0, 7.5}));
  int inside = 0;
  for (double x = -14; x <= 14; x += 0.173)
    for (double y = -14; y <= 14; y += 0.131) {
      EXPECT_EQ(set.contains({x, y}), polygon_contains(wavy, {x, y})) << x << " " << y;
      inside += set.contains({x, y});
    }
  EXPECT_GT(inside, 1000);
  EXPECT_TRUE(PolygonSet({}).empty());
}

TEST(Cluster, KMeansFindsTheColoursAndClassifies) {
  const auto run = [] {
    return run_reduce("texture.cluster", {kCell}, 4,
                      [](CellId) {
                        CellData d;
                        d.inputs.emplace("rgb", image());
                        return d;
                      },
                      {{"k", 3}});
  };
  const json clusters = run();
  EXPECT_EQ(clusters, run());
  const json& c = clusters.at("centres");
  ASSERT_EQ(c.size(), 3u);
  for (const auto& z : c) EXPECT_GT(z["pixels"].get<int>(), 0);
  // Red, green and the two greys (same hue 300, low saturation) fall in three clusters.
  CellData d;
  d.inputs.emplace("rgb", image());
  const Tile<float> k = classify(d, {{"centres", c}});
  EXPECT_NE(k.at(0, 0), k.at(0, 1));
  EXPECT_NE(k.at(0, 0), k.at(0, 2));
  EXPECT_NE(k.at(0, 1), k.at(0, 2));
  EXPECT_EQ(k.at(0, 2), k.at(0, 3));
  EXPECT_EQ(k.at(0, 0), k.at(3, 0));
}

// Zion's surface types as "lab" clusters: red rock and cream sandstone have nearly the same
// hue-saturation-value brightness band apart from their chroma; lit and shaded forest differ in
// lightness only. The centres are the bins' CIELAB colours (within half a bin of each colour:
// 1.5 in a* and b*, 2.5 in L*), and texture.classify with them gives each colour its class.
TEST(Cluster, LabCentresAreTheColoursAndClassify) {
  const std::vector<std::array<float, 3>> colours = {
      {176, 98, 66}, {214, 200, 170}, {52, 66, 44}, {40, 50, 34}};  // rock, sandstone, forest
  Tile<float> rgb(4, 3);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 3; ++k) rgb.at(c, r, k) = colours[size_t(r)][size_t(k)];
  const json clusters = run_reduce("texture.cluster", {kCell}, 4,
                                   [&](CellId) {
                                     CellData d;
                                     d.inputs.emplace("rgb", rgb);
                                     return d;
                                   },
                                   {{"k", 3}, {"space", "lab"}});
  EXPECT_EQ(clusters.at("space"), "lab");
  const json& c = clusters.at("centres");
  ASSERT_EQ(c.size(), 3u);
  std::vector<int> found;
  for (size_t i = 0; i < 2; ++i) {  // rock and sandstone: one cluster each, at the bin's centre
    const Lab lab = srgb_to_lab(colours[i][0], colours[i][1], colours[i][2]);
    bool matched = false;
    for (const auto& z : c)
      matched = matched || (std::abs(z["L"].get<double>() - lab[0]) <= 2.5 &&
                            std::abs(z["a"].get<double>() - lab[1]) <= 1.5 &&
                            std::abs(z["b"].get<double>() - lab[2]) <= 1.5);
    EXPECT_TRUE(matched) << i << " " << c;
  }
  CellData d;
  d.inputs.emplace("rgb", rgb);
  const Tile<float> k = classify(d, {{"centres", c}});
  EXPECT_NE(k.at(0, 0), k.at(0, 1));
  EXPECT_NE(k.at(0, 0), k.at(0, 2));
  EXPECT_NE(k.at(0, 1), k.at(0, 2));
  EXPECT_EQ(k.at(0, 2), k.at(0, 3));  // lit and shaded forest: one class
}

// Nearest CIELAB centre by hand, in (a*, b*, L* / 2): a grey pixel of L* 60 is nearer a centre
// of L* 40 (distance 10) than one of a* 12 (12), and nearer one of L* 55, a* 6
// (sqrt(2.5^2 + 6^2) = 6.5) than one of L* 80 (10). Errors name the centre.
TEST(Classify, LabCentresNearestWithLightnessWeighted) {
  const Lab grey = srgb_to_lab(145, 145, 145);  // L* 60.0
  const auto centre = [](int id, double l, double a, double b) {
    return json{{"id", id}, {"L", l}, {"a", a}, {"b", b}};
  };
  const float g = 145;
  EXPECT_NEAR(grey[0], 60, 0.2);
  EXPECT_EQ(classes_of({{g, g, g}},
                       {{"centres", {centre(1, grey[0] - 20, 0, 0), centre(2, grey[0], 12, 0)}}}),
            std::vector<int>{1});
  EXPECT_EQ(
      classes_of({{g, g, g}},
                 {{"centres", {centre(1, grey[0] + 20, 0, 0), centre(2, grey[0] - 5, 6, 0)}}}),
      std::vector<int>{2});
  EXPECT_EQ(
      error_of({{"centres", {centre(1, 50, 0, 0), {{"id", 2}, {"hue", 10}, {"saturation", 0.5}}}}}),
      "texture.classify: params.centres: give CIELAB colours for every centre or for none "
      "(centre id 2)");
  EXPECT_EQ(error_of({{"centres", {{{"id", 3}, {"L", 50}, {"a", 0}}}}}),
            "texture.classify: params.centres: centre id 3: give \"hue\" and \"saturation\" (and "
            "\"value\"), or \"L\", \"a\" and \"b\", got {\"L\":50,\"a\":0,\"id\":3}");
}

// Test pairs 1, 7, 17 and 25 of Sharma, Wu and Dalal (2005).
TEST(Colour, Ciede2000ReferenceValues) {
  EXPECT_NEAR(ciede2000({50, 2.6772, -79.7751}, {50, 0, -82.7485}), 2.0425, 1e-4);
  EXPECT_NEAR(ciede2000({50, 0, 0}, {50, -1, 2}), 2.3669, 1e-4);
  EXPECT_NEAR(ciede2000({50, 2.5, 0}, {73, 25, -18}), 27.1492, 1e-4);
  EXPECT_NEAR(ciede2000({60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}), 1.2644, 1e-4);
  const auto white = srgb_to_lab(255, 255, 255);
  EXPECT_NEAR(white[0], 100, 1e-3);
  EXPECT_NEAR(white[1], 0, 1e-2);
}

}  // namespace
}  // namespace maquette::texture
