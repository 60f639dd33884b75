// maquette info STORE: layers, levels, tile counts, bounding box, size on disk; for content layers
// (mesh, instances, volume) the cells, objects, triangles, instances and voxels their blobs'
// headers count; for models the objects, triangles and materials.
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <span>
#include <string>

#include "cli/commands.h"
#include "core/grid.h"
#include "core/lonlat_bounds.h"
#include "gdal/vertical_datum.h"
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

// The name of a WKB geometry type (ISO codes: 1..7, +1000 Z, +2000 M, +3000 ZM).
std::string wkb_type_name(std::span<const std::byte> wkb) {
  static constexpr const char* kNames[] = {
      "Geometry",   "Point",           "LineString",   "Polygon",
      "MultiPoint", "MultiLineString", "MultiPolygon", "GeometryCollection"};
  if (wkb.size() < 5) return "invalid";
  uint32_t type = 0;
  std::memcpy(&type, wkb.data() + 1, 4);
  if (wkb[0] == std::byte{0}) type = __builtin_bswap32(type);  // big endian
  const uint32_t base = type % 1000, dims = type / 1000;
  if (base > 7 || dims > 3) return "type " + std::to_string(type);
  return std::string(kNames[base]) + (dims == 1 ? " Z" : dims == 2 ? " M" : dims == 3 ? " ZM" : "");
}

// A features layer: the union of its features' boxes (W S E N), the count of each geometry type
// and the attribute names.
void describe_features(const Store& store, const std::string& layer, json& j) {
  const auto features = store.features_in(layer, CellId::FromFace(0).range_min(),
                                          CellId::FromFace(CellId::kNumFaces - 1).range_max());
  std::map<std::string, int64_t> types;
  std::set<std::string> attributes;
  for (const Feature& f : features) {
    ++types[wkb_type_name(f.wkb)];
    for (const auto& [key, _] : f.attributes.items()) attributes.insert(key);
  }
  j["geometry_types"] = types;
  j["attributes"] = attributes;
  j["bbox"] = nullptr;
  if (features.empty()) return;
  std::array<double, 4> b = features.front().bbox;
  for (const Feature& f : features) {
    b[0] = std::min(b[0], f.bbox[0]);
    b[1] = std::min(b[1], f.bbox[1]);
    b[2] = std::max(b[2], f.bbox[2]);
    b[3] = std::max(b[3], f.bbox[3]);
  }
  j["bbox"] = json::array({b[0], b[1], b[2], b[3]});
}

// A content layer: what its blobs' headers count at the layer's level (Store::content_stats).
void describe_content(const Store& store, const LayerInfo& l, json& j) {
  const ContentLayerStats st = store.content_stats(l.name);
  j["cells"] = st.cells;
  j["objects"] = st.content.objects;
  j["triangles"] = st.content.triangles;
  j["instances"] = l.kind == LayerKind::Instances ? st.content.objects : 0;
  j["voxels"] = st.content.voxels;
  j["bbox"] = cells_bbox(store.content_cells(l.name));
}

