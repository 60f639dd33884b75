// The campus example (examples/campus-soho.json: paper 002's campus scenario on London Soho) run
// by the real program on ../shared/data, as a user runs it, every step: the DEM, the imagery,
// the footprints, the strokes and the hotel's model (maquette-prism) ingested, a canal carved and
// filled, a footbridge, buildings, trees, a placed tree and the placed hotel made, the 3D Tiles
// written. Checked against independent oracles:
// - buildings: one per footprint of examples/campus-soho/footprints.vrt, counted by OGR (the
//   shared file's 158 less the two garden squares), each 10 m high (no height tags) with its
//   lowest vertex on the ground: the DEM's 25 m above EGM96 taken to the ellipsoid by PROJ;
// - trees: every plant inside its stroke (OGR), one per spacing_m^2 of the stroke's geodesic
//   area (GeographicLib) or a little more (the edge effect below), every pair at least the
//   blue noise's minimum distance apart (geodesics), on the ground (PROJ);
// - the placed tree: at its stroke's centre, scaled by sqrt(stroke area / the trunk's base area)
//   (the prototype's base: its trunk's convex foot, by GEOS), its heading the stroke's, on the
//   ground;
// - the hotel: at its stroke's centroid (OGR), on the ground, along the stroke's principal axis,
//   scaled to the stroke's geodesic area over its floor's;
// - the canal and footbridge: the bed on the curve's height and the deck's ends on the deformed
//   DEM as GDAL reads its GeoTIFF export (PROJ's EGM96), the deck's floor above the water;
// - the 3D Tiles: read as a viewer reads them (regions, Draco decoded, tileset_reader.h), each
//   content layer shipped, the buildings, the deck and the water drawn with a material that is
//   not a metal and with decoded normals along their faces' (a sliver's along its neighbours'),
//   and every GLB valid by the Khronos glTF validator.
// Skipped when the data is absent.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/PolygonArea.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "content/prototypes.h"
#include "egm96_oracle.h"
#include "example_pipeline.h"
#include "gltf/gltf_model.h"
#include "gltf/mesh_glb.h"
#include "run_cli.h"
#include "store/store.h"
#include "stored_content.h"
#include "tileset_reader.h"

namespace maquette::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kSoho = kShared + "/data/buildings/london_soho_buildings_wgs84.geojson";
constexpr double kGroundEgm96 = 25;  // examples/campus-soho/ground.asc
constexpr double kPi = std::numbers::pi;
// The content layers the example exports (its export step's `content`).
const std::array<std::string, 5> kContentLayers{"buildings", "trees", "placed", "water", "bridge"};

// The example run once, its store and export in a temporary folder, its sources at their
// absolute paths (example_pipeline.h).
struct ExampleRun {
  std::string dir = temp_dir();
  std::string store = dir + "/campus-soho.mqt";
  std::string tiles = dir + "/campus-soho-output/tiles3d";
  CliResult result;
  std::string hotel = dir + "/hotel.glb";
  // As examples/campus-soho/run.sh: maquette-prism writes the hotel's GLB, the pipeline ingests
  // it (here from the temporary folder).
  ExampleRun() {
    json pipeline = example_pipeline("campus-soho");
    for (json& step : pipeline["steps"])
      if (step["op"] == "ingest" && step["params"]["as"] == "model")
        step["params"]["sources"] = json::array({hotel});
    std::ofstream(dir + "/pipeline.json") << pipeline.dump(1);
    const std::string prism = std::string(MAQUETTE_BIN_DIR) + "/maquette-prism " + kExamples +
                              "/prism-building.json " + hotel + " > /dev/null";
    result.exit_code = std::system(prism.c_str());
    if (result.exit_code == 0) result = run_maquette("-q run " + dir + "/pipeline.json");
  }
};

const ExampleRun& example() {
  static const ExampleRun run;
  return run;
}

bool have_data() { return fs::exists(kSoho) && fs::exists(kShared + "/data/global/world.tif"); }

#define REQUIRE_EXAMPLE()                                                    \
  if (!have_data()) GTEST_SKIP() << "no ../shared/data (buildings, global)"; \
  ASSERT_EQ(example().result.exit_code, 0) << example().result.err;

// The ground's height above the ellipsoid at lon, lat: the DEM's EGM96 height by PROJ.
double ground(double lon, double lat) {
  static const Egm96ToEllipsoid to_ellipsoid;
  return to_ellipsoid(lon, lat, kGroundEgm96);
}

