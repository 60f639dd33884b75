// Reading full-resolution tiles: point lookups and range scans in cell id order.
#include "store/store_impl.h"

namespace maquette {

std::optional<RawTile> Store::get_tile(const std::string& layer, CellId cell) const {
  const LayerEntry e = impl_->require_tiles(layer);
  auto conn = impl_->readers.borrow();
  auto q = conn->query("SELECT blob FROM tiles WHERE layer = ? AND cell = ?");
  if (!q.bind_int(1, e.id).bind_int(2, int64_t(cell.id())).step()) return std::nullopt;
  return impl_->decode(q.blob(0), e, cell);
}

bool Store::has_tile(const std::string& layer, CellId cell) const {
  const LayerEntry e = impl_->require(layer);
  auto conn = impl_->readers.borrow();
  auto q = conn->query("SELECT 1 FROM tiles WHERE layer = ? AND cell = ?");
  return q.bind_int(1, e.id).bind_int(2, int64_t(cell.id())).step();
}

std::vector<CellId> Store::tile_cells(const std::string& layer, CellId first, CellId last) const {
  const LayerEntry e = impl_->require(layer);
  auto conn = impl_->readers.borrow();
  auto q =
      conn->query("SELECT cell FROM tiles WHERE layer = ? AND cell BETWEEN ? AND ? ORDER BY cell");
  q.bind_int(1, e.id).bind_int(2, int64_t(first.id())).bind_int(3, int64_t(last.id()));
  std::vector<CellId> cells;
  while (q.step()) cells.emplace_back(uint64_t(q.int64(0)));
  return cells;
}

std::vector<CellId> Store::tile_cells(const std::string& layer) const {
  return tile_cells(layer, CellId(0), CellId(uint64_t(INT64_MAX)));
}

void Store::scan(const std::string& layer, CellId first, CellId last,
                 const std::function<void(CellId, const RawTile&)>& visit) const {
  const LayerEntry e = impl_->require_tiles(layer);
  auto conn = impl_->readers.borrow();
  auto q = conn->query(
      "SELECT cell, blob FROM tiles WHERE layer = ? AND cell BETWEEN ? AND ? ORDER BY cell");
  q.bind_int(1, e.id).bind_int(2, int64_t(first.id())).bind_int(3, int64_t(last.id()));
  while (q.step()) {
    const CellId cell(uint64_t(q.int64(0)));
    visit(cell, impl_->decode(q.blob(1), e, cell));
  }
}

}  // namespace maquette
