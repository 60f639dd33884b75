// Content layers (kinds mesh, instances, volume): one envelope blob per cell, in tiles at the
// layer's level and in overviews at the coarser levels that hold simplified content.
#include "content/content_blob.h"
#include "store/store_impl.h"

namespace maquette {
namespace {

ContentKind check_content_layer(const LayerEntry& e, const std::string& store_path) {
  if (const auto kind = layer_content_kind(e.info.kind)) return *kind;
  throw Error("layer '" + e.info.name + "' in " + store_path + " is of kind " +
              std::string(layer_kind_name(e.info.kind)) +
              ", not a content layer (mesh, instances or volume)");
}

// Throws unless `cell` is at the layer's level or coarser.
void check_content_cell(const LayerEntry& e, CellId cell, const std::string& where) {
  if (!cell.is_valid() || cell.level() > e.info.level)
    throw Error(where + "the layer's content is at level " + std::to_string(e.info.level) +
                " and the coarser ones");
}

std::string content_where(const LayerEntry& e, CellId cell, const std::string& store_path) {
  return "layer '" + e.info.name + "', " + cell_text(cell) + ", in " + store_path;
}

// The envelope of a stored blob from its first bytes (`head`) and its size; throws naming the
// layer and cell unless it is sound and of the layer's kind.
ContentEnvelope stored_envelope(const LayerEntry& e, ContentKind kind, CellId cell,
                                std::span<const std::byte> head, int64_t bytes,
                                const std::string& store_path) {
  const std::string where = content_where(e, cell, store_path);
  const ContentEnvelope envelope = read_content_header(
      {reinterpret_cast<const char*>(head.data()), head.size()}, uint64_t(bytes), where);
  if (envelope.kind != kind)
    throw Error("corrupt content blob (" + where + "): it holds " +
                std::string(content_kind_name(envelope.kind)) + " content, the layer " +
                std::string(content_kind_name(kind)));
  return envelope;
}

}  // namespace

ContentWrite content_write(const LayerEntry& e, const std::string& store_path, CellId cell,
                           std::string_view blob) {
  const ContentKind kind = check_content_layer(e, store_path);
  const std::string where = "cannot write content of layer '" + e.info.name + "' at " +
                            cell_text(cell) + " in " + store_path + ": ";
  check_content_cell(e, cell, where);
  const ContentEnvelope envelope = read_content_envelope(blob, content_where(e, cell, store_path));
  if (envelope.kind != kind)
    throw Error(where + "the blob holds " + std::string(content_kind_name(envelope.kind)) +
                " content, the layer " + std::string(content_kind_name(kind)));
  return {e.id, cell, cell.level() < e.info.level, std::string(blob)};
}

void write_content(sqlite::Connection& c, const ContentWrite& w) {
  const auto blob = std::as_bytes(std::span(w.blob));
  // A cell at the layer's level marks its parent stale for update_content_overviews
  // (content/content_overviews.h); a coarser one is an overview the writer put itself.
  if (w.coarser)
    c.query("INSERT OR REPLACE INTO overviews(layer, level, cell, blob) VALUES(?, ?, ?, ?)")
        .bind_int(1, w.layer)
        .bind_int(2, w.cell.level())
        .bind_int(3, int64_t(w.cell.id()))
        .bind_blob(4, blob)
        .run();
  else {
    c.query("INSERT OR REPLACE INTO tiles(layer, cell, blob) VALUES(?, ?, ?)")
        .bind_int(1, w.layer)
        .bind_int(2, int64_t(w.cell.id()))
        .bind_blob(3, blob)
        .run();
    mark_parent_stale(c, w.layer, w.cell);
  }
}

std::optional<std::string> Store::get_content(const std::string& layer, CellId cell) const {
  const LayerEntry e = impl_->require(layer);
  const ContentKind kind = check_content_layer(e, impl_->path);
  check_content_cell(
      e, cell,
      "no content of layer '" + layer + "' at " + cell_text(cell) + " in " + impl_->path + ": ");
  auto conn = impl_->readers.borrow();
  auto q =
      cell.level() == e.info.level
          ? conn->query("SELECT blob FROM tiles WHERE layer = ?1 AND cell = ?3")
          : conn->query("SELECT blob FROM overviews WHERE layer = ?1 AND level = ?2 AND cell = ?3");
  q.bind_int(1, e.id).bind_int(2, cell.level()).bind_int(3, int64_t(cell.id()));
  if (!q.step()) return std::nullopt;
  const auto blob = q.blob(0);
  stored_envelope(e, kind, cell, blob, int64_t(blob.size()), impl_->path);
  return std::string(reinterpret_cast<const char*>(blob.data()), blob.size());
}

std::vector<CellId> Store::content_cells(const std::string& layer, int level, CellId first,
                                         CellId last) const {
  const LayerEntry e = impl_->require(layer);
  check_content_layer(e, impl_->path);
  if (level < 0 || level > e.info.level)
    throw Error("layer '" + layer + "' in " + impl_->path + " has no level " +
                std::to_string(level) + ": its content is at levels 0 to " +
                std::to_string(e.info.level));
  auto conn = impl_->readers.borrow();
  auto q = level == e.info.level
               ? conn->query(
                     "SELECT cell FROM tiles WHERE layer = ?1 AND cell BETWEEN ?3 AND ?4 "
                     "ORDER BY cell")
               : conn->query(
                     "SELECT cell FROM overviews WHERE layer = ?1 AND level = ?2 AND cell "
                     "BETWEEN ?3 AND ?4 ORDER BY cell");
  q.bind_int(1, e.id)
      .bind_int(2, level)
      .bind_int(3, int64_t(first.id()))
      .bind_int(4, int64_t(last.id()));
  std::vector<CellId> cells;
  while (q.step()) cells.emplace_back(uint64_t(q.int64(0)));
  return cells;
}

std::vector<CellId> Store::content_cells(const std::string& layer, int level) const {
  return content_cells(layer, level, CellId(0), CellId(uint64_t(INT64_MAX)));
}

std::vector<CellId> Store::content_cells(const std::string& layer) const {
  return content_cells(layer, impl_->require(layer).info.level);
}

ContentLayerStats Store::content_stats(const std::string& layer) const {
  const LayerEntry e = impl_->require(layer);
  const ContentKind kind = check_content_layer(e, impl_->path);
  auto conn = impl_->readers.borrow();
  ContentLayerStats s;
  {
    // The header alone (content_blob.h), not the payload: length() reads no blob either.
    auto q =
        conn->query("SELECT cell, substr(blob, 1, ?2), length(blob) FROM tiles WHERE layer = ?1");
    q.bind_int(1, e.id).bind_int(2, int64_t(kContentHeaderBytes));
    while (q.step()) {
      const int64_t length = q.int64(2);
      const ContentEnvelope envelope =
          stored_envelope(e, kind, CellId(uint64_t(q.int64(0))), q.blob(1), length, impl_->path);
      s.content.objects += envelope.stats.objects;
      s.content.triangles += envelope.stats.triangles;
      s.content.voxels += envelope.stats.voxels;
      ++s.cells;
      s.bytes += length;
    }
  }
  auto q = conn->query("SELECT coalesce(sum(length(blob)), 0) FROM overviews WHERE layer = ?");
  q.bind_int(1, e.id).step();
  s.bytes += q.int64(0);
  return s;
}

}  // namespace maquette
