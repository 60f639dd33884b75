// Run records: pipelines being executed and the cells each step has finished, for --resume.
#include <cstdio>

#include "store/store_impl.h"

namespace maquette {
namespace {

// FNV-1a 64 of the canonical dump (nlohmann::json keeps object keys sorted), as 16 hex digits.
std::string pipeline_hash(const nlohmann::json& pipeline) {
  uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char ch : pipeline.dump()) h = (h ^ ch) * 0x100000001b3ULL;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

}  // namespace

int64_t Store::begin_run(const nlohmann::json& pipeline) {
  int64_t id = 0;
  impl_->write([&](sqlite::Connection& c) {
    c.query(
         "INSERT INTO runs(pipeline, pipeline_hash, status, started) "
         "VALUES(?, ?, 'running', strftime('%Y-%m-%dT%H:%M:%fZ'))")
        .bind_text(1, pipeline.dump())
        .bind_text(2, pipeline_hash(pipeline))
        .run();
    id = c.last_insert_rowid();
  });
  return id;
}

std::optional<int64_t> Store::latest_unfinished_run(const nlohmann::json& pipeline) const {
  auto conn = impl_->readers.borrow();
  auto q = conn->query(
      "SELECT id FROM runs WHERE pipeline_hash = ? AND pipeline = ? AND "
      "(status = 'running' OR status LIKE 'failed%') ORDER BY id DESC LIMIT 1");
  if (!q.bind_text(1, pipeline_hash(pipeline)).bind_text(2, pipeline.dump()).step())
    return std::nullopt;
  return q.int64(0);
}

std::vector<CellId> Store::done_cells(int64_t run_id, int step) const {
  std::vector<CellId> cells;
  for (int64_t key : done_keys(run_id, step)) cells.emplace_back(uint64_t(key));
  return cells;
}

std::vector<int64_t> Store::done_keys(int64_t run_id, int step) const {
  auto conn = impl_->readers.borrow();
  auto q = conn->query("SELECT cell FROM run_cells WHERE run = ? AND step = ? ORDER BY cell");
  q.bind_int(1, run_id).bind_int(2, step);
  std::vector<int64_t> keys;
  while (q.step()) keys.push_back(q.int64(0));
  return keys;
}

void Store::finish_run(int64_t run_id, const std::string& status) {
  if (status.empty() || status == "running")
    throw Error("a finished run needs a status like 'ok' or 'failed: reason', not '" + status +
                "'");
  impl_->write([&](sqlite::Connection& c) {
    c.query("UPDATE runs SET status = ?, finished = strftime('%Y-%m-%dT%H:%M:%fZ') WHERE id = ?")
        .bind_text(1, status)
        .bind_int(2, run_id)
        .run();
    if (c.changes() == 0) throw Error("no run " + std::to_string(run_id) + " in " + impl_->path);
    if (status == "ok")
      c.query("DELETE FROM incomplete_layers WHERE run = ?").bind_int(1, run_id).run();
  });
}

}  // namespace maquette
