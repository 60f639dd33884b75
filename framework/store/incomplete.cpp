// Marks of layers being written, so that a layer left partial by a failed or killed command is
// refused by readers until it is finished; and the undoing of a failed write.
#include "store/store_impl.h"

namespace maquette {
namespace {

// A store of schema version 2 or older opened read-only has no marks table.
bool has_marks(sqlite::Connection& conn) {
  auto q =
      conn.query("SELECT 1 FROM sqlite_schema WHERE type = 'table' AND name = 'incomplete_layers'");
  return q.step();
}

}  // namespace

void Store::mark_incomplete(const std::string& layer, int64_t run_id) {
  const LayerEntry e = impl_->require(layer);
  impl_->write([&](sqlite::Connection& c) {
    c.query("INSERT OR REPLACE INTO incomplete_layers(layer, run) VALUES(?, ?)")
        .bind_int(1, e.id)
        .bind_int(2, run_id)
        .run();
  });
}

void Store::mark_complete(const std::string& layer) {
  const LayerEntry e = impl_->require(layer);
  impl_->write([&](sqlite::Connection& c) {
    c.query("DELETE FROM incomplete_layers WHERE layer = ?").bind_int(1, e.id).run();
  });
}

std::optional<int64_t> Store::incomplete_run(const std::string& layer) const {
  const auto e = impl_->find(layer);
  if (!e) return std::nullopt;
  auto conn = impl_->readers.borrow();
  if (!has_marks(*conn)) return std::nullopt;
  auto q = conn->query("SELECT run FROM incomplete_layers WHERE layer = ?");
  if (!q.bind_int(1, e->id).step()) return std::nullopt;
  return q.int64(0);
}

std::optional<std::string> Store::incomplete(const std::string& layer) const {
  const auto e = impl_->find(layer);
  if (!e) return std::nullopt;
  auto conn = impl_->readers.borrow();
  if (!has_marks(*conn)) return std::nullopt;
  auto q = conn->query(
      "SELECT m.run, r.status FROM incomplete_layers m LEFT JOIN runs r ON r.id = m.run "
      "WHERE m.layer = ?");
  if (!q.bind_int(1, e->id).step()) return std::nullopt;
  const std::string run = "run " + std::to_string(q.int64(0));
  const std::string status = q.text(1);
  return status == "running" || status.empty() ? run + " is running or was interrupted"
                                               : run + " " + status;
}

void Store::drop_layer(const std::string& layer, int64_t run_id) {
  const LayerEntry e = impl_->require(layer);
  impl_->write([&](sqlite::Connection& c) {
    for (const char* sql :
         {"DELETE FROM tiles WHERE layer = ?", "DELETE FROM overviews WHERE layer = ?",
          "DELETE FROM content WHERE layer = ?", "DELETE FROM stale_overviews WHERE layer = ?",
          "DELETE FROM features WHERE layer = ?", "DELETE FROM feature_cells WHERE layer = ?",
          "DELETE FROM incomplete_layers WHERE layer = ?", "DELETE FROM layers WHERE id = ?"})
      c.query(sql).bind_int(1, e.id).run();
    for (const char* sql : {"DELETE FROM run_cells WHERE run = ?", "DELETE FROM runs WHERE id = ?"})
      c.query(sql).bind_int(1, run_id).run();
  });
  std::lock_guard lock(impl_->layers_mutex);
  impl_->layers.erase(layer);
}

}  // namespace maquette
