// The 3D content of a cell (a store's layers of kind mesh, instances and volume,
// content/content.h) as a GLB in the content's own frame, for the exports
// (formats/tiles3d/README.md, "3D content"):
// - mesh: the stored GLB itself (already Draco-compressed; nothing decoded or encoded again);
// - instances: instances_glb (EXT_mesh_gpu_instancing) of the cell's instances, each prototype
//   with its own materials (gltf/prototype_library.h) and each instance's colour;
// - volume: its grids meshed by the volume plug-in (libmaquette_vdb.so, plugins/vdb_content.h),
//   then written as a mesh layer's GLB (gltf/mesh_glb.h).
// An export places it with frame_to_frame (a node matrix, gltf/glb_merge.h).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "core/cell_id.h"
#include "gltf/local_frame.h"
#include "gltf/prototype_library.h"
#include "store/store.h"

namespace maquette {

// Not runtime/operator.h's CellContent (what an operator makes): one name for two types would break
// the one-definition rule.
struct CellGlb {
  std::string glb;  // in the east-north-up frame at `origin`, glTF axes (x east, y up, z south)
  EnuOrigin origin;
  // What the content covers: west, south, east, north (radians), min, max height (metres), the
  // bounding box of its vertices in its frame (instances: of spheres holding their prototypes)
  // taken to geodetic coordinates and padded by 1 cm.
  std::array<double, 6> region{};
};

class CellContentReader {
 public:
  explicit CellContentReader(const Store& store) : store_(store), prototypes_(store) {}

  // The content of `cell` in `layer` (at the layer's level, or its simplified copy at a coarser
  // level), nullopt when there is none (or a volume that meshes to nothing). Throws
  // maquette::Error naming the layer and cell for a corrupt blob, an unknown prototype or a cell
  // finer than the layer's level.
  std::optional<CellGlb> read(const std::string& layer, CellId cell);

 private:
  const Store& store_;
  PrototypeLibrary prototypes_;
};

// Throws maquette::Error unless `layer` is a layer of kind mesh, instances or volume.
void require_content_layer(const Store& store, const std::string& layer);

// The column-major 4x4 matrix taking glTF coordinates (x east, y up, z south) of the
// east-north-up frame at `from` to those of the frame `to`, computed in double precision through
// ECEF (content/enu_transform.h, in glTF axes): centimetres hold for content anywhere on the globe.
std::array<double, 16> frame_to_frame(const EnuOrigin& from, const LocalFrame& to);

}  // namespace maquette
