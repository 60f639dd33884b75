// maquette info STORE: layers, levels, tile counts, bounding box, size on disk.
#include <algorithm>
#include <array>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/commands.h"
#include "core/grid.h"
#include "core/lonlat_bounds.h"
#include "store/store.h"

namespace maquette::cli {
namespace {

using json = nlohmann::json;

// W S E N of the layer's cells; W > E when they cross the antimeridian.
json cells_bbox(const std::vector<CellId>& cells) {
  if (cells.empty()) return nullptr;
  const LonLatBounds b = lonlat_bounds(default_grid(), cells);
  return json::array({b.west, b.south, b.east > 180.0 ? b.east - 360.0 : b.east, b.north});
}

// W S E N of a features layer: the union of its features' boxes.
json features_bbox(const Store& store, const std::string& layer) {
  const auto features = store.features_in(layer, CellId::FromFace(0).range_min(),
                                          CellId::FromFace(CellId::kNumFaces - 1).range_max());
  if (features.empty()) return nullptr;
  std::array<double, 4> b = features.front().bbox;
  for (const Feature& f : features) {
    b[0] = std::min(b[0], f.bbox[0]);
    b[1] = std::min(b[1], f.bbox[1]);
    b[2] = std::max(b[2], f.bbox[2]);
    b[3] = std::max(b[3], f.bbox[3]);
  }
  return json::array({b[0], b[1], b[2], b[3]});
}

json layer_json(const Store& store, const LayerInfo& l) {
  const LayerStats st = store.stats(l.name);
  json j = {{"name", l.name},
            {"kind", layer_kind_name(l.kind)},
            {"dtype", dtype_name(l.dtype)},
            {"channels", l.channels},
            {"tile_size", l.tile_size},
            {"level", l.level},
            {"levels", st.levels},
            {"tiles", st.tile_count},
            {"features", st.feature_count},
            {"bytes", st.bytes},
            {"semantics", semantics_name(l.semantics)},
            {"units", l.units},
            {"codec", l.codec},
            {"nodata", l.nodata ? json(*l.nodata) : json(nullptr)},
            {"bbox", l.kind == LayerKind::Features ? features_bbox(store, l.name)
                                                   : cells_bbox(store.tile_cells(l.name))},
            {"provenance", l.provenance}};
  if (l.level >= 0 && l.tile_size > 0)
    j["pixel_m"] = default_grid().level_info(l.level, l.tile_size).pixel_m;
  return j;
}

void print_info(const std::string& path, bool as_json) {
  const auto store = Store::open(path, Store::Mode::ReadOnly);
  json layers = json::array();
  for (const LayerInfo& l : store->layers()) layers.push_back(layer_json(*store, l));
  const json report = {{"store", path},
                       {"size_bytes", store->file_size()},
                       {"layers", layers},
                       {"artifacts", store->artifact_names()}};
  if (as_json) {
    std::cout << report.dump(2) << "\n";
    return;
  }
  std::printf("store     %s (%.1f MiB on disk)\n", path.c_str(),
              double(store->file_size()) / 1048576.0);
  std::printf("layers    %zu\n", layers.size());
  for (const json& l : layers) {
    std::printf("\n  %s: %s %s x%d, %d px tiles at level %d (%.3f m/px), %s%s%s\n",
                l["name"].get<std::string>().c_str(), l["kind"].get<std::string>().c_str(),
                l["dtype"].get<std::string>().c_str(), l["channels"].get<int>(),
                l["tile_size"].get<int>(), l["level"].get<int>(), l.value("pixel_m", 0.0),
                l["semantics"].get<std::string>().c_str(),
                l["units"].get<std::string>().empty() ? "" : ", units ",
                l["units"].get<std::string>().c_str());
    if (l["kind"] == "features")
      std::printf("    features %lld indexed in %lld cells (%.1f MiB)\n",
                  l["features"].get<long long>(), l["tiles"].get<long long>(),
                  l["bytes"].get<double>() / 1048576.0);
    else
      std::printf("    tiles  %lld (%.1f MiB compressed), levels %s\n", l["tiles"].get<long long>(),
                  l["bytes"].get<double>() / 1048576.0, l["levels"].dump().c_str());
    std::printf("    bbox   %s (W S E N)\n", l["bbox"].dump().c_str());
  }
  if (!report["artifacts"].empty())
    std::printf("\nartifacts %s\n", report["artifacts"].dump().c_str());
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto as_json = std::make_shared<bool>(false);
  CLI::App* info = app.add_subcommand(
      "info", "Describe a store: layers, levels, tile counts, bounding box, size");
  info->add_option("STORE", *path, "Store file")->required();
  info->add_flag("--json", *as_json, "Print JSON");
  info->callback([path, as_json] { print_info(*path, *as_json); });
}

}  // namespace maquette::cli
