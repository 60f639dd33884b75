// The blobs of content and model layers as rows of the `content` table (schema version 4): a blob
// is its parts in order, each at most a page's eighth, so that blobs of a few kB pack whole pages
// (a row of a WITHOUT ROWID table keeps at most ~4 kB in its page and spills the rest into
// overflow pages of its own).
#include "store/store_impl.h"

namespace maquette {
namespace {

// The rows of content and model blobs in a store of version 3 or older (tiles at the layer's
// level, overviews below it; a model at level 0, cell 0), each as one part.
constexpr const char* kVersion3ContentRows = R"sql(
SELECT t.layer, l.level, t.cell, 0, t.blob FROM main.tiles t JOIN main.layers l ON l.id = t.layer
  WHERE l.kind IN ('mesh', 'instances', 'volume', 'model')
UNION ALL
SELECT o.layer, o.level, o.cell, 0, o.blob FROM main.overviews o
  JOIN main.layers l ON l.id = o.layer WHERE l.kind IN ('mesh', 'instances', 'volume')
)sql";

// Parts of at most this size: eight rows, with their keys and the page's header, fit in a page
// (16 KiB pages: 2,016 bytes), and no part overflows (a row of up to ~4 kB stays in its page).
size_t part_bytes(sqlite::Connection& c) {
  auto q = c.query("PRAGMA page_size");
  q.step();
  return size_t(q.int64(0)) / 8 - 32;
}

std::string_view text_of(std::span<const std::byte> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

}  // namespace

void write_content_blob(sqlite::Connection& c, int64_t layer, int level, int64_t cell,
                        std::string_view blob) {
  delete_content_blob(c, layer, level, cell);
  const size_t part = part_bytes(c);
  for (size_t k = 0; k * part < blob.size(); ++k)
    c.query("INSERT INTO content(layer, level, cell, part, data) VALUES(?, ?, ?, ?, ?)")
        .bind_int(1, layer)
        .bind_int(2, level)
        .bind_int(3, cell)
        .bind_int(4, int64_t(k))
        .bind_blob(5, std::as_bytes(std::span(blob.substr(k * part, part))))
        .run();
}

bool delete_content_blob(sqlite::Connection& c, int64_t layer, int level, int64_t cell) {
  c.query("DELETE FROM content WHERE layer = ? AND level = ? AND cell = ?")
      .bind_int(1, layer)
      .bind_int(2, level)
      .bind_int(3, cell)
      .run();
  return c.changes() > 0;
}

std::optional<std::string> read_content_blob(sqlite::Connection& c, int64_t layer, int level,
                                             int64_t cell) {
  std::optional<std::string> blob;
  read_content_blobs(c, layer, level, cell, cell,
                     [&](int64_t, std::string&& b) { blob = std::move(b); });
  return blob;
}

void read_content_blobs(sqlite::Connection& c, int64_t layer, int level, int64_t first,
                        int64_t last, const std::function<void(int64_t, std::string&&)>& visit) {
  auto q = c.query(
      "SELECT cell, data FROM content WHERE layer = ? AND level = ? AND cell BETWEEN ? AND ? "
      "ORDER BY cell, part");
  q.bind_int(1, layer).bind_int(2, level).bind_int(3, first).bind_int(4, last);
  std::optional<int64_t> cell;
  std::string blob;
  while (q.step()) {
    const int64_t at = q.int64(0);
    if (cell && *cell != at) visit(*cell, std::move(blob));
    if (cell != at) blob.clear();
    cell = at;
    blob += text_of(q.blob(1));
  }
  if (cell) visit(*cell, std::move(blob));
}

void move_content_rows(sqlite::Connection& c) {
  {
    // Writing `content` while reading tiles and overviews, other tables, is safe in SQLite.
    auto q = c.query(kVersion3ContentRows);
    while (q.step())
      write_content_blob(c, q.int64(0), int(q.int64(1)), q.int64(2), text_of(q.blob(4)));
  }
  c.exec(
      "DELETE FROM tiles WHERE layer IN (SELECT id FROM layers WHERE kind IN "
      "('mesh', 'instances', 'volume', 'model'));"
      "DELETE FROM overviews WHERE layer IN (SELECT id FROM layers WHERE kind IN "
      "('mesh', 'instances', 'volume'));");
}

void view_content_rows(sqlite::Connection& c) {
  c.exec((std::string("CREATE TEMP VIEW content(layer, level, cell, part, data) AS ") +
          kVersion3ContentRows)
             .c_str());
}

}  // namespace maquette
