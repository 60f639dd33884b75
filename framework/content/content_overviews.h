// Coarser levels of content layers (store/README.md, "Content overviews"): a parent cell's
// overview is its four children's content merged into the parent's frame and simplified, so
// that a view of a whole town from afar reads few, light blobs.
//
// - Frame: the parent's origin is its cell's centre (default_grid) at the mean of its present
//   children's origin heights (summed in child digit order); every position is re-expressed
//   through ECEF in double (enu_transform.h) and rounded to float once.
// - Instances (instances_thin.h): the children's instances that the thinning rule keeps at the
//   parent's sample (fewer where they are smaller than it, those kept widened so that the cover
//   stays), bit for bit but for their positions and rotations, re-expressed in the parent frame,
//   and their widened scales.
// - Meshes (plug-in libmaquette_mesh.so, gltf/mesh_simplify.h): each object simplified to about
//   a quarter of its triangles within half the level's sample, objects smaller than the sample
//   dropped, textures halved.
// - Volumes (plug-in libmaquette_vdb.so, vdb/volume_coarsen.h): grids of the same name merged,
//   resampled at twice the voxel size.
// A parent whose children hold nothing after simplification gets no overview (a stored one is
// removed); levels go down to 0. Deterministic: every blob is a function of its children's
// blobs and its cell only, whatever the order the cells were written in or the threads.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "content/content.h"
#include "core/cell_id.h"

namespace maquette {

class Store;

// What simplifying into a parent cell at `level` may do.
struct ContentLevel {
  int level = 0;        // the parent's level
  int depth = 1;        // levels between the parent and the layer's level (>= 1)
  EnuOrigin origin;     // the parent's frame (above)
  double sample_m = 0;  // the level's sample: default_grid's mean cell side / kContentSamples
};

// The samples across a cell: a coarse level's content is meant to be seen as a tile of this
// many pixels across, as raster tiles are.
inline constexpr int kContentSamples = 256;

ContentLevel content_level(CellId parent, int layer_level, const std::vector<EnuOrigin>& children);

// A plug-in's builder of a parent's overview blob from its children's blobs (present children
// only, in digit order): nullopt when nothing is left. Errors name `where`.
using ContentOverviewBuilder = void(const std::vector<std::string>& children,
                                    const ContentLevel& level, const std::string& where,
                                    std::optional<std::string>& overview);

// Rebuilds the overviews of layer `layer` (kind mesh, instances or volume) above every cell
// written since the last call (the store's stale marks: Store::rebuild_stale_content), level by
// level down to 0; a layer still marked incomplete (its writer calls this before it is whole)
// is built too. Throws maquette::Error naming the layer for an unknown layer or one of another
// kind, or a child blob that does not decode (naming its cell; nothing of that transaction is
// written).
void update_content_overviews(Store& store, const std::string& layer);

}  // namespace maquette