// A vector file's features, read by OGR.
std::vector<std::unique_ptr<OGRGeometry>> geometries(const std::string& path) {
  GDALAllRegister();
  const std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  EXPECT_TRUE(ds) << path;
  std::vector<std::unique_ptr<OGRGeometry>> out;
  if (!ds) return out;
  for (const auto& feature : *ds->GetLayer(0)) out.emplace_back(feature->GetGeometryRef()->clone());
  return out;
}

// The example's strokes: as JSON (properties) and as OGR reads them, in the file's order.
struct Strokes {
  json collection = read_json(kExamples + "/campus-soho/strokes.geojson");
  std::vector<std::unique_ptr<OGRGeometry>> shapes =
      geometries(kExamples + "/campus-soho/strokes.geojson");
};

const Strokes& example_strokes() {
  static const Strokes strokes;
  return strokes;
}

// A stored instance (stored_content.h) with its heading: degrees clockwise from north of the
// model's +y, a quarter turn anticlockwise from its +x.
struct Instance : StoredInstance {
  double heading_deg = 0;
};

std::vector<Instance> instances(const std::string& layer) {
  std::vector<Instance> out;
  for (const StoredInstance& s :
       stored_instances(*Store::open(example().store, Store::Mode::ReadOnly), layer))
    out.push_back({s, std::atan2(-s.x_axis[1], s.x_axis[0]) * 180 / kPi});
  return out;
}

// The geodesic area (m2) of a polygon's outer ring less its holes, by GeographicLib.
double geodesic_area(const OGRPolygon& polygon) {
  double area = 0;
  for (int r = 0; r <= polygon.getNumInteriorRings(); ++r) {
    const OGRLinearRing* ring = r == 0 ? polygon.getExteriorRing() : polygon.getInteriorRing(r - 1);
    GeographicLib::PolygonArea p(GeographicLib::Geodesic::WGS84());
    for (int i = 0; i + 1 < ring->getNumPoints(); ++i) p.AddPoint(ring->getY(i), ring->getX(i));
    double perimeter = 0, a = 0;
    p.Compute(false, true, perimeter, a);
    area += (r == 0 ? 1 : -1) * std::abs(a);
  }
  return area;
}

TEST(CampusExample, BuildingsStandOnTheGround) {
  REQUIRE_EXAMPLE();
  const size_t footprints = geometries(kExamples + "/campus-soho/footprints.vrt").size();
  EXPECT_EQ(footprints, geometries(kSoho).size() - 2);  // less the two gardens
  const auto st = Store::open(example().store, Store::Mode::ReadOnly);
  EXPECT_EQ(st->content_stats("buildings").content.objects, footprints);
  double worst_base = 0, worst_top = 0;
  size_t checked = 0;
  for (const auto& [origin, mesh] : stored_meshes(*st, "buildings")) {
    const GeographicLib::LocalCartesian frame(origin.lat, origin.lon, origin.height);
    for (const MeshObject& o : mesh.objects) {
      double low = INFINITY, high = -INFINITY, lon = 0, lat = 0;
      for (size_t k = 0; k < o.positions.size(); k += 3) {
        double vlat = 0, vlon = 0, vh = 0;
        frame.Reverse(o.positions[k], o.positions[k + 1], o.positions[k + 2], vlat, vlon, vh);
        if (vh < low) low = vh, lon = vlon, lat = vlat;
        high = std::max(high, vh);
      }
      worst_base = std::max(worst_base, std::abs(low - ground(lon, lat)));
      worst_top = std::max(worst_top, std::abs(high - low - 10));
      ++checked;
    }
  }
  EXPECT_EQ(checked, footprints);
  std::printf("%zu buildings: base - ground %.1f mm, height - 10 m %.1f mm at worst\n", checked,
              worst_base * 1000, worst_top * 1000);
  EXPECT_LE(worst_base, 0.01);
  EXPECT_LE(worst_top, 0.01);
}

