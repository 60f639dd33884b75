// deform.water's 3D content: each lake's closed mesh with a flat bottom (water_mesh.h: the prism
// of its outline, the bottom under the terrain) on the mesh port, with facet normals
// (content/facet_normals.h: CesiumJS draws a mesh without normals unlit) and a water material
// (water_material), and its fog volume on the volume port, built by the volume plug-in
// (plugins/vdb_content.h: columns_to_fog of the lake's depth raster, water_columns.h, the
// water's own volume) so that the module does not link OpenVDB. Each object is written by the
// cell that owns its anchor: the mesh's first vertex, the volume grid's centre of its active
// voxels (content/content.h).
//
// Heights are the DEM's taken to the ellipsoid with its layer's recorded vertical datum
// (gdal/vertical_datum.h), as the terrain export takes them, so a lake sits on the exported
// terrain of an EGM96 DEM as of an ellipsoidal one.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/unfolded_faces.h"
#include "gdal/vertical_datum.h"
#include "runtime/operator.h"
#include "water_body.h"
#include "water_columns.h"
#include "water_mesh.h"

namespace maquette::deform {

// A cartographer's water blue-green by default.
inline constexpr std::array<double, 3> kWaterSrgb{0.25, 0.45, 0.55};

// The material "water" of colour `srgb` (sRGB components in 0..1, unchecked) as glTF's linear
// factors: opaque (the lake is a closed mesh: a translucent top would show its walls and bottom),
// not metallic, roughness 0.2 so that its surface catches the sun's highlight.
Material water_material(const std::array<double, 3>& srgb);

class LakeContent {
 public:
  // The content of `output` (deform.water's output mosaic) for the lakes of `input`'s mosaic,
  // their meshes of `material`.
  LakeContent(const StepContext& ctx, const Mosaic& input, Mosaic& output, Material material);

  // The lake of water stroke `f` (a non-empty body of `basin`), kept for finish (of `basin`, its
  // size and pixel area only: the raster need not outlive the call).
  void add(const VectorFeature& f, const BasinRaster& basin, const WaterBody& body);

  // Once the lakes are added, their content, for the ports the step maps: the meshes beside the
  // volumes (TBB: each side in parallel too, and the volumes' serial writing beside the meshes'
  // work; the same content for any thread count). The meshes: each lake's added to its owner
  // cell's mesh port, in the lakes' order, with its facet normals. The volumes: one VDB stream
  // per owner cell, a fog grid "water" per lake (horizontal voxels of a pixel's side, vertical
  // ones of the lake's greatest depth over kVoxelsDeep, a layer of voxel faces at the water's
  // surface, so that no voxel layer is cut by it). A failure of the meshes is thrown before one
  // of the volumes.
  void finish();

  static constexpr int kVoxelsDeep = 32;

 private:
  // A lake added: its body and what its content is made of.
  struct Lake {
    BasinRaster basin;  // its size and pixel area only
    WaterBody body;
    double bottom = 0;  // its mesh's flat bottom (lake_flat_bottom)
    ObjectProvenance provenance;
    std::string where;  // "feature 7 (tool water)"
  };
  // A lake's flat-bottomed mesh, its vertices placed: lon, lat, ellipsoidal height.
  struct PlacedMesh {
    std::vector<std::array<double, 3>> places;
    std::vector<uint32_t> indices;  // the mesh's triangles
  };
  // A lake's volume: the places (lon, lat, ellipsoidal height) of its wet pixels' centres on the
  // water's surface, then of the seed pixel's east, west, south and north sides' midpoints (its
  // lattice's axes in a frame).
  struct Column {
    const Lake* lake = nullptr;
    std::vector<std::array<double, 3>> places;
  };
  PlacedMesh placed(const Lake& lake) const;
  Column columns(const Lake& lake) const;
  // The place (lon, lat, ellipsoidal height) of the mosaic's pixel-centre coordinates (col, row)
  // (corners at half-integers) in `plane` (unfolded around the mosaic's face) at `height` of the
  // DEM's datum; the point lies on a wet pixel (which has a place).
  std::array<double, 3> place(const UnfoldedFaces& plane, double col, double row,
                              double height) const;
  // Each lake's mesh with its normals on its owner cell's mesh port, in the lakes' order.
  void add_meshes();
  void write_volumes();
  MeshObject object(const Lake& lake, const PlacedMesh& mesh, const EnuOrigin& origin) const;
  // The columns of `column` in the frame of `origin` (water_columns.h).
  static FogColumns fog(const Column& column, const EnuOrigin& origin);
  CellId owner(const std::string& what, double lon, double lat) const;

  const StepContext& ctx_;
  const Material material_;
  // The DEM's heights to the ellipsoid, set up with the first lake (PROJ and its geoid grid are
  // needed only for content).
  std::optional<EllipsoidalHeights> to_ellipsoid_;
  const Mosaic& input_;
  Mosaic& output_;
  std::vector<Lake> lakes_;
};

}  // namespace maquette::deform
