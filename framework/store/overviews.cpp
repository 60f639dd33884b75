// Overview pyramid: stale marks and bottom-up rebuilding.
//
// Writing a tile marks only its parent stale; rebuilding an overview tile marks its own parent
// stale in the same transaction. So update_overviews(layer, m) walks the levels from the base
// down to m and rebuilds exactly the ancestors of the tiles written since, and marks left
// below m wait for a later call with a lower min_level.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include "store/codec.h"
#include "store/downsample.h"
#include "store/store_impl.h"

namespace maquette {
namespace {

constexpr size_t kCellsPerTransaction = 64;  // bounds memory and lock time
constexpr size_t kMaxBuiltKept = 64;         // overview tiles kept in memory for the next level

}  // namespace

size_t Store::Impl::rebuild_stale(sqlite::Connection& c, const LayerEntry& e, int level,
                                  size_t limit, const BuiltOverviews& below,
                                  BuiltOverviews& built) {
  const auto [cells, children] = read_stale_cells(c, e, level, limit);

  // Decoding, reducing and encoding dominate: done in parallel, without SQLite. Isolated, so
  // that a worker waiting here never picks up an outer task that would take the write lock.
  std::vector<std::vector<std::byte>> blobs(cells.size());
  std::vector<RawTile> overviews(cells.size());
  const Codec codec = parse_codec(e.info.codec);
  // (&cells = cells: clang 14, the fuzz build's compiler, cannot capture a structured binding)
  tbb::this_task_arena::isolate([&, &cells = cells, &children = children] {
    tbb::parallel_for(size_t(0), cells.size(), [&](size_t i) {
      std::array<std::optional<RawTile>, 4> tiles;
      std::array<const RawTile*, 4> ptrs{};
      for (int k = 0; k < 4; ++k)
        if (const auto& blob = children[i][k]) {
          const CellId child = cells[i].child(k);
          const auto bytes = std::as_bytes(std::span(*blob));
          // Built at the level below in this call and stored as is: no need to decode it.
          if (const auto it = below.find(child.id());
              it != below.end() && std::ranges::equal(it->second.first, bytes)) {
            ptrs[k] = &it->second.second;
            continue;
          }
          tiles[k] = decode(bytes, e, child);
          ptrs[k] = &*tiles[k];
        }
      overviews[i] = build_overview(ptrs, e.info);
      blobs[i] = encode_tile(overviews[i], codec);
      // Kept for the next level as the tile stored (what decoding the blob gives).
      if (!codec.lossless()) overviews[i] = decode_tile(blobs[i]);
    });
  });

  for (size_t i = 0; i < cells.size(); ++i) write_overview(c, e.id, cells[i], blobs[i]);
  for (size_t i = 0; i < cells.size() && built.size() < kMaxBuiltKept; ++i)
    built.insert_or_assign(cells[i].id(),
                           std::make_pair(std::move(blobs[i]), std::move(overviews[i])));
  return cells.size();
}

StaleCells read_stale_cells(sqlite::Connection& c, const LayerEntry& e, int level, size_t limit) {
  StaleCells stale;
  auto q = c.query(
      "SELECT cell FROM stale_overviews WHERE layer = ? AND level = ? ORDER BY cell LIMIT ?");
  q.bind_int(1, e.id).bind_int(2, level).bind_int(3, int64_t(limit));
  while (q.step()) stale.cells.emplace_back(uint64_t(q.int64(0)));
  for (CellId cell : stale.cells) stale.children.push_back(read_children(c, e, cell));
  return stale;
}

ChildBlobs read_children(sqlite::Connection& c, const LayerEntry& e, CellId cell) {
  const int child_level = cell.level() + 1;
  const int64_t first = int64_t(cell.range_min().id()), last = int64_t(cell.range_max().id());
  ChildBlobs out;
  const auto keep = [&](int64_t child, std::string&& blob) {
    out[CellId(uint64_t(child)).digit(child_level)] = std::move(blob);
  };
  if (holds_content(e.info.kind)) {
    read_content_blobs(c, e.id, child_level, first, last, keep);
    return out;
  }
  auto q = c.query(child_level == e.info.level
                       ? "SELECT cell, blob FROM tiles WHERE layer = ?1 AND cell BETWEEN ?3 AND ?4"
                       : "SELECT cell, blob FROM overviews WHERE layer = ?1 AND level = ?2 AND "
                         "cell BETWEEN ?3 AND ?4");
  q.bind_int(1, e.id).bind_int(2, child_level).bind_int(3, first).bind_int(4, last);
  while (q.step()) {
    const auto blob = q.blob(1);
    keep(q.int64(0), std::string(reinterpret_cast<const char*>(blob.data()), blob.size()));
  }
  return out;
}

void write_overview(sqlite::Connection& conn, int64_t layer_id, CellId cell,
                    std::span<const std::byte> blob) {
  const int64_t id = int64_t(cell.id());
  conn.query("INSERT OR REPLACE INTO overviews(layer, level, cell, blob) VALUES(?, ?, ?, ?)")
      .bind_int(1, layer_id)
      .bind_int(2, cell.level())
      .bind_int(3, id)
      .bind_blob(4, blob)
      .run();
  conn.query("DELETE FROM stale_overviews WHERE layer = ? AND level = ? AND cell = ?")
      .bind_int(1, layer_id)
      .bind_int(2, cell.level())
      .bind_int(3, id)
      .run();
  mark_parent_stale(conn, layer_id, cell);
}

void mark_parent_stale(sqlite::Connection& conn, int64_t layer_id, CellId cell) {
  if (cell.level() == 0) return;
  conn.query("INSERT OR IGNORE INTO stale_overviews(layer, level, cell) VALUES(?, ?, ?)")
      .bind_int(1, layer_id)
      .bind_int(2, cell.level() - 1)
      .bind_int(3, int64_t(cell.parent().id()))
      .run();
}

void Store::update_overviews(const std::string& layer, int min_level) {
  Impl& d = *impl_;
  const LayerEntry e = d.require(layer);
  const std::string where = "cannot build overviews of layer '" + layer + "' in " + d.path + ": ";
  if (min_level < 0 || min_level > e.info.level)
    throw Error(where + "min level " + std::to_string(min_level) + " not in [0, " +
                std::to_string(e.info.level) + "]");
  if (e.info.kind == LayerKind::Model) throw Error(where + "a model has no coarser levels");
  if (layer_content_kind(e.info.kind))
    throw Error(where + "the coarser levels of its " + std::string(layer_kind_name(e.info.kind)) +
                " content hold what its writer simplified (put_content)");
  if (e.info.tile_size < 2) throw Error(where + "tiles of 1x1 samples cannot be halved");
  // The tiles written before this call are on their way to the disk while overviews are built.
  if (d.checkpointer) d.checkpointer->request();
  Impl::BuiltOverviews below, built;
  // Up to kCellsPerTransaction tiles per transaction, over as many levels as they take (the
  // upper levels of a pyramid hold a few tiles each: one transaction for all of them).
  int level = e.info.level - 1;
  while (level >= min_level)
    d.write([&](sqlite::Connection& c) {
      size_t budget = kCellsPerTransaction;
      while (level >= min_level && budget > 0) {
        const size_t rebuilt = d.rebuild_stale(c, e, level, budget, below, built);
        if (rebuilt < budget) {  // the level is done
          below = std::move(built);
          built.clear();
          --level;
        }
        budget -= rebuilt;
      }
    });
}

std::optional<RawTile> Store::get_overview(const std::string& layer, CellId cell) const {
  const LayerEntry e = impl_->require_tiles(layer);
  if (!cell.is_valid() || cell.level() >= e.info.level)
    throw Error("no overview of layer '" + layer + "' at " + cell_text(cell) + " in " +
                impl_->path + ": overviews are at levels below " + std::to_string(e.info.level));
  auto conn = impl_->readers.borrow();
  auto q = conn->query("SELECT blob FROM overviews WHERE layer = ? AND level = ? AND cell = ?");
  if (!q.bind_int(1, e.id).bind_int(2, cell.level()).bind_int(3, int64_t(cell.id())).step())
    return std::nullopt;
  return impl_->decode(q.blob(0), e, cell);
}

}  // namespace maquette
