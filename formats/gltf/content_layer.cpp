#include "gltf/content_layer.h"

#include <algorithm>

#include "core/error.h"

namespace maquette {
namespace {

using nlohmann::json;

const char* kind_name(ContentTile::Kind k) {
  return k == ContentTile::Kind::Mesh ? "mesh" : "instances";
}

void check(const ContentTile& c) {
  if (c.kind == ContentTile::Kind::Mesh) {
    const size_t n = c.positions.size() / 3;
    if (c.positions.size() % 3 || c.indices.size() % 3 ||
        std::ranges::any_of(c.indices, [n](uint32_t i) { return i >= n; }))
      throw Error("content mesh: 3 values per vertex, 3 indices in range per triangle");
  } else if (c.prototype != "cone" && c.prototype != "box") {
    throw Error("content instances: unknown prototype '" + c.prototype + "' (cone or box)");
  }
}

}  // namespace

std::string content_artifact_name(const std::string& layer, CellId cell) {
  return "content/" + layer + "/" + cell.ToText();
}

void put_content(Store::Batch& batch, const std::string& layer, CellId cell, const ContentTile& c) {
  check(c);
  json j = {{"kind", kind_name(c.kind)}, {"color", c.color}};
  if (c.kind == ContentTile::Kind::Mesh) {
    j["positions"] = c.positions;
    j["indices"] = c.indices;
  } else {
    j["prototype"] = c.prototype;
    j["instances"] = json::array();
    for (const ContentInstance& i : c.instances)
      j["instances"].push_back({i.lon, i.lat, i.height, i.scale, i.heading});
  }
  const std::string text = j.dump();
  batch.put_artifact(Artifact::FromText(content_artifact_name(layer, cell), text,
                                        {{"layer", layer}, {"cell", cell.ToText()}}));
}

std::optional<ContentTile> get_content(const Store& store, const std::string& layer, CellId cell) {
  const auto a = store.get_artifact(content_artifact_name(layer, cell));
  if (!a) return std::nullopt;
  const json j = json::parse(a->text());
  ContentTile c;
  c.kind = j.at("kind") == "mesh" ? ContentTile::Kind::Mesh : ContentTile::Kind::Instances;
  c.color = j.at("color").get<std::array<double, 3>>();
  if (c.kind == ContentTile::Kind::Mesh) {
    c.positions = j.at("positions").get<std::vector<double>>();
    c.indices = j.at("indices").get<std::vector<uint32_t>>();
  } else {
    c.prototype = j.at("prototype").get<std::string>();
    for (const auto& i : j.at("instances")) c.instances.push_back({i[0], i[1], i[2], i[3], i[4]});
  }
  check(c);
  return c;
}

void require_content_layer(const Store& store, const std::string& layer) {
  const std::string prefix = "content/" + layer + "/";
  for (const std::string& name : store.artifact_names())
    if (name.starts_with(prefix)) return;
  throw Error("no content layer '" + layer + "' in " + store.path() +
              " (expected artifacts content/" + layer + "/<CELL>)");
}

}  // namespace maquette
