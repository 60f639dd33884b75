// Batches passed between processes (Batch::serialize, add_serialized): CBOR of the pending
// writes, blobs as CBOR byte strings, layers by name.
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "store/batch_pending.h"

namespace maquette {
namespace {

using nlohmann::json;

json bytes(std::span<const std::byte> blob) {
  const auto* p = reinterpret_cast<const uint8_t*>(blob.data());
  return json::binary(std::vector<uint8_t>(p, p + blob.size()));
}

json bytes(std::string_view blob) { return bytes(std::as_bytes(std::span(blob))); }

std::vector<std::byte> blob_of(const json& j) {
  const auto& b = j.get_binary();
  const auto* p = reinterpret_cast<const std::byte*>(b.data());
  return {p, p + b.size()};
}

std::string text_of(const json& j) {
  const auto& b = j.get_binary();
  return {reinterpret_cast<const char*>(b.data()), b.size()};
}

}  // namespace

std::string Store::Batch::serialize() const {
  const Impl& d = *store_.impl_;
  if (!open_) throw Error("cannot serialize a batch on " + d.path + ": already committed");
  const Pending& p = *pending_;
  if (!p.features.empty() || !p.models.empty())
    throw Error("a batch of features or models on " + d.path + " cannot be serialized");
  // Every layer id in the batch came from require(), which cached its entry.
  std::map<int64_t, std::string> names;
  {
    std::lock_guard lock(d.layers_mutex);
    for (const auto& [name, entry] : d.layers) names[entry.id] = name;
  }
  const auto tile = [&](const Pending::TileWrite& t) {
    return json::array({names.at(t.layer), t.cell.id(), bytes(t.blob)});
  };
  json j = {{"tiles", json::array()},    {"overviews", json::array()}, {"partial", json::array()},
            {"contents", json::array()}, {"artifacts", json::array()}, {"done", json::array()}};
  for (const auto& t : p.tiles) j["tiles"].push_back(tile(t));
  for (const auto& o : p.overviews) j["overviews"].push_back(tile(o));
  for (const auto& [o, children] : p.partial_overviews)
    j["partial"].push_back(json::array({tile(o), children}));
  for (const auto& c : p.contents)
    j["contents"].push_back(
        json::array({names.at(c.layer), c.cell.id(), c.blob ? bytes(*c.blob) : json(nullptr)}));
  for (const auto& a : p.artifacts)
    j["artifacts"].push_back(json::array({a.name, a.media_type, bytes(a.data), a.metadata}));
  for (const auto& x : p.done) j["done"].push_back(json::array({x.run, x.step, x.key}));
  const std::vector<uint8_t> cbor = json::to_cbor(j);
  return {reinterpret_cast<const char*>(cbor.data()), cbor.size()};
}

void Store::Batch::add_serialized(std::string_view bytes) {
  const Impl& d = *store_.impl_;
  if (!open_) throw Error("cannot add to a batch on " + d.path + ": already committed");
  Pending& p = *pending_;
  try {
    const json j = json::from_cbor(bytes);
    // A tile or overview of a raster layer at the layer's level or coarser.
    const auto tile = [&](const json& t, bool overview) {
      const LayerEntry e = d.require_tiles(t.at(0).get<std::string>());
      const CellId cell(t.at(1).get<uint64_t>());
      if (!cell.is_valid() ||
          (overview ? cell.level() >= e.info.level : cell.level() != e.info.level))
        throw Error("layer '" + e.info.name + "' in " + d.path + " holds no " +
                    (overview ? "overview" : "tile") + " at " + cell_text(cell));
      return Pending::TileWrite{e.id, cell, blob_of(t.at(2))};
    };
    for (const json& t : j.at("tiles")) p.tiles.push_back(tile(t, false));
    for (const json& o : j.at("overviews")) p.overviews.push_back(tile(o, true));
    for (const json& o : j.at("partial"))
      p.partial_overviews.push_back({tile(o.at(0), true), o.at(1).get<int64_t>()});
    for (const json& c : j.at("contents")) {
      const std::string blob = c.at(2).is_null() ? "" : text_of(c.at(2));
      p.contents.push_back(content_write(
          d.require(c.at(0).get<std::string>()), d.path, CellId(c.at(1).get<uint64_t>()),
          c.at(2).is_null() ? std::nullopt : std::optional<std::string_view>(blob)));
    }
    for (const json& a : j.at("artifacts"))
      p.artifacts.push_back(
          {a.at(0).get<std::string>(), a.at(1).get<std::string>(), blob_of(a.at(2)), a.at(3)});
    for (const json& x : j.at("done"))
      p.done.push_back({x.at(0).get<int64_t>(), x.at(1).get<int>(), x.at(2).get<int64_t>()});
  } catch (const json::exception& e) {
    throw Error("not a serialized batch (for " + d.path + "): " + e.what());
  }
}

}  // namespace maquette
