// Stale marks of content layers: the store's half of update_content_overviews
// (content/content_overviews.h), which builds the simplified content itself.
#include "store/store_impl.h"

namespace maquette {

size_t Store::rebuild_stale_content(const std::string& layer, int level, size_t limit,
                                    const BuildContentOverviews& build) {
  Impl& d = *impl_;
  const LayerEntry e = d.require(layer);
  const std::string where = "cannot build overviews of layer '" + layer + "' in " + d.path + ": ";
  if (!layer_content_kind(e.info.kind))
    throw Error(where + "it is of kind " + std::string(layer_kind_name(e.info.kind)) +
                ", not a content layer (mesh, instances or volume)");
  if (level < 0 || level >= e.info.level)
    throw Error(where + "level " + std::to_string(level) + " not in [0, " +
                std::to_string(e.info.level - 1) + "]");
  size_t taken = 0;
  d.write([&](sqlite::Connection& c) {
    const auto [cells, children] = read_stale_cells(c, e, level, limit);
    std::vector<std::optional<std::string>> overviews(cells.size());
    build(cells, children, overviews);
    for (size_t i = 0; i < cells.size(); ++i) {
      // Nothing: its children hold nothing, and an overview it had goes.
      write_content(c, content_write(e, d.path, cells[i],
                                     overviews[i] ? std::optional<std::string_view>(*overviews[i])
                                                  : std::nullopt));
      c.query("DELETE FROM stale_overviews WHERE layer = ? AND level = ? AND cell = ?")
          .bind_int(1, e.id)
          .bind_int(2, level)
          .bind_int(3, int64_t(cells[i].id()))
          .run();
      mark_parent_stale(c, e.id, cells[i]);
    }
    taken = cells.size();
  });
  return taken;
}

}  // namespace maquette
