#include "content/content_overviews.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <map>
#include <mutex>

#include "content/content_blob.h"
#include "content/instances_codec.h"
#include "content/instances_thin.h"
#include "content/model_extent.h"
#include "core/error.h"
#include "core/grid.h"
#include "plugins/mesh_overviews.h"
#include "plugins/mesh_plugin.h"
#include "plugins/vdb_content.h"
#include "runtime/plugin.h"
#include "store/store.h"

namespace maquette {
namespace {

constexpr size_t kCellsPerTransaction = 64;  // bounds memory and the time the write lock is held

std::string cell_where(const std::string& layer, CellId cell) {
  return "layer '" + layer + "', cell " + cell.ToText();
}

// The horizontal extents of the model layers an instances layer places, each read from the store
// once per update, whichever thread asks first.
class ModelExtents {
 public:
  ModelExtents(const Store& store, const std::string& layer) : store_(store), layer_(layer) {}

  double operator()(const std::string& model) {
    const std::lock_guard lock(mutex_);
    if (const auto at = extents_.find(model); at != extents_.end()) return at->second;
    const std::string where = "model '" + model + "' in " + store_.path();
    const auto blob = store_.get_model(model);
    if (!blob)
      throw Error("layer '" + layer_ + "': prototype '" + model + "' is no model layer of " +
                  store_.path());
    return extents_[model] = model_horizontal_extent(*blob, where);
  }

 private:
  const Store& store_;
  const std::string& layer_;
  std::mutex mutex_;
  std::map<std::string, double> extents_;
};

// `wheres`: each child's place, for errors.
std::optional<std::string> instances_overview(const std::vector<std::string>& children,
                                              const std::vector<std::string>& wheres,
                                              const ContentLevel& level,
                                              ModelExtents& model_extents) {
  std::vector<InstancesContent> decoded;
  for (size_t i = 0; i < children.size(); ++i)
    decoded.push_back(unwrap_instances(children[i], wheres[i]));
  const InstancesContent thinned =
      thin_instances(decoded, level, [&](const std::string& m) { return model_extents(m); });
  if (thinned.size() == 0) return std::nullopt;
  return wrap_instances(thinned);
}

}  // namespace

ContentLevel content_level(CellId parent, int layer_level, const std::vector<EnuOrigin>& children) {
  const Grid& grid = default_grid();
  const LonLat centre = grid.centre(parent);
  double height = 0;
  for (const EnuOrigin& o : children) height += o.height;
  if (!children.empty()) height /= double(children.size());
  return {parent.level(),
          layer_level - parent.level(),
          {centre.lon, centre.lat, height},
          grid.level_info(parent.level(), 1).cell_side_m / kContentSamples};
}

void update_content_overviews(Store& store, const std::string& layer) {
  // Not require_layer: a writer builds the overviews before it marks its layer complete.
  const auto found = store.layer(layer);
  if (!found) throw Error("unknown layer '" + layer + "' in " + store.path());
  const LayerInfo& info = *found;
  const auto kind = layer_content_kind(info.kind);
  if (!kind)
    throw Error("cannot build content overviews of layer '" + layer + "' in " + store.path() +
                ": it is of kind " + std::string(layer_kind_name(info.kind)) +
                ", not a content layer (mesh, instances or volume)");
  ContentOverviewBuilder* plugin = nullptr;
  if (*kind == ContentKind::Mesh)
    plugin = plugin_function<ContentOverviewBuilder>(kMeshPlugin, kMeshOverviewEntry);
  else if (*kind == ContentKind::Volume)
    plugin = plugin_function<ContentOverviewBuilder>(kVdbPlugin, kVdbOverviewEntry);
  ModelExtents model_extents(store, layer);

  const auto build = [&](std::span<const CellId> cells,
                         std::span<const Store::ContentChildren> children,
                         std::span<std::optional<std::string>> overviews) {
    // Isolated, so that a worker waiting here never picks up an outer task that would take the
    // store's write lock, held by this call.
    tbb::this_task_arena::isolate([&] {
      tbb::parallel_for(size_t(0), cells.size(), [&](size_t i) {
        std::vector<std::string> blobs, wheres;
        std::vector<EnuOrigin> origins;
        for (int k = 0; k < 4; ++k)
          if (const auto& blob = children[i][k]) {
            wheres.push_back(cell_where(layer, cells[i].child(k)));
            origins.push_back(read_content_envelope(*blob, wheres.back()).origin);
            blobs.push_back(*blob);
          }
        const ContentLevel level = content_level(cells[i], info.level, origins);
        if (blobs.empty())
          overviews[i].reset();
        else if (plugin)
          plugin(blobs, level, "layer '" + layer + "', a child of cell " + cells[i].ToText(),
                 overviews[i]);
        else
          overviews[i] = instances_overview(blobs, wheres, level, model_extents);
      });
    });
  };
  for (int level = info.level - 1; level >= 0; --level)
    while (store.rebuild_stale_content(layer, level, kCellsPerTransaction, build) ==
           kCellsPerTransaction) {
    }
}

}  // namespace maquette