TEST(CampusExample, TreesFillTheirStrokesOnTheGround) {
  REQUIRE_EXAMPLE();
  const json& strokes = example_strokes().collection;
  const auto& shapes = example_strokes().shapes;
  std::map<int64_t, std::vector<Instance>> per_stroke;
  double worst_base = 0;
  for (const Instance& t : instances("trees")) {
    ASSERT_GE(t.provenance.feature_id, 1);
    ASSERT_LE(size_t(t.provenance.feature_id), shapes.size());
    // The ingest numbers features from 1 in the file's order.
    const json& properties = strokes["features"][size_t(t.provenance.feature_id - 1)]["properties"];
    EXPECT_EQ(properties["tool"], "vegetation");
    const OGRPoint point(t.lon, t.lat);
    EXPECT_TRUE(shapes[size_t(t.provenance.feature_id - 1)]->Contains(&point))
        << "a tree of stroke " << t.provenance.feature_id << " outside it at " << t.lon << ", "
        << t.lat;
    EXPECT_EQ(t.prototype, "builtin:broadleaf");
    EXPECT_GE(t.scale[0], 9);
    EXPECT_LE(t.scale[0], 14);
    worst_base = std::max(worst_base, std::abs(t.height - ground(t.lon, t.lat)));
    per_stroke[t.provenance.feature_id].push_back(t);
  }
  int vegetation = 0;
  for (size_t i = 0; i < shapes.size(); ++i) {
    const json& properties = strokes["features"][i]["properties"];
    if (properties["tool"] != "vegetation") continue;
    ++vegetation;
    const double spacing = properties["spacing_m"];
    const double expected = geodesic_area(*shapes[i]->toPolygon()) / (spacing * spacing);
    const std::vector<Instance>& trees = per_stroke[int64_t(i) + 1];
    // Blue noise: every pair at least 0.769 spacing apart (modules/structures/README.md).
    double closest = INFINITY;
    for (size_t a = 0; a < trees.size(); ++a)
      for (size_t b = a + 1; b < trees.size(); ++b) {
        double d = 0;
        GeographicLib::Geodesic::WGS84().Inverse(trees[a].lat, trees[a].lon, trees[b].lat,
                                                 trees[b].lon, d);
        closest = std::min(closest, d);
      }
    std::printf("%s: %zu trees, area / spacing^2 = %.1f, closest pair %.2f m (spacing %.0f m)\n",
                properties["name"].get<std::string>().c_str(), trees.size(), expected, closest,
                spacing);
    EXPECT_GE(closest, 0.769 * spacing) << properties["name"];
    // One plant per spacing^2 on average (poisson_disk.h: the plane sampled whole, the stroke
    // cut out of it); a garden of a few dozen trees within a quarter of that.
    EXPECT_GE(double(trees.size()), 0.75 * expected) << properties["name"];
    EXPECT_LE(double(trees.size()), 1.25 * expected) << properties["name"];
  }
  EXPECT_EQ(vegetation, 2);
  EXPECT_LE(worst_base, 0.01);
}

TEST(CampusExample, TheStrokePlacesOneTree) {
  REQUIRE_EXAMPLE();
  const json& strokes = example_strokes().collection;
  const auto& shapes = example_strokes().shapes;
  std::vector<Instance> placed = instances("placed");
  ASSERT_EQ(placed.size(), 2u);  // the tree and the hotel
  std::erase_if(placed, [](const Instance& p) { return p.prototype == "hotel"; });
  ASSERT_EQ(placed.size(), 1u);
  const Instance& tree = placed[0];
  const size_t index = size_t(tree.provenance.feature_id - 1);
  ASSERT_LT(index, shapes.size());
  const json& properties = strokes["features"][index]["properties"];
  EXPECT_EQ(properties["tool"], "place");
  EXPECT_EQ(tree.prototype, properties["model"]);
  // At the stroke's centre (its ring is regular: the mean of its vertices), on the ground.
  const OGRLinearRing* ring = shapes[index]->toPolygon()->getExteriorRing();
  const int n = ring->getNumPoints() - 1;
  double lon = 0, lat = 0;
  for (int i = 0; i < n; ++i) lon += ring->getX(i) / n, lat += ring->getY(i) / n;
  double e = 0, north = 0, u = 0;
  GeographicLib::LocalCartesian(lat, lon, 0).Forward(tree.lat, tree.lon, 0, e, north, u);
  EXPECT_LE(std::hypot(e, north), 0.02);
  EXPECT_NEAR(tree.height, ground(tree.lon, tree.lat), 0.01);
  // The model's base (modules/structures/README.md): its floor, the trunk's foot, a convex
  // polygon: the convex hull (GEOS) of the vertices within 5 cm of the lowest. The scale takes
  // it to the stroke's area.
  OGRMultiPoint low;
  const MeshContent& model = builtin_prototype(tree.prototype);
  double lowest = INFINITY;
  for (const MeshObject& o : model.objects)
    for (size_t k = 2; k < o.positions.size(); k += 3)
      lowest = std::min(lowest, double(o.positions[k]));
  for (const MeshObject& o : model.objects)
    for (size_t k = 0; k < o.positions.size(); k += 3)
      if (o.positions[k + 2] <= lowest + 0.05) {
        const OGRPoint vertex(o.positions[k], o.positions[k + 1]);
        low.addGeometry(&vertex);
      }
  const std::unique_ptr<OGRGeometry> base(low.ConvexHull());
  const double scale =
      std::sqrt(geodesic_area(*shapes[index]->toPolygon()) / base->toPolygon()->get_Area());
  EXPECT_NEAR(tree.scale[0] / scale, 1, 1e-3);
  EXPECT_NEAR(std::remainder(tree.heading_deg - properties["heading_deg"].get<double>(), 360), 0,
              1e-3);
  std::printf("placed %s: %.2f m from the stroke's centre, scale %.3f (area ratio %.3f)\n",
              tree.prototype.c_str(), std::hypot(e, north), double(tree.scale[0]), scale);
}