// A model layer: its one blob's objects, triangles and materials (Store::model_stats).
void describe_model(const Store& store, const LayerInfo& l, json& j) {
  const ModelStats st = store.model_stats(l.name);
  j["objects"] = st.content.objects;
  j["triangles"] = st.content.triangles;
  j["materials"] = st.materials;
  j["bytes"] = st.bytes;
  j["bbox"] = nullptr;  // in its own frame: placed by the instances that use it
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
            {"provenance", l.provenance}};
  const auto why = store.incomplete(l.name);
  j["incomplete"] = why ? json(*why) : json(nullptr);
  const bool content = layer_content_kind(l.kind).has_value() || l.kind == LayerKind::Model;
  if (l.kind == LayerKind::Features)
    describe_features(store, l.name, j);
  else if (l.kind == LayerKind::Model)
    describe_model(store, l, j);
  else if (content)
    describe_content(store, l, j);
  else
    j["bbox"] = cells_bbox(store.tile_cells(l.name));
  if (const auto datum = layer_vertical_datum(l)) j["vertical_datum"] = datum->describe();
  if (!content && l.level >= 0 && l.tile_size > 0)
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
    if (l["kind"] == "features") {
      std::string types;
      for (const auto& [type, count] : l["geometry_types"].items())
        types += (types.empty() ? "" : ", ") + type + " " + count.dump();
      std::printf("\n  %s: features indexed in cells at level %d\n",
                  l["name"].get<std::string>().c_str(), l["level"].get<int>());
      std::printf("    features %lld (%s) in %lld cells (%.1f MiB)\n",
                  l["features"].get<long long>(), types.c_str(), l["tiles"].get<long long>(),
                  l["bytes"].get<double>() / 1048576.0);
      std::string attributes;
      for (const json& a : l["attributes"])
        attributes += (attributes.empty() ? "" : ", ") + a.get<std::string>();
      std::printf("    attributes %s\n", attributes.empty() ? "none" : attributes.c_str());
    } else if (l["kind"] == "model") {
      std::printf("\n  %s: model (own frame: metres, z up, base at z = 0)\n",
                  l["name"].get<std::string>().c_str());
      std::printf("    objects %llu, triangles %llu, materials %lld (%.1f kB)\n",
                  l["objects"].get<unsigned long long>(), l["triangles"].get<unsigned long long>(),
                  l["materials"].get<long long>(), l["bytes"].get<double>() / 1024.0);
      if (l["provenance"].contains("source"))
        std::printf("    source %s\n", l["provenance"]["source"].dump().c_str());
    } else if (l.contains("objects")) {
      std::printf("\n  %s: %s content in cells at level %d\n", l["name"].get<std::string>().c_str(),
                  l["kind"].get<std::string>().c_str(), l["level"].get<int>());
      std::printf(
          "    cells  %lld, objects %llu, triangles %llu, instances %llu, voxels %llu "
          "(%.1f MiB), levels %s\n",
          l["cells"].get<long long>(), l["objects"].get<unsigned long long>(),
          l["triangles"].get<unsigned long long>(), l["instances"].get<unsigned long long>(),
          l["voxels"].get<unsigned long long>(), l["bytes"].get<double>() / 1048576.0,
          l["levels"].dump().c_str());
    } else {
      std::printf("\n  %s: %s %s x%d, %d px tiles at level %d (%.3f m/px), %s%s%s\n",
                  l["name"].get<std::string>().c_str(), l["kind"].get<std::string>().c_str(),
                  l["dtype"].get<std::string>().c_str(), l["channels"].get<int>(),
                  l["tile_size"].get<int>(), l["level"].get<int>(), l.value("pixel_m", 0.0),
                  l["semantics"].get<std::string>().c_str(),
                  l["units"].get<std::string>().empty() ? "" : ", units ",
                  l["units"].get<std::string>().c_str());
      std::printf("    tiles  %lld (%.1f MiB compressed), levels %s\n", l["tiles"].get<long long>(),
                  l["bytes"].get<double>() / 1048576.0, l["levels"].dump().c_str());
    }
    if (l["kind"] != "model") std::printf("    bbox   %s (W S E N)\n", l["bbox"].dump().c_str());
    if (!l["incomplete"].is_null())
      std::printf("    INCOMPLETE: %s; readers refuse it until it is finished (--resume)\n",
                  l["incomplete"].get<std::string>().c_str());
    if (l.contains("vertical_datum"))
      std::printf("    heights above %s\n", l["vertical_datum"].get<std::string>().c_str());
  }
  if (!report["artifacts"].empty())
    std::printf("\nartifacts %s\n", report["artifacts"].dump().c_str());
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto as_json = std::make_shared<bool>(false);
  CLI::App* info = app.add_subcommand(
      "info", "Describe a store: layers, levels, tile and content counts, bounding box, size");
  info->add_option("STORE", *path, "Store file")->required();
  info->add_flag("--json", *as_json, "Print JSON");
  info->callback([path, as_json] { print_info(*path, *as_json); });
}

}  // namespace maquette::cli
