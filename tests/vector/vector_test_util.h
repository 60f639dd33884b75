// Helpers for the vector tests: stores, files written with OGR, expected errors.
#pragma once

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "../store/store_test_util.h"
#include "core/error.h"
#include "store/store.h"

namespace maquette::test {

inline std::unique_ptr<Store> new_store(const TempDir& dir, const std::string& name = "s.mqt") {
  return Store::open(dir.file(name), Store::Mode::Create);
}

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Runs f, expects a maquette::Error whose message contains every one of `parts`.
template <typename F>
void expect_error(F&& f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no error thrown";
  } catch (const Error& e) {
    for (const std::string& p : parts)
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos)
          << "'" << p << "' not in: " << e.what();
  }
}

// A vector file written with OGR: one layer of features given as WKT plus an integer field
// "n" and a text field "label", in the CRS `epsg` (0: none).
struct WktFeature {
  std::string wkt;
  int n = 0;
  std::string label;
};

inline void write_vector(const std::string& path, const std::string& driver, int epsg,
                         const std::vector<WktFeature>& features) {
  GDALAllRegister();
  GDALDriver* d = GetGDALDriverManager()->GetDriverByName(driver.c_str());
  ASSERT_NE(d, nullptr) << driver;
  std::unique_ptr<GDALDataset> ds(d->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
  ASSERT_NE(ds, nullptr) << path;
  OGRSpatialReference srs;
  if (epsg) srs.importFromEPSG(epsg);
  OGRLayer* layer = ds->CreateLayer("things", epsg ? &srs : nullptr, wkbUnknown, nullptr);
  ASSERT_NE(layer, nullptr);
  OGRFieldDefn n("n", OFTInteger), label("label", OFTString);
  layer->CreateField(&n);
  layer->CreateField(&label);
  for (const WktFeature& w : features) {
    OGRFeatureUniquePtr f(OGRFeature::CreateFeature(layer->GetLayerDefn()));
    OGRGeometry* g = nullptr;
    ASSERT_EQ(OGRGeometryFactory::createFromWkt(w.wkt.c_str(), nullptr, &g), OGRERR_NONE) << w.wkt;
    f->SetGeometryDirectly(g);
    f->SetField("n", w.n);
    f->SetField("label", w.label.c_str());
    ASSERT_EQ(layer->CreateFeature(f.get()), OGRERR_NONE);
  }
}

}  // namespace maquette::test