// The hotel modelled from building.jpg (examples/prism-building.json), placed by a closed stroke
// drawn around its footprint: at the stroke's centre, on the ground, its long side (the facade,
// the model's x) along the stroke's long axis, at the scale that takes the model's floor (a
// rectangle) to the stroke's area (GeographicLib), within the 3 % of issue 17.
TEST(CampusExample, TheStrokePlacesTheHotelFromThePhoto) {
  REQUIRE_EXAMPLE();
  const auto& shapes = example_strokes().shapes;
  std::vector<Instance> placed = instances("placed");
  std::erase_if(placed, [](const Instance& p) { return p.prototype != "hotel"; });
  ASSERT_EQ(placed.size(), 1u);
  const Instance& hotel = placed[0];
  const size_t index = size_t(hotel.provenance.feature_id - 1);
  ASSERT_LT(index, shapes.size());
  EXPECT_EQ(example_strokes().collection["features"][index]["properties"]["model"], "hotel");
  // The stroke (a hand's: 56 points) at its centroid (OGR), its long axis the principal axis of
  // its points in the tangent plane there.
  OGRPoint centroid;
  ASSERT_EQ(shapes[index]->Centroid(&centroid), OGRERR_NONE);
  const GeographicLib::LocalCartesian frame(centroid.getY(), centroid.getX(), 0);
  double e = 0, n = 0, u = 0;
  frame.Forward(hotel.lat, hotel.lon, 0, e, n, u);
  EXPECT_LE(std::hypot(e, n), 0.1);
  EXPECT_NEAR(hotel.height, ground(hotel.lon, hotel.lat), 0.01);
  const OGRLinearRing* ring = shapes[index]->toPolygon()->getExteriorRing();
  double see = 0, snn = 0, sen = 0;
  for (int i = 0; i + 1 < ring->getNumPoints(); ++i) {
    double x = 0, y = 0;
    frame.Forward(ring->getY(i), ring->getX(i), 0, x, y, u);
    see += x * x, snn += y * y, sen += x * y;
  }
  // The major axis' bearing (degrees clockwise from north).
  const double side_bearing = 90 - 0.5 * std::atan2(2 * sen, see - snn) * 180 / kPi;
  const MeshContent model = read_gltf_model(example().hotel);
  std::array<double, 2> lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  for (const MeshObject& o : model.objects)
    for (size_t k = 0; k < o.positions.size(); k += 3)
      for (size_t a = 0; a < 2; ++a)
        lo[a] = std::min(lo[a], double(o.positions[k + a])),
        hi[a] = std::max(hi[a], double(o.positions[k + a]));
  const double scale =
      std::sqrt(geodesic_area(*shapes[index]->toPolygon()) / ((hi[0] - lo[0]) * (hi[1] - lo[1])));
  EXPECT_NEAR(hotel.scale[0] / scale, 1, 0.03);
  // The model's +y is turned to the heading; its +x, the facade, runs along the stroke's long
  // axis, either way round.
  EXPECT_NEAR(std::remainder(hotel.heading_deg + 90 - side_bearing, 180), 0, 1);
  std::printf(
      "placed hotel: %.2f m from the stroke's centre, scale %.3f (area ratio %.3f), "
      "heading %.1f deg\n",
      std::hypot(e, n), double(hotel.scale[0]), scale, hotel.heading_deg);
}

