// Batches: writes checked and encoded by the caller's thread, applied in one transaction.
#include <algorithm>
#include <array>
#include <optional>
#include <set>

#include "store/batch_pending.h"
#include "store/codec.h"
#include "store/downsample.h"

namespace maquette {

Store::Batch::Batch(Store& store) : store_(store), pending_(std::make_unique<Pending>()) {
  store_.impl_->require_writable();
}

Store::Batch::~Batch() = default;

void Store::Batch::put_tile(const std::string& layer, CellId cell, const RawTile& tile) {
  const Impl& d = *store_.impl_;
  const LayerEntry e = d.require(layer);
  const LayerInfo& l = e.info;
  const std::string where =
      "cannot write layer '" + layer + "' at " + cell_text(cell) + " in " + d.path + ": ";
  if (!open_) throw Error(where + "the batch is already committed");
  if (holds_content(l.kind))
    throw Error(where + "it holds " + std::string(layer_kind_name(l.kind)) + " content (" +
                (l.kind == LayerKind::Model ? "put_model" : "put_content") + "), not raster tiles");
  if (!cell.is_valid() || cell.level() != l.level)
    throw Error(where + "the layer's tiles are at level " + std::to_string(l.level));
  if (tile.dtype != l.dtype || tile.size != l.tile_size || tile.channels != l.channels ||
      tile.bytes.size() != tile.sample_count() * dtype_size(tile.dtype))
    throw Error(where + "got a " + std::to_string(tile.size) + "x" + std::to_string(tile.size) +
                "x" + std::to_string(tile.channels) + " " + std::string(dtype_name(tile.dtype)) +
                " tile of " + std::to_string(tile.bytes.size()) + " bytes, the layer holds " +
                std::to_string(l.tile_size) + "x" + std::to_string(l.tile_size) + "x" +
                std::to_string(l.channels) + " " + std::string(dtype_name(l.dtype)));
  const Codec codec = parse_codec(l.codec);
  pending_->tiles.push_back({e.id, cell, encode_tile(tile, codec)});
  if (l.level == 0 || l.tile_size < 2) return;  // no parent, or tiles that cannot be halved
  const auto key = std::make_pair(e.id, cell.parent());
  auto& children = pending_->siblings[key].tiles;
  // The overview is built from the tile as stored, as update_overviews would build it.
  children[cell.digit(l.level)] =
      codec.lossless() ? tile : decode_tile(pending_->tiles.back().blob);
  if (!std::ranges::all_of(children, [](const auto& t) { return t.has_value(); })) return;
  const RawTile overview =
      build_overview({&*children[0], &*children[1], &*children[2], &*children[3]}, l);
  pending_->overviews.push_back({e.id, cell.parent(), encode_tile(overview, codec)});
  pending_->siblings.erase(key);
}

void Store::Batch::put_parent_overview(const std::string& layer, CellId parent) {
  const LayerEntry e = store_.impl_->require(layer);
  if (!open_)
    throw Error("cannot write the overview of layer '" + layer + "' at " + cell_text(parent) +
                ": batch already committed");
  const auto it = pending_->siblings.find({e.id, parent});
  if (it == pending_->siblings.end()) return;  // no child written, or all four (already built)
  std::array<const RawTile*, 4> children{};
  int64_t count = 0;
  for (size_t k = 0; k < 4; ++k)
    if (const auto& tile = it->second.tiles[k]) {
      children[k] = &*tile;
      ++count;
    }
  pending_->partial_overviews.push_back(
      {{e.id, parent, encode_tile(build_overview(children, e.info), parse_codec(e.info.codec))},
       count});
  pending_->siblings.erase(it);
}

void Store::Batch::put_artifact(const Artifact& artifact) {
  if (!open_) throw Error("cannot write artifact '" + artifact.name + "': batch already committed");
  if (artifact.name.empty()) throw Error("an artifact needs a name");
  pending_->artifacts.push_back(artifact);
}

void Store::Batch::put_feature(const std::string& layer, const Feature& feature,
                               std::span<const CellId> cells) {
  if (!open_)
    throw Error("cannot write feature " + std::to_string(feature.fid) + " of layer '" + layer +
                "': batch already committed");
  const Impl& d = *store_.impl_;
  pending_->features.push_back(feature_write(d.require(layer), d.path, feature, cells));
}

void Store::Batch::put_content(const std::string& layer, CellId cell, std::string_view blob) {
  const Impl& d = *store_.impl_;
  if (!open_)
    throw Error("cannot write content of layer '" + layer + "' at " + cell_text(cell) +
                ": batch already committed");
  pending_->contents.push_back(content_write(d.require(layer), d.path, cell, blob));
}

void Store::Batch::remove_content(const std::string& layer, CellId cell) {
  const Impl& d = *store_.impl_;
  if (!open_)
    throw Error("cannot remove content of layer '" + layer + "' at " + cell_text(cell) +
                ": batch already committed");
  pending_->contents.push_back(content_write(d.require(layer), d.path, cell, std::nullopt));
}

void Store::Batch::put_model(const std::string& name, std::string_view blob,
                             const nlohmann::json& provenance) {
  const Impl& d = *store_.impl_;
  if (!open_) throw Error("cannot write model '" + name + "': batch already committed");
  pending_->models.push_back(model_write(d.find(name), d.path, name, blob, provenance));
}

void Store::Batch::mark_done(int64_t run_id, int step, CellId cell) {
  mark_done(run_id, step, int64_t(cell.id()));
}

void Store::Batch::mark_done(int64_t run_id, int step, int64_t key) {
  if (!open_) throw Error("cannot mark work done: batch already committed");
  pending_->done.push_back({run_id, step, key});
}

void Store::Batch::commit() {
  if (!open_) throw Error("batch on " + store_.impl_->path + " is already committed");
  const Pending& p = *pending_;
  store_.impl_->write([&](sqlite::Connection& c) {
    std::set<int64_t> layers;
    for (const auto& t : p.tiles) {
      c.query("INSERT OR REPLACE INTO tiles(layer, cell, blob) VALUES(?, ?, ?)")
          .bind_int(1, t.layer)
          .bind_int(2, int64_t(t.cell.id()))
          .bind_blob(3, t.blob)
          .run();
      mark_parent_stale(c, t.layer, t.cell);
      layers.insert(t.layer);
    }
    // After the tiles: writing an overview clears the stale mark its children just set.
    for (const auto& o : p.overviews) write_overview(c, o.layer, o.cell, o.blob);
    for (const auto& [o, children] : p.partial_overviews) {
      int64_t stored = 0;
      {
        auto q = c.query("SELECT count(*) FROM tiles WHERE layer = ? AND cell BETWEEN ? AND ?");
        q.bind_int(1, o.layer)
            .bind_int(2, int64_t(o.cell.range_min().id()))
            .bind_int(3, int64_t(o.cell.range_max().id()));
        if (q.step()) stored = q.int64(0);
      }
      if (stored == children) write_overview(c, o.layer, o.cell, o.blob);
    }
    for (const auto& f : p.features) {
      write_feature(c, f);
      layers.insert(f.layer);
    }
    for (const auto& w : p.contents) {
      write_content(c, w);
      layers.insert(w.layer);
    }
    for (const auto& m : p.models) write_model(c, store_.impl_->path, m);
    for (int64_t id : layers)
      c.query("UPDATE layers SET updated = strftime('%Y-%m-%dT%H:%M:%fZ') WHERE id = ?")
          .bind_int(1, id)
          .run();
    for (const auto& a : p.artifacts)
      c.query(
           "INSERT OR REPLACE INTO artifacts(name, media_type, data, metadata, updated) "
           "VALUES(?, ?, ?, ?, strftime('%Y-%m-%dT%H:%M:%fZ'))")
          .bind_text(1, a.name)
          .bind_text(2, a.media_type)
          .bind_blob(3, a.data)
          .bind_text(4, a.metadata.dump())
          .run();
    for (const auto& d : p.done)
      c.query("INSERT OR IGNORE INTO run_cells(run, step, cell) VALUES(?, ?, ?)")
          .bind_int(1, d.run)
          .bind_int(2, d.step)
          .bind_int(3, d.key)
          .run();
  });
  open_ = false;
  pending_.reset();
}

void Store::put_tile(const std::string& layer, CellId cell, const RawTile& tile) {
  Batch batch(*this);
  batch.put_tile(layer, cell, tile);
  batch.commit();
}

}  // namespace maquette
