// Layer definitions and per-layer statistics.
#include "store/store_impl.h"

namespace maquette {
namespace {

constexpr const char* kSelectLayer =
    "SELECT id, name, kind, dtype, channels, tile_size, level, nodata, semantics, units, codec, "
    "provenance FROM layers";

LayerEntry read_layer(const sqlite::Query& q) {
  LayerEntry e;
  e.id = q.int64(0);
  LayerInfo& l = e.info;
  l.name = q.text(1);
  l.kind = parse_layer_kind(q.text(2));
  l.dtype = parse_dtype(q.text(3));
  l.channels = int(q.int64(4));
  l.tile_size = int(q.int64(5));
  l.level = int(q.int64(6));
  if (!q.is_null(7)) l.nodata = q.real(7);
  l.semantics = parse_semantics(q.text(8));
  l.units = q.text(9);
  l.codec = q.text(10);
  l.provenance = nlohmann::json::parse(q.text(11));
  return e;
}

}  // namespace

std::optional<LayerEntry> load_layer(sqlite::Connection& conn, const std::string& name) {
  static const std::string sql = std::string(kSelectLayer) + " WHERE name = ?";
  auto q = conn.query(sql.c_str());
  q.bind_text(1, name);
  if (!q.step()) return std::nullopt;
  return read_layer(q);
}

int64_t insert_layer(sqlite::Connection& c, const LayerInfo& def) {
  auto q = c.query(
      "INSERT INTO layers(name, kind, dtype, channels, tile_size, level, nodata, semantics, "
      "units, codec, provenance, created, updated) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
      "strftime('%Y-%m-%dT%H:%M:%fZ'), strftime('%Y-%m-%dT%H:%M:%fZ'))");
  q.bind_text(1, def.name)
      .bind_text(2, layer_kind_name(def.kind))
      .bind_text(3, dtype_name(def.dtype))
      .bind_int(4, def.channels)
      .bind_int(5, def.tile_size)
      .bind_int(6, def.level)
      .bind_text(8, semantics_name(def.semantics))
      .bind_text(9, def.units)
      .bind_text(10, def.codec)
      .bind_text(11, def.provenance.dump());
  if (def.nodata)
    q.bind_real(7, *def.nodata);
  else
    q.bind_null(7);
  q.run();
  return c.last_insert_rowid();
}

void update_provenance(sqlite::Connection& c, const LayerEntry& layer,
                       const nlohmann::json& provenance) {
  if (layer.info.provenance == provenance) return;
  c.query("UPDATE layers SET provenance = ?, updated = strftime('%Y-%m-%dT%H:%M:%fZ') WHERE id = ?")
      .bind_text(1, provenance.dump())
      .bind_int(2, layer.id)
      .run();
}

std::optional<LayerEntry> Store::Impl::find(const std::string& name) const {
  {
    std::lock_guard lock(layers_mutex);
    if (auto it = layers.find(name); it != layers.end()) return it->second;
  }
  auto entry = load_layer(*readers.borrow(), name);
  if (entry) {
    std::lock_guard lock(layers_mutex);
    layers.emplace(name, *entry);
  }
  return entry;
}

LayerEntry Store::Impl::require(const std::string& name) const {
  if (auto e = find(name)) return *e;
  throw Error("unknown layer '" + name + "' in " + path);
}

namespace {

// Throws unless the stored layer `old` has the (normalized) definition `def`.
void refuse_another_definition(const std::string& path, const LayerInfo& old,
                               const LayerInfo& def) {
  if (const std::string diff = layer_difference(old, def); !diff.empty())
    throw Error("layer '" + def.name + "' already exists in " + path +
                " with another definition: " + diff + " (stored vs requested)");
}

}  // namespace

void Store::check_layer(const LayerInfo& info) const {
  const LayerInfo def = normalized_layer(info);
  if (auto old = load_layer(*impl_->readers.borrow(), def.name))
    refuse_another_definition(impl_->path, old->info, def);
}

void Store::create_layer(const LayerInfo& info) {
  const LayerInfo def = normalized_layer(info);
  impl_->write([&](sqlite::Connection& c) {
    // An existing layer keeps its codec: each blob names its own format, so a layer written
    // before a codec existed (normals before normal_oct) or at another level resumes as it is.
    if (auto old = load_layer(c, def.name)) {
      refuse_another_definition(impl_->path, old->info, def);
      update_provenance(c, *old, def.provenance);
      return;
    }
    insert_layer(c, def);
  });
}

std::optional<LayerInfo> Store::layer(const std::string& name) const {
  auto e = load_layer(*impl_->readers.borrow(), name);
  if (!e) return std::nullopt;
  return e->info;
}

LayerInfo Store::require_layer(const std::string& name) const {
  auto l = layer(name);
  if (!l) throw Error("unknown layer '" + name + "' in " + impl_->path);
  if (const auto why = incomplete(name))
    throw Error("layer '" + name + "' in " + impl_->path + " is incomplete (" + *why +
                "): finish it with --resume, or write it again");
  return *l;
}

std::vector<LayerInfo> Store::layers() const {
  static const std::string sql = std::string(kSelectLayer) + " ORDER BY name";
  auto conn = impl_->readers.borrow();
  auto q = conn->query(sql.c_str());
  std::vector<LayerInfo> out;
  while (q.step()) out.push_back(read_layer(q).info);
  return out;
}

LayerStats Store::stats(const std::string& layer) const {
  const LayerEntry e = impl_->require(layer);
  auto conn = impl_->readers.borrow();
  if (e.info.kind == LayerKind::Features) return feature_stats(*conn, e);
  if (holds_content(e.info.kind)) return content_layer_stats(*conn, e);
  LayerStats s;
  {
    auto q = conn->query(
        "SELECT count(*), coalesce(sum(length(blob)), 0), min(cell), max(cell) FROM tiles "
        "WHERE layer = ?");
    q.bind_int(1, e.id).step();
    s.tile_count = q.int64(0);
    s.bytes = q.int64(1);
    if (s.tile_count > 0) {
      s.first = CellId(uint64_t(q.int64(2)));
      s.last = CellId(uint64_t(q.int64(3)));
    }
  }
  {
    auto q = conn->query("SELECT coalesce(sum(length(blob)), 0) FROM overviews WHERE layer = ?");
    q.bind_int(1, e.id).step();
    s.bytes += q.int64(0);
  }
  for (int level = 0; level < e.info.level; ++level) {
    auto q = conn->query("SELECT 1 FROM overviews WHERE layer = ? AND level = ? LIMIT 1");
    if (q.bind_int(1, e.id).bind_int(2, level).step()) s.levels.push_back(level);
  }
  if (s.tile_count > 0) s.levels.push_back(e.info.level);
  return s;
}

}  // namespace maquette
