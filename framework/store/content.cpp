// Content layers (kinds mesh, instances, volume): one envelope blob per cell, in the content
// table (content_rows.cpp) at the layer's level and at the coarser levels that hold simplified
// content.
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
                           std::optional<std::string_view> blob) {
  const ContentKind kind = check_content_layer(e, store_path);
  const std::string where = "cannot " + std::string(blob ? "write" : "remove") +
                            " content of layer '" + e.info.name + "' at " + cell_text(cell) +
                            " in " + store_path + ": ";
  check_content_cell(e, cell, where);
  const bool coarser = cell.level() < e.info.level;
  if (!blob) return {e.id, cell, coarser, std::nullopt};
  const ContentEnvelope envelope = read_content_envelope(*blob, content_where(e, cell, store_path));
  if (envelope.kind != kind)
    throw Error(where + "the blob holds " + std::string(content_kind_name(envelope.kind)) +
                " content, the layer " + std::string(content_kind_name(kind)));
  return {e.id, cell, coarser, std::string(*blob)};
}

void write_content(sqlite::Connection& c, const ContentWrite& w) {
  const int64_t cell = int64_t(w.cell.id());
  bool changed = true;
  if (w.blob)
    write_content_blob(c, w.layer, w.cell.level(), cell, *w.blob);
  else
    changed = delete_content_blob(c, w.layer, w.cell.level(), cell);
  // A cell at the layer's level marks its parent stale for update_content_overviews
  // (content/content_overviews.h); a coarser one is an overview the writer put itself.
  if (changed && !w.coarser) mark_parent_stale(c, w.layer, w.cell);
}

LayerStats content_layer_stats(sqlite::Connection& c, const LayerEntry& e) {
  LayerStats s;
  auto q = c.query(
      "SELECT level, sum(part = 0), sum(length(data)), min(cell), max(cell) FROM content "
      "WHERE layer = ? GROUP BY level ORDER BY level");
  q.bind_int(1, e.id);
  while (q.step()) {
    s.levels.push_back(int(q.int64(0)));
    s.bytes += q.int64(2);
    if (s.levels.back() != e.info.level) continue;
    s.tile_count = q.int64(1);
    s.first = CellId(uint64_t(q.int64(3)));
    s.last = CellId(uint64_t(q.int64(4)));
  }
  return s;
}

std::optional<std::string> Store::get_content(const std::string& layer, CellId cell) const {
  const LayerEntry e = impl_->require(layer);
  const ContentKind kind = check_content_layer(e, impl_->path);
  check_content_cell(
      e, cell,
      "no content of layer '" + layer + "' at " + cell_text(cell) + " in " + impl_->path + ": ");
  auto conn = impl_->readers.borrow();
  auto blob = read_content_blob(*conn, e.id, cell.level(), int64_t(cell.id()));
  if (blob)
    stored_envelope(e, kind, cell, std::as_bytes(std::span(*blob)), int64_t(blob->size()),
                    impl_->path);
  return blob;
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
  auto q = conn->query(
      "SELECT cell FROM content WHERE layer = ? AND level = ? AND cell BETWEEN ? AND ? AND "
      "part = 0 ORDER BY cell");
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
  // The header (content_blob.h) from the first part, not the payload; length() reads no blob.
  auto q = conn->query(
      "SELECT level, cell, part, substr(data, 1, ?2), length(data) FROM content WHERE layer = ?1 "
      "ORDER BY level, cell, part");
  q.bind_int(1, e.id).bind_int(2, int64_t(kContentHeaderBytes));
  std::vector<std::byte> head;
  int64_t cell = 0, bytes = 0;
  const auto add_cell = [&] {
    const ContentEnvelope envelope =
        stored_envelope(e, kind, CellId(uint64_t(cell)), head, bytes, impl_->path);
    s.content.objects += envelope.stats.objects;
    s.content.triangles += envelope.stats.triangles;
    s.content.voxels += envelope.stats.voxels;
    ++s.cells;
  };
  bool base = false;  // the cell at `cell` is at the layer's level
  while (q.step()) {
    const int64_t length = q.int64(4);
    s.bytes += length;
    if (q.int64(2) == 0) {  // a cell's first part
      if (base) add_cell();
      base = q.int64(0) == e.info.level;
      cell = q.int64(1);
      const auto h = q.blob(3);
      head.assign(h.begin(), h.end());
      bytes = 0;
    }
    bytes += length;
  }
  if (base) add_cell();
  return s;
}

}  // namespace maquette
