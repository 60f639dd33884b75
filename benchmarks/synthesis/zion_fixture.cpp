#include "zion_fixture.h"

#include <gdal_priv.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "runtime/params_schema.h"
#include "transfer_params.h"

namespace maquette::synthesis::bench {
namespace {

const std::string kData = MAQUETTE_SHARED_DIR "/data";
// The window's origin in nlcd.tif (1073 x 1359 pixels): the canyon and the plateau around it.
constexpr int kOriginCol = 20, kOriginRow = 160;

}  // namespace

nlohmann::json zion_classes() {
  return {{"1", 7}, {"2", 3}, {"3", 5}, {"4", {6, 1}}, {"5", 7}, {"6", 2}, {"7", 2}, {"8", {6, 1}}};
}

nlohmann::json zion_params(const nlohmann::json& classes, const nlohmann::json& painting_classes) {
  nlohmann::json params = {{"painting", kData + "/painting/bruegel_the_harvesters_1565.png"},
                           {"classes", 8},
                           {"exclude_classes", {0}},
                           {"landcover_classes", classes},
                           {"exemplar_scale", 2},
                           {"k", 2}};
  if (painting_classes.contains("labels")) {
    params.erase("classes");
    params["labels"] = painting_classes.at("labels");
    params["exclude_classes"] = painting_classes.value("exclude_classes", nlohmann::json::array());
  }
  for (const char* key : {"exemplars", "harmonize"})
    if (painting_classes.contains(key)) params[key] = painting_classes.at(key);
  return params;
}

nlohmann::json zion_weights(const nlohmann::json& weights, const std::string& program) {
  nlohmann::json properties = synthesis_params_schema();
  properties["landcover_classes"] = exemplar_params_schema().at("landcover_classes");
  properties["landcover_classes"]["default"] = zion_classes();
  for (const char* key : {"labels", "exclude_classes"})
    properties[key] = exemplar_params_schema().at(key);
  properties["exclude_classes"].erase("default");
  properties.update(further_exemplars_schema());
  const nlohmann::json schema = {
      {"type", "object"}, {"properties", properties}, {"additionalProperties", false}};
  return validate_params(schema, weights, program);
}

nlohmann::json example_weights(const std::string& example) {
  const std::filesystem::path source = MAQUETTE_SOURCE_DIR;
  const std::filesystem::path path = source / "examples" / example;
  std::ifstream in(path);
  if (!in) throw Error(path.string() + ": cannot read it");
  const nlohmann::json pipeline = nlohmann::json::parse(in);
  const nlohmann::json names = synthesis_params_schema();
  nlohmann::json weights = nlohmann::json::object();
  for (const nlohmann::json& step : pipeline.at("steps")) {
    if (step.at("op") != "synthesis.transfer") continue;
    for (const auto& [key, value] : step.at("params").items())
      if (names.contains(key) || key == "exemplars" || key == "harmonize") weights[key] = value;
  }
  if (weights.contains("exemplars"))
    for (nlohmann::json& exemplar : weights["exemplars"]) {
      exemplar.erase("painting_altitude");
      for (const char* key : {"painting", "labels"})
        if (exemplar.contains(key))
          exemplar[key] = (source / exemplar.at(key).get<std::string>()).string();
    }
  return weights;
}

nlohmann::json painting_classes(const nlohmann::json& weights) {
  nlohmann::json classes = nlohmann::json::object();
  for (const char* key : {"labels", "exclude_classes", "exemplars"})
    if (weights.contains(key)) classes[key] = weights.at(key);
  if (weights.contains("exemplars")) classes["harmonize"] = weights.at("harmonize");
  return classes;
}

std::shared_ptr<const TransferExemplar> zion_exemplar(const nlohmann::json& classes,
                                                      const nlohmann::json& painting_classes) {
  return transfer_exemplar(zion_params(classes, painting_classes));
}

std::vector<uint8_t> zion_labels(const PixelRect& window, const nlohmann::json& classes) {
  struct Raster {
    int width = 0, height = 0;
    std::vector<uint8_t> classes;
  };
  static const Raster raster = [] {
    GDALAllRegister();
    const std::string path = kData + "/zion/nlcd.tif";
    std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
    if (!ds) throw Error(path + ": GDAL cannot open it");
    Raster r{ds->GetRasterXSize(), ds->GetRasterYSize(), {}};
    r.classes.resize(size_t(r.width) * size_t(r.height));
    if (ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, r.width, r.height, r.classes.data(), r.width,
                                       r.height, GDT_Byte, 0, 0, nullptr) != CE_None)
      throw Error(path + ": cannot read band 1");
    return r;
  }();
  const auto table = class_table(classes, "zion fixture");
  std::vector<uint8_t> out(size_t(window.width) * size_t(window.height), kUnknownLabel);
  for (int64_t r = 0; r < window.height; ++r)
    for (int64_t c = 0; c < window.width; ++c) {
      const int64_t x = kOriginCol + window.col0 + c, y = kOriginRow + window.row0 + r;
      if (x < 0 || y < 0 || x >= raster.width || y >= raster.height) continue;
      const uint8_t v = raster.classes[size_t(y) * size_t(raster.width) + size_t(x)];
      out[size_t(r) * size_t(window.width) + size_t(c)] =
          v == 255 ? kUnknownLabel : painting_class(table, float(v));
    }
  return out;
}

std::vector<int32_t> synthesize_tiles(const TransferExemplar& t, const PixelRect& out, int tile,
                                      int threads, const SynthesisParams& params,
                                      const nlohmann::json& classes) {
  std::vector<int32_t> result(size_t(out.width) * size_t(out.height));
  const int64_t across = (out.width + tile - 1) / tile, down = (out.height + tile - 1) / tile;
  const int halo = synthesis_halo();
  tbb::task_arena(threads).execute([&] {
    tbb::parallel_for(int64_t(0), across * down, [&](int64_t i) {
      const PixelRect part{out.col0 + i % across * tile, out.row0 + i / across * tile,
                           std::min<int64_t>(tile, out.width - i % across * tile),
                           std::min<int64_t>(tile, out.height - i / across * tile)};
      TargetGuides g;
      g.rect = {part.col0 - halo, part.row0 - halo, part.width + 2 * halo, part.height + 2 * halo};
      g.labels = zion_labels(g.rect, classes);
      const std::vector<int32_t> src = synthesize(t.pyramid, g, params, part);
      for (int64_t r = 0; r < part.height; ++r)
        std::copy_n(
            src.begin() + r * part.width, part.width,
            result.begin() + (part.row0 - out.row0 + r) * out.width + (part.col0 - out.col0));
    });
  });
  return result;
}

std::vector<float> source_colours(const Exemplar& e, const std::vector<int32_t>& source) {
  std::vector<float> rgb(source.size() * 3);
  for (size_t p = 0; p < source.size(); ++p)
    std::copy_n(e.rgb.begin() + 3 * std::ptrdiff_t(source[p]), 3,
                rgb.begin() + 3 * std::ptrdiff_t(p));
  return rgb;
}

AssessedImage assessed(const PixelRect& out, std::vector<int32_t> source, std::vector<float> rgb,
                       const nlohmann::json& classes) {
  AssessedImage a;
  a.rect = out;
  a.source = std::move(source);
  a.rgb = std::move(rgb);
  a.labels = zion_labels(out, classes);
  return a;
}

}  // namespace maquette::synthesis::bench