// The deformed DEM (`ground`, EGM96 heights) as GDAL reads its GeoTIFF export in the grid's
// plane, bilinear between pixel centres, lon/lat taken to the plane by PROJ (OGR).
class ExportedGround {
 public:
  ExportedGround() {
    const std::string tif = example().dir + "/ground.tif";
    const CliResult r = run_maquette("-q export gtiff " + example().store + " " + tif +
                                     " --layer ground --bbox -0.1330 51.5147 -0.1315 51.5158");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    ds_.reset(GDALDataset::Open(tif.c_str(), GDAL_OF_RASTER));
    EXPECT_TRUE(ds_);
    ds_->GetGeoTransform(transform_.data());
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    to_plane_.reset(OGRCreateCoordinateTransformation(&wgs84, ds_->GetSpatialRef()));
  }
  double egm96(double lon, double lat) const {
    double x = lon, y = lat;
    EXPECT_TRUE(to_plane_->Transform(1, &x, &y));
    const double col = (x - transform_[0]) / transform_[1] - 0.5,
                 row = (y - transform_[3]) / transform_[5] - 0.5;
    const int c = int(std::floor(col)), r = int(std::floor(row));
    std::array<float, 4> v{};
    EXPECT_EQ(ds_->GetRasterBand(1)->RasterIO(GF_Read, c, r, 2, 2, v.data(), 2, 2, GDT_Float32, 0,
                                              0, nullptr),
              CE_None);
    const double fc = col - c, fr = row - r;
    return (1 - fr) * ((1 - fc) * v[0] + fc * v[1]) + fr * ((1 - fc) * v[2] + fc * v[3]);
  }

 private:
  std::unique_ptr<GDALDataset> ds_;
  std::array<double, 6> transform_{};
  std::unique_ptr<OGRCoordinateTransformation> to_plane_;
};

// The canal (deform.features) carved into Soho Square's garden, filled (deform.water), and the
// footbridge over it (structures.bridge): the canal's bed at its curve's height, the water at
// the stroke's level, the deck's four ends on the deformed DEM (PROJ's EGM96, 1 cm) and its floor
// above the water.
TEST(CampusExample, FootbridgeSpansTheFilledCanalFromBankToBank) {
  REQUIRE_EXAMPLE();
  const json& features = example_strokes().collection["features"];
  const auto stroke = [&](const std::string& tool) {
    for (const json& f : features)
      if (f["properties"]["tool"] == tool) return f;
    ADD_FAILURE() << "no stroke of tool " << tool;
    return json();
  };
  const ExportedGround dem;
  // The bed along the canal (its Z constant) at its inner vertices and its segments' midpoints;
  // at its ends the trench closes within a pixel (2.2 m), so no pixel there is all bed.
  const json canal = stroke("feature")["geometry"]["coordinates"];
  ASSERT_GE(canal.size(), 3u);
  for (size_t i = 0; i + 1 < canal.size(); ++i) {
    const double lon = (canal[i][0].get<double>() + canal[i + 1][0].get<double>()) / 2,
                 lat = (canal[i][1].get<double>() + canal[i + 1][1].get<double>()) / 2;
    EXPECT_NEAR(dem.egm96(lon, lat), canal[i][2].get<double>(), 0.01) << "segment " << i + 1;
    if (i > 0) {
      EXPECT_NEAR(dem.egm96(canal[i][0], canal[i][1]), canal[i][2].get<double>(), 0.01)
          << "vertex " << i;
    }
  }
  const auto st = Store::open(example().store, Store::Mode::ReadOnly);
  const std::vector<StoredMeshes> water = stored_meshes(*st, "water");
  ASSERT_EQ(water.size(), 1u);
  ASSERT_EQ(water[0].mesh.objects.size(), 1u);
  const double level = stroke("water")["properties"]["level"].get<double>();
  EXPECT_NEAR(water[0].mesh.objects[0].provenance.attributes.at("level").get<double>(), level,
              1e-6);

  const std::vector<StoredMeshes> decks = stored_meshes(*st, "bridge");
  ASSERT_EQ(decks.size(), 1u);
  ASSERT_EQ(decks[0].mesh.objects.size(), 1u);
  const MeshObject& deck = decks[0].mesh.objects[0];
  std::vector<std::array<double, 3>> vertices;
  for (size_t k = 0; k < deck.positions.size(); k += 3)
    vertices.push_back(enu_to_geodetic(decks[0].origin, deck.positions[k], deck.positions[k + 1],
                                       deck.positions[k + 2]));
  const Egm96ToEllipsoid to_ellipsoid;
  double worst_end = 0, lowest = INFINITY;
  for (const auto& v : vertices) lowest = std::min(lowest, v[2]);
  const json bridge = stroke("bridge");
  for (const json& edge : bridge["geometry"]["coordinates"])
    for (const json& end : {edge.front(), edge.back()}) {
      // The deck's top at this end: the highest vertex within 5 cm of it across the ground.
      const GeographicLib::LocalCartesian at(end[1], end[0], 0);
      double top = -INFINITY;
      for (const auto& v : vertices) {
        double e = 0, n = 0, u = 0;
        at.Forward(v[1], v[0], 0, e, n, u);
        if (std::hypot(e, n) < 0.05) top = std::max(top, v[2]);
      }
      const double terrain = to_ellipsoid(end[0], end[1], dem.egm96(end[0], end[1]));
      worst_end = std::max(worst_end, std::abs(top - terrain));
    }
  EXPECT_LE(worst_end, 0.01);
  const json& first = features[0]["geometry"]["coordinates"][0][0];  // any point of the garden
  const double water_ellipsoidal = to_ellipsoid(first[0], first[1], level);
  EXPECT_GT(lowest, water_ellipsoidal) << "the deck's floor in the water";
  std::printf("footbridge: ends %.1f mm from the deformed DEM, floor %.2f m above the water\n",
              1000 * worst_end, lowest - water_ellipsoidal);
}

