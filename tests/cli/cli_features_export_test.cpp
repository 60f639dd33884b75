// `maquette export geojson|gpkg` through the real program: features out as ingested, read back
// with GDAL and compared with the source (geometry, field types and values), and the region
// filters compared with OGR's own spatial filter (ogrinfo -spat); `export png` drawing features
// over a quicklook and alone, checked where the PNG's georeferencing (read by GDAL) puts them.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "run_cli.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

const std::string kShared = MAQUETTE_SHARED_DIR;
const std::string kSoho = kShared + "/data/buildings/london_soho_buildings_wgs84.geojson";
const std::string kZion = kShared + "/data/zion/zion.gpkg";

struct Closer {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

Dataset open_vector(const std::string& path) {
  GDALAllRegister();
  Dataset ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  EXPECT_TRUE(ds) << path;
  return ds;
}

// The feature count ogrinfo reports for `path` (with its options, e.g. -spat).
int ogrinfo_count(const std::string& path, const std::string& options = "") {
  const std::string out = shell_output("ogrinfo -ro -al -so " + options + " " + path);
  const size_t at = out.find("Feature Count: ");
  return at == std::string::npos ? -1 : std::stoi(out.substr(at + 15));
}

// The vertices of a geometry, in order (points, lines, polygon rings, collections).
std::vector<std::pair<double, double>> points_of(const OGRGeometry& g) {
  std::vector<std::pair<double, double>> out;
  const OGRwkbGeometryType type = wkbFlatten(g.getGeometryType());
  if (type == wkbPoint) {
    out.emplace_back(g.toPoint()->getX(), g.toPoint()->getY());
  } else if (type == wkbLineString || type == wkbLinearRing) {
    for (const OGRPoint& p : *g.toLineString()) out.emplace_back(p.getX(), p.getY());
  } else if (type == wkbPolygon) {
    for (const OGRLinearRing* ring : *g.toPolygon())
      for (const OGRPoint& p : *ring) out.emplace_back(p.getX(), p.getY());
  } else {
    for (const OGRGeometry* part : *g.toGeometryCollection()) {
      const auto more = points_of(*part);
      out.insert(out.end(), more.begin(), more.end());
    }
  }
  return out;
}

// Every feature of the first layer of `a` and `b` in order: same geometry (within `tolerance`
// degrees, vertex by vertex), same fields (names, types, subtypes) and values.
void expect_same_features(const std::string& a, const std::string& b, double tolerance) {
  const Dataset da = open_vector(a), db = open_vector(b);
  ASSERT_TRUE(da && db);
  OGRLayer& la = *da->GetLayer(0);
  OGRLayer& lb = *db->GetLayer(0);
  ASSERT_EQ(la.GetFeatureCount(), lb.GetFeatureCount());
  OGRFeatureDefn& fa = *la.GetLayerDefn();
  OGRFeatureDefn& fb = *lb.GetLayerDefn();
  ASSERT_EQ(fa.GetFieldCount(), fb.GetFieldCount());
  for (int i = 0; i < fa.GetFieldCount(); ++i) {
    EXPECT_STREQ(fa.GetFieldDefn(i)->GetNameRef(), fb.GetFieldDefn(i)->GetNameRef());
    EXPECT_EQ(fa.GetFieldDefn(i)->GetType(), fb.GetFieldDefn(i)->GetType())
        << fa.GetFieldDefn(i)->GetNameRef();
    EXPECT_EQ(fa.GetFieldDefn(i)->GetSubType(), fb.GetFieldDefn(i)->GetSubType())
        << fa.GetFieldDefn(i)->GetNameRef();
  }
  la.ResetReading();
  lb.ResetReading();
  for (;;) {
    OGRFeatureUniquePtr x(la.GetNextFeature()), y(lb.GetNextFeature());
    if (!x || !y) {
      EXPECT_EQ(bool(x), bool(y));
      break;
    }
    for (int i = 0; i < fa.GetFieldCount(); ++i) {
      const std::string u = x->GetFieldAsString(i), v = y->GetFieldAsString(i);
      if (fa.GetFieldDefn(i)->GetSubType() == OFSTJSON && !u.empty())  // the same JSON value
        EXPECT_EQ(json::parse(u), json::parse(v)) << "fid " << x->GetFID();
      else
        EXPECT_EQ(u, v) << "fid " << x->GetFID() << " field " << fa.GetFieldDefn(i)->GetNameRef();
    }
    const OGRGeometry* gx = x->GetGeometryRef();
    const OGRGeometry* gy = y->GetGeometryRef();
    ASSERT_TRUE(gx && gy);
    EXPECT_EQ(wkbFlatten(gx->getGeometryType()), wkbFlatten(gy->getGeometryType()));
    const auto pa = points_of(*gx), pb = points_of(*gy);
    ASSERT_EQ(pa.size(), pb.size()) << "fid " << x->GetFID();
    EXPECT_GT(pa.size(), 0u);
    double worst = 0;
    for (size_t i = 0; i < pa.size(); ++i)
      worst = std::max(
          {worst, std::abs(pa[i].first - pb[i].first), std::abs(pa[i].second - pb[i].second)});
    EXPECT_LE(worst, tolerance) << "fid " << x->GetFID();
  }
}

std::string ingest(const std::string& source, const std::string& layer) {
  const std::string store = temp_dir() + "/s.mqt";
  const CliResult r =
      run_maquette("-q ingest " + store + " --layer " + layer + " --as features " + source);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return store;
}

TEST(CliFeaturesExport, SohoRoundTripsExactlyThroughGeoJsonAndGpkg) {
  if (!fs::exists(kSoho)) GTEST_SKIP() << "no ../shared/data (" << kSoho << ")";
  const std::string store = ingest(kSoho, "soho");
  for (const char* format : {"geojson", "gpkg"}) {
    const std::string out = temp_dir() + "/soho." + format;
    const CliResult r =
        run_maquette("export " + std::string(format) + " " + store + " --layer soho " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(ogrinfo_count(out), 158);
    expect_same_features(kSoho, out, 0.0);
  }
}

// The park boundary is in UTM 12N: the export holds it in WGS84 as ogr2ogr transforms it.
TEST(CliFeaturesExport, ZionBoundaryComesOutInWgs84) {
  if (!fs::exists(kZion)) GTEST_SKIP() << "no ../shared/data (" << kZion << ")";
  const std::string store = ingest(kZion, "zion");
  const std::string dir = temp_dir();
  ASSERT_EQ(run_maquette("export gpkg " + store + " --layer zion " + dir + "/out.gpkg").exit_code,
            0);
  shell_output("ogr2ogr -t_srs EPSG:4326 " + dir + "/ref.gpkg " + kZion);
  // ogr2ogr keeps EPSG:4326's axis order in the file (lon, lat), as the export does.
  expect_same_features(dir + "/ref.gpkg", dir + "/out.gpkg", 1e-9);
  EXPECT_NE(shell_output("ogrinfo -ro -so -al " + dir + "/out.gpkg").find("ID[\"EPSG\",4326]"),
            std::string::npos);
}

// Every OGR field type a GeoPackage holds, and null values, come back with their types.
TEST(CliFeaturesExport, FieldTypesAndNullsRoundTrip) {
  const std::string dir = temp_dir(), source = dir + "/typed.gpkg";
  {
    GDALAllRegister();
    Dataset ds(GetGDALDriverManager()->GetDriverByName("GPKG")->Create(source.c_str(), 0, 0, 0,
                                                                       GDT_Unknown, nullptr));
    OGRSpatialReference wgs84;
    wgs84.importFromEPSG(4326);
    OGRLayer* l = ds->CreateLayer("typed", &wgs84, wkbPoint, nullptr);
    const std::vector<std::pair<const char*, std::pair<OGRFieldType, OGRFieldSubType>>> fields = {
        {"i", {OFTInteger, OFSTNone}},    {"i64", {OFTInteger64, OFSTNone}},
        {"r", {OFTReal, OFSTNone}},       {"s", {OFTString, OFSTNone}},
        {"b", {OFTInteger, OFSTBoolean}}, {"d", {OFTDate, OFSTNone}},
        {"dt", {OFTDateTime, OFSTNone}},  {"j", {OFTString, OFSTJSON}},
        {"bin", {OFTBinary, OFSTNone}}};
    for (const auto& [name, type] : fields) {
      OGRFieldDefn f(name, type.first);
      f.SetSubType(type.second);
      ASSERT_EQ(l->CreateField(&f), OGRERR_NONE);
    }
    for (int k = 0; k < 2; ++k) {
      OGRFeature f(l->GetLayerDefn());
      OGRPoint p(-0.1 + 0.001 * k, 51.5);
      f.SetGeometry(&p);
      if (k == 0) {
        f.SetField("i", 7);
        f.SetField("i64", GIntBig(1) << 40);
        f.SetField("r", 2.5);
        f.SetField("s", "Grüße, \"quoted\"");
        f.SetField("b", 1);
        f.SetField("d", "2024-05-01");
        f.SetField("dt", "2024-05-01T12:30:15.250Z");
        f.SetField("j", "{\"a\": [1, 2]}");
        f.SetField("bin", "00ff7f");
      }  // k == 1: every field null
      ASSERT_EQ(l->CreateFeature(&f), OGRERR_NONE);
    }
  }
  const std::string store = ingest(source, "typed");
  ASSERT_EQ(run_maquette("export gpkg " + store + " --layer typed " + dir + "/out.gpkg").exit_code,
            0);
  expect_same_features(source, dir + "/out.gpkg", 0.0);
}

// --bbox keeps the features whose geometry meets the box, as OGR's spatial filter does; --cells
// the features indexed in the cells; a region without features is an error naming the layer.
TEST(CliFeaturesExport, RegionsSelectAsOgrDoes) {
  if (!fs::exists(kSoho)) GTEST_SKIP() << "no ../shared/data (" << kSoho << ")";
  const std::string store = ingest(kSoho, "soho");
  const std::string dir = temp_dir();
  const std::string box = "-0.1360 51.5120 -0.1330 51.5140";
  CliResult r = run_maquette("export geojson " + store + " --layer soho " + dir +
                             "/box.geojson --bbox " + box);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const int want = ogrinfo_count(kSoho, "-spat " + box);
  ASSERT_GT(want, 0);
  ASSERT_LT(want, 158);
  EXPECT_EQ(ogrinfo_count(dir + "/box.geojson"), want);

  // One building's cell, found from its centroid: it is among the features of that cell.
  const std::string cell = run_maquette("cells from-point -0.1345 51.5130 --level 14").out;
  r = run_maquette("export geojson " + store + " --layer soho " + dir + "/cell.geojson --cells " +
                   cell.substr(0, cell.find('\n')));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const int in_cell = ogrinfo_count(dir + "/cell.geojson");
  EXPECT_GT(in_cell, 0);
  EXPECT_LE(in_cell, 158);

  r = run_maquette("export gpkg " + store + " --layer soho " + dir +
                   "/none.gpkg --bbox 10 10 10.1 10.1");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("layer 'soho' in " + store + " has no features in the region"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir + "/none.gpkg"));
}

// A raster layer is not features; a pipeline's export step writes features too.
TEST(CliFeaturesExport, PipelineStepAndBadLayer) {
  if (!fs::exists(kZion)) GTEST_SKIP() << "no ../shared/data (" << kZion << ")";
  const std::string dir = temp_dir();
  std::ofstream(dir + "/p.json") << json{
      {"store", "p.mqt"},
      {"region", {{"bbox", {-113.3, 37.1, -112.8, 37.6}}}},
      {"level", 9},
      {"tile_size", 256},
      {"steps",
       {{{"op", "ingest"},
         {"outputs", {{"layer", "zion"}}},
         {"params", {{"sources", {kZion}}, {"as", "features"}}}},
        {{"op", "ingest"},
         {"outputs", {{"layer", "dem"}}},
         {"params", {{"sources", {kShared + "/data/zion/srtm.tif"}}, {"as", "dem"}}}},
        {{"op", "export"},
         {"params", {{"format", "geojson"}, {"layer", "zion"}, {"out", "out/zion.geojson"}}}}}}};
  CliResult r = run_maquette("run " + dir + "/p.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(ogrinfo_count(dir + "/out/zion.geojson"), 1);
  r = run_maquette("export geojson " + dir + "/p.mqt --layer dem " + dir + "/dem.geojson");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("not a features layer"), std::string::npos) << r.err;
}

// The pixels of a PNG quicklook, and where they lie: the geotransform GDAL reads from its
// georeferencing (.aux.xml / .pgw) beside it.
struct Picture {
  cv::Mat rgba;
  std::array<double, 6> gt{};
  // Whether the overlay's magenta core is within `radius` pixels of the point.
  bool drawn_near(double lon, double lat, int radius) const {
    const int c = int((lon - gt[0]) / gt[1]), r = int((lat - gt[3]) / gt[5]);
    for (int y = std::max(0, r - radius); y <= std::min(rgba.rows - 1, r + radius); ++y)
      for (int x = std::max(0, c - radius); x <= std::min(rgba.cols - 1, c + radius); ++x) {
        const cv::Vec4b p = rgba.at<cv::Vec4b>(y, x);  // B G R A
        if (p[2] > 230 && p[1] < 60 && p[0] > 170) return true;
      }
    return false;
  }
};

Picture read_picture(const std::string& png) {
  Picture p;
  GDALAllRegister();
  p.rgba = cv::imread(png, cv::IMREAD_UNCHANGED);
  EXPECT_EQ(p.rgba.type(), CV_8UC4) << png;
  const Dataset ds(GDALDataset::Open(png.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  EXPECT_TRUE(ds && ds->GetGeoTransform(p.gt.data()) == CE_None) << png << " not georeferenced";
  return p;
}

// The park boundary's vertices in lon/lat, as ogr2ogr transforms them.
std::vector<std::pair<double, double>> zion_vertices(const std::string& dir) {
  shell_output("ogr2ogr -t_srs EPSG:4326 " + dir + "/ref.gpkg " + kZion);
  const Dataset ds = open_vector(dir + "/ref.gpkg");
  OGRFeatureUniquePtr f(ds->GetLayer(0)->GetNextFeature());
  return points_of(*f->GetGeometryRef());
}

// --overlay draws the Zion boundary over the DEM quicklook: magenta at every vertex of the
// boundary (placed by the PNG's own georeferencing), and every changed pixel near the boundary.
TEST(CliFeaturesExport, OverlayDrawsTheBoundaryWhereItLies) {
  if (!fs::exists(kZion)) GTEST_SKIP() << "no ../shared/data (" << kZion << ")";
  const std::string dir = temp_dir(), store = ingest(kZion, "zion");
  ASSERT_EQ(run_maquette("-q ingest " + store + " --layer dem --as dem " + kShared +
                         "/data/zion/srtm.tif")
                .exit_code,
            0);
  CliResult r = run_maquette("export png " + store + " --layer dem " + dir + "/plain.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_maquette("export png " + store + " --layer dem --overlay zion " + dir + "/over.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Picture plain = read_picture(dir + "/plain.png"), over = read_picture(dir + "/over.png");
  ASSERT_EQ(plain.rgba.size(), over.rgba.size());
  const auto vertices = zion_vertices(dir);
  ASSERT_GT(vertices.size(), 100u);
  size_t drawn = 0;
  for (const auto& [lon, lat] : vertices) drawn += over.drawn_near(lon, lat, 1);
  EXPECT_EQ(drawn, vertices.size());
  size_t plain_magenta = 0;
  for (const auto& [lon, lat] : vertices) plain_magenta += plain.drawn_near(lon, lat, 1);
  EXPECT_EQ(plain_magenta, 0u) << "the overlay's colour must stand out from the quicklook";
  // Changed pixels lie within a few pixels of the boundary's segments.
  size_t changed = 0, far = 0;
  for (int y = 0; y < over.rgba.rows; ++y)
    for (int x = 0; x < over.rgba.cols; ++x) {
      if (over.rgba.at<cv::Vec4b>(y, x) == plain.rgba.at<cv::Vec4b>(y, x)) continue;
      ++changed;
      const double lon = over.gt[0] + (x + 0.5) * over.gt[1];
      const double lat = over.gt[3] + (y + 0.5) * over.gt[5];
      double nearest = 1e9;  // pixels to the closest segment of the boundary
      for (size_t i = 0; i + 1 < vertices.size(); ++i) {
        const double ax = (vertices[i].first - lon) / over.gt[1];
        const double ay = (vertices[i].second - lat) / over.gt[5];
        const double dx = (vertices[i + 1].first - vertices[i].first) / over.gt[1];
        const double dy = (vertices[i + 1].second - vertices[i].second) / over.gt[5];
        const double len2 = dx * dx + dy * dy;
        const double t = len2 > 0 ? std::clamp(-(ax * dx + ay * dy) / len2, 0.0, 1.0) : 0.0;
        nearest = std::min(nearest, std::hypot(ax + t * dx, ay + t * dy));
      }
      far += nearest > 5;  // the casing is 2.2 px wide on either side
    }
  EXPECT_GT(changed, vertices.size());
  EXPECT_EQ(far, 0u);
}

// A features layer alone: its features on a plain background, framed around them.
TEST(CliFeaturesExport, FeaturesLayerAloneIsDrawnOnAPlainBackground) {
  if (!fs::exists(kZion)) GTEST_SKIP() << "no ../shared/data (" << kZion << ")";
  const std::string dir = temp_dir(), store = ingest(kZion, "zion");
  const CliResult r = run_maquette("export png " + store + " --layer zion " + dir + "/zion.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Picture p = read_picture(dir + "/zion.png");
  EXPECT_EQ(std::max(p.rgba.cols, p.rgba.rows) <= 2048, true);
  EXPECT_GT(std::max(p.rgba.cols, p.rgba.rows), 500);
  for (const auto& [lon, lat] : zion_vertices(dir)) EXPECT_TRUE(p.drawn_near(lon, lat, 1));
  const cv::Vec4b corner = p.rgba.at<cv::Vec4b>(0, 0);
  EXPECT_EQ(corner, cv::Vec4b(230, 236, 236, 255));  // opaque light grey (B G R A)
  const CliResult bad =
      run_maquette("export png " + store + " --layer zion --overlay zion " + dir + "/x.png");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("--overlay draws features over a raster layer"), std::string::npos)
      << bad.err;
}

}  // namespace
}  // namespace maquette::test
