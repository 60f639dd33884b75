// Features layers: each feature stored once, indexed in every cell it touches.
#include <algorithm>
#include <cmath>

#include "store/store_impl.h"

namespace maquette {
namespace {

// The cells a feature is indexed in, as little-endian int64s (to drop them on a rewrite).
std::vector<std::byte> encode_cells(const std::vector<CellId>& cells) {
  std::vector<std::byte> out(cells.size() * 8);
  for (size_t i = 0; i < cells.size(); ++i)
    for (int b = 0; b < 8; ++b) out[i * 8 + b] = std::byte(cells[i].id() >> (8 * b));
  return out;
}

std::vector<CellId> decode_cells(std::span<const std::byte> blob) {
  std::vector<CellId> cells(blob.size() / 8);
  for (size_t i = 0; i < cells.size(); ++i) {
    uint64_t id = 0;
    for (int b = 0; b < 8; ++b) id |= uint64_t(blob[i * 8 + b]) << (8 * b);
    cells[i] = CellId(id);
  }
  return cells;
}

const LayerEntry& check_features(const LayerEntry& e, const std::string& store_path) {
  if (e.info.kind != LayerKind::Features)
    throw Error("layer '" + e.info.name + "' in " + store_path + " is a " +
                std::string(layer_kind_name(e.info.kind)) + " layer, not a features layer");
  return e;
}

}  // namespace

FeatureWrite feature_write(const LayerEntry& layer, const std::string& store_path,
                           const Feature& feature, std::span<const CellId> cells) {
  const LayerEntry& e = check_features(layer, store_path);
  const std::string where = "cannot write feature " + std::to_string(feature.fid) + " of layer '" +
                            e.info.name + "' in " + store_path + ": ";
  for (CellId c : cells)
    if (!c.is_valid() || c.level() != e.info.level)
      throw Error(where + cell_text(c) + " is not a cell at the layer's level " +
                  std::to_string(e.info.level));
  const auto& b = feature.bbox;
  if (!std::all_of(b.begin(), b.end(), [](double v) { return std::isfinite(v); }) || b[1] > b[3])
    throw Error(where + "bad bounding box");
  if (!feature.attributes.is_object()) throw Error(where + "attributes must be a JSON object");
  FeatureWrite w{e.id, feature, {cells.begin(), cells.end()}};
  std::sort(w.cells.begin(), w.cells.end());
  w.cells.erase(std::unique(w.cells.begin(), w.cells.end()), w.cells.end());
  return w;
}

void write_feature(sqlite::Connection& c, const FeatureWrite& w) {
  const Feature& f = w.feature;
  {
    auto old = c.query("SELECT cells FROM features WHERE layer = ? AND fid = ?");
    if (old.bind_int(1, w.layer).bind_int(2, f.fid).step())
      for (CellId cell : decode_cells(old.blob(0)))
        c.query("DELETE FROM feature_cells WHERE layer = ? AND cell = ? AND fid = ?")
            .bind_int(1, w.layer)
            .bind_int(2, int64_t(cell.id()))
            .bind_int(3, f.fid)
            .run();
  }
  c.query(
       "INSERT OR REPLACE INTO features(layer, fid, west, south, east, north, geometry, "
       "attributes, cells) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .bind_int(1, w.layer)
      .bind_int(2, f.fid)
      .bind_real(3, f.bbox[0])
      .bind_real(4, f.bbox[1])
      .bind_real(5, f.bbox[2])
      .bind_real(6, f.bbox[3])
      .bind_blob(7, f.wkb)
      .bind_text(8, f.attributes.dump())
      .bind_blob(9, encode_cells(w.cells))
      .run();
  for (CellId cell : w.cells)
    c.query("INSERT INTO feature_cells(layer, cell, fid) VALUES(?, ?, ?)")
        .bind_int(1, w.layer)
        .bind_int(2, int64_t(cell.id()))
        .bind_int(3, f.fid)
        .run();
}

LayerStats feature_stats(sqlite::Connection& c, const LayerEntry& e) {
  LayerStats s;
  {
    auto q = c.query(
        "SELECT count(*), coalesce(sum(length(geometry) + length(attributes) + length(cells)), 0) "
        "FROM features WHERE layer = ?");
    q.bind_int(1, e.id).step();
    s.feature_count = q.int64(0);
    s.bytes = q.int64(1);
  }
  auto q = c.query(
      "SELECT count(DISTINCT cell), min(cell), max(cell) FROM feature_cells WHERE layer = ?");
  q.bind_int(1, e.id).step();
  s.tile_count = q.int64(0);
  if (s.tile_count > 0) {
    s.first = CellId(uint64_t(q.int64(1)));
    s.last = CellId(uint64_t(q.int64(2)));
    s.levels = {e.info.level};
  }
  return s;
}

std::vector<Feature> Store::features_in(const std::string& layer, CellId first, CellId last) const {
  const LayerEntry e = check_features(impl_->require(layer), impl_->path);
  auto conn = impl_->readers.borrow();
  auto q = conn->query(
      "SELECT fid, west, south, east, north, geometry, attributes FROM features "
      "WHERE layer = ?1 AND fid IN (SELECT fid FROM feature_cells "
      "WHERE layer = ?1 AND cell BETWEEN ?2 AND ?3) ORDER BY fid");
  q.bind_int(1, e.id).bind_int(2, int64_t(first.id())).bind_int(3, int64_t(last.id()));
  std::vector<Feature> out;
  while (q.step()) {
    const auto wkb = q.blob(5);
    out.push_back({q.int64(0),
                   {wkb.begin(), wkb.end()},
                   nlohmann::json::parse(q.text(6)),
                   {q.real(1), q.real(2), q.real(3), q.real(4)}});
  }
  return out;
}

std::vector<CellId> Store::feature_cells(const std::string& layer, int64_t fid) const {
  const LayerEntry e = check_features(impl_->require(layer), impl_->path);
  auto conn = impl_->readers.borrow();
  auto q = conn->query("SELECT cells FROM features WHERE layer = ? AND fid = ?");
  if (!q.bind_int(1, e.id).bind_int(2, fid).step()) return {};
  return decode_cells(q.blob(0));
}

int64_t Store::feature_count(const std::string& layer) const {
  const LayerEntry e = check_features(impl_->require(layer), impl_->path);
  auto conn = impl_->readers.borrow();
  auto q = conn->query("SELECT count(*) FROM features WHERE layer = ?");
  q.bind_int(1, e.id).step();
  return q.int64(0);
}

}  // namespace maquette