// Checks a decoded primitive's normals: of unit length and along their faces' normals (the
// decoded positions' cross product: counter-clockwise from outside) within 1.5 degrees: faces
// within 1 degree share a normal (facet_normals.h; the overviews' simplified walls), Draco's 10
// bits (0.2), the node's rotation (0.01). Triangles of less than 1e-4 m^2 of doubled area are too
// small for a direction. A sliver (a triangle whose height over its longest side is within the
// reach of the positions' quantization, mesh_glb.h: each coordinate rounded by up to half a
// step, a flat triangle's corner can stand sqrt(3) steps off the line of the other two) has no
// direction of its own either: meshoptimizer's edge collapses leave such triangles in the
// overviews, three corners on one line of a flat face closing a T-junction (the lake's bed along
// a wall at levels 13 to 10: its decoded face normal 90 to 135 degrees off), drawn as nothing;
// each of its corners must carry the normal of a triangle with a direction that has a corner at
// its place (a neighbour's; by place, since Draco may give a sliver's corners vertices of their
// own): checked above for a corner that such a triangle uses, below for a corner only slivers
// use. Returns the corners checked; counts the slivers.
size_t check_normals(const DecodedPrimitive& p, size_t& slivers) {
  EXPECT_EQ(p.normals.size(), p.positions.size());
  if (p.normals.size() != p.positions.size()) return 0;
  const double min_dot = std::cos(1.5 * kPi / 180), step = MeshGlbSettings{}.position_error;
  using Direction = std::array<double, 3>;
  const auto along = [&](uint32_t v, const Direction& n) {
    const auto& m = p.normals[v];
    return m[0] * n[0] + m[1] * n[1] + m[2] * n[2] > min_dot;
  };
  std::vector<std::vector<Direction>> faces_at(p.positions.size());  // unit normals, by vertex
  std::vector<std::array<uint32_t, 3>> sliver_faces;
  size_t checked = 0;
  for (const auto& f : p.faces) {
    const auto &a = p.positions[f[0]], &b = p.positions[f[1]], &c = p.positions[f[2]];
    const Direction u{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
        w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    Direction n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double area2 = std::hypot(n[0], n[1], n[2]);
    if (area2 < 1e-4) continue;  // too small for a direction
    const double longest = std::max({std::hypot(u[0], u[1], u[2]), std::hypot(w[0], w[1], w[2]),
                                     std::hypot(c[0] - b[0], c[1] - b[1], c[2] - b[2])});
    if (area2 / longest < std::sqrt(3.0) * step) {
      sliver_faces.push_back(f);
      continue;
    }
    for (double& x : n) x /= area2;
    for (const uint32_t v : f) {
      const auto& m = p.normals[v];
      EXPECT_NEAR(std::hypot(m[0], m[1], m[2]), 1, 1e-3) << "corner " << v;
      EXPECT_TRUE(along(v, n)) << "corner " << v;
      faces_at[v].push_back(n);
      ++checked;
    }
  }
  // The directions of the faces at each place.
  std::map<std::array<double, 3>, std::vector<Direction>> faces_at_place;
  for (size_t v = 0; v < p.positions.size(); ++v)
    for (const Direction& n : faces_at[v]) faces_at_place[p.positions[v]].push_back(n);
  for (const auto& f : sliver_faces)
    for (const uint32_t v : f) {
      if (!faces_at[v].empty()) continue;  // checked against a face with a direction above
      bool neighbours = false;
      for (const uint32_t shared : f)
        for (const Direction& n : faces_at_place[p.positions[shared]])
          neighbours = neighbours || along(v, n);
      EXPECT_TRUE(neighbours) << "corner " << v << " of a sliver: not a neighbour's normal";
      ++checked;
    }
  slivers += sliver_faces.size();
  return checked;
}

// The buildings, the deck and the water as the viewer draws them: every normal decoded from
// Draco along its face's (check_normals), every primitive with a material that is not a metal
// (glTF's default material, and an absent metallicFactor, mean metallic 1, which three.js without
// an environment map drew pure black on every wall facing away from its sun).
TEST(CampusExample, BuildingsDeckAndWaterAreLitWhereTheSunDoesNotReach) {
  REQUIRE_EXAMPLE();
  const Export out = read_export(example().tiles);
  const std::array<std::string, 3> kLit{"buildings", "bridge", "water"};
  std::map<std::string, size_t> checked, slivers;
  for (const auto& [uri, glb] : out.glbs) {
    // (&uri = uri: clang 14, the fuzz build's compiler, cannot capture a structured binding)
    const auto layer = std::find_if(kLit.begin(), kLit.end(), [&uri = uri](const std::string& l) {
      return uri.ends_with("." + l + ".glb");
    });
    if (layer == kLit.end()) continue;
    SCOPED_TRACE(uri);
    for (const json& prim : glb.json["meshes"][0]["primitives"]) {
      ASSERT_TRUE(prim.contains("material"));
      const json& material = glb.json["materials"][prim["material"].get<size_t>()];
      EXPECT_LT(material["pbrMetallicRoughness"].value("metallicFactor", 1.0), 1);
    }
    for (const DecodedPrimitive& p : glb.primitives)
      checked[*layer] += check_normals(p, slivers[*layer]);
  }
  for (const auto& [layer, n] : checked)
    std::printf("%s: %zu corners' normals checked, %zu slivers\n", layer.c_str(), n,
                slivers[layer]);
  EXPECT_GT(checked["buildings"], 10000u);
  EXPECT_GT(checked["bridge"], 100u);
  EXPECT_GT(checked["water"], 1000u);
}

TEST(CampusExample, TilesetHoldsTheTerrainAndEveryContentLayer) {
  REQUIRE_EXAMPLE();
  const Export out = read_export(example().tiles);
  std::map<std::string, int> glbs;
  for (const auto& [uri, glb] : out.glbs)
    for (const std::string& layer : kContentLayers)
      glbs[layer] += uri.ends_with("." + layer + ".glb");  // OUTDIR/<stem>.<LAYER>.glb
  size_t content = 0;
  for (const std::string& layer : kContentLayers) {
    EXPECT_GT(glbs[layer], 0) << "no GLB of " << layer;
    content += size_t(glbs[layer]);
  }
  EXPECT_GT(out.glbs.size(), content) << "no terrain";
  const auto valid = gltf_validator_passes(example().tiles);
  if (!valid)
    GTEST_SKIP() << "gltf-validator not installed (npm ci in " MAQUETTE_NODE_DIR " failed)";
  EXPECT_TRUE(*valid);
}

}  // namespace
}  // namespace maquette::test
