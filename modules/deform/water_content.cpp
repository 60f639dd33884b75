#include "water_content.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <set>
#include <utility>

#include "content/enu_transform.h"
#include "content/facet_normals.h"
#include "core/enu_frame.h"
#include "core/error.h"
#include "core/halo.h"
#include "core/parallel_chunks.h"
#include "core/unfolded_faces.h"
#include "plugins/vdb_content.h"
#include "runtime/plugin.h"
#include "stroke.h"
#include "water_mesh.h"
#include "water_stroke.h"

namespace maquette::deform {
namespace {

// The centre of the bounding box of a mesh's positions.
std::array<double, 3> box_centre(const std::vector<float>& positions) {
  std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < positions.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], double(positions[i]));
    hi[i % 3] = std::max(hi[i % 3], double(positions[i]));
  }
  return {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
}

// Mesh vertices per parallel chunk.
constexpr size_t kChunk = 4096;

}  // namespace

Material water_material(const std::array<double, 3>& srgb) {
  Material m;
  m.name = "water";
  for (size_t k = 0; k < 3; ++k) {
    const double c = srgb[k];  // IEC 61966-2-1's transfer function
    m.base_colour[k] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
  }
  m.metallic = 0;
  m.roughness = 0.2f;
  return m;
}

double LakeContent::surface_height(const Lake& lake, const MeshObject& object) {
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < lake.places.size(); ++i)
    if (lake.on_surface[i]) {
      sum += double(object.positions[3 * i + 2]);
      ++n;
    }
  return sum / double(n);
}

LakeContent::LakeContent(const StepContext& ctx, const Mosaic& input, Mosaic& output,
                         Material material)
    : ctx_(ctx), material_(std::move(material)), input_(input), output_(output) {}

CellId LakeContent::owner(const std::string& what, double lon, double lat) const {
  const CellId cell =
      ctx_.grid->cell_from_point({lon, lat}, output_.content.begin()->first.level());
  if (!output_.content.count(cell))
    throw Error(what + " is anchored at " + lonlat_text({lon, lat}) + ", outside the step's cells");
  return cell;
}

MeshObject LakeContent::object(const Lake& lake, const EnuOrigin& origin) const {
  const EnuFrame frame = enu_frame(origin);
  MeshObject object;
  object.provenance = lake.fog.mesh.provenance;
  object.indices = lake.fog.mesh.indices;
  object.positions.resize(3 * lake.places.size());
  parallel_chunks(lake.places.size(), kChunk, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      const auto& [lon, lat, height] = lake.places[i];
      const auto [x, y, z] = frame.to_enu(lon, lat, height);
      std::copy_n(std::array{float(x), float(y), float(z)}.begin(), 3, &object.positions[3 * i]);
    }
  });
  return object;
}

LakeContent::Lake LakeContent::placed(const VectorFeature& f, const BasinRaster& basin,
                                      const WaterBody& body, LakeBottom bottom) const {
  const LakeMesh mesh = lake_mesh(basin, body, bottom);
  // Corner (col, row) of the mosaic lies on the face holding it in the plane unfolded around
  // the mosaic's face (a lake may cross a face seam).
  const UnfoldedFaces plane(*ctx_.grid, input_.face, input_.level);
  Lake lake;
  lake.where = describe(f);
  lake.level = body.level;
  lake.places.resize(mesh.vertices.size());
  // In order within each chunk: a failure (of the geoid's grid) is the lowest vertex's.
  parallel_chunks(mesh.vertices.size(), kChunk, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      // A corner of a wet pixel, which has a place.
      const LakeVertex& v = mesh.vertices[i];
      const UnfoldedFaces::FacePoint at = *plane.from_anchor(
          double(input_.origin_col) + v.col - 0.5, double(input_.origin_row) + v.row - 0.5);
      const LonLat p = face_point_lonlat(*ctx_.grid, at.face, at.col, at.row, input_.level);
      lake.places[i] = {p.lon, p.lat, (*to_ellipsoid_)(p, v.height)};
    }
  });
  for (const LakeVertex& v : mesh.vertices) lake.on_surface.push_back(v.height == body.level);
  lake.fog.mesh.provenance = {
      uint64_t(f.id),
      f.id,
      "deform.water",
      {{"level", body.level}, {"area_m2", body.area_m2}, {"volume_m3", body.volume_m3}}};
  lake.fog.mesh.indices = mesh.indices;
  const double side = std::sqrt(basin.pixel_area_m2);
  const double deepest = double(*std::max_element(body.depth.begin(), body.depth.end()));
  lake.fog.voxel = {side, side, deepest / kVoxelsDeep};
  lake.fog.name = "water";
  return lake;
}

void LakeContent::add(const VectorFeature& f, const BasinRaster& basin, const WaterBody& body) {
  if (!to_ellipsoid_) to_ellipsoid_.emplace(ellipsoidal_heights(ctx_.input_layer("dem")));
  const CellContent& any = output_.content.begin()->second;
  if (any.wants("mesh")) {
    const Lake lake = placed(f, basin, body, LakeBottom::Flat);
    const auto& first = lake.places.front();
    const CellId cell = owner(lake.where + ": the lake's mesh", first[0], first[1]);
    MeshContent& content = output_.content.at(cell).mesh("mesh");
    if (content.materials.empty()) content.materials.push_back(material_);
    unlit_.push_back({cell, content.objects.size()});
    content.objects.push_back(object(lake, content.origin));
    content.objects.back().material = 0;
  }
  if (any.wants("volume")) lakes_.push_back(placed(f, basin, body, LakeBottom::Terrain));
}

void LakeContent::finish() {
  // Each side's failure kept, the volumes' rethrown first: the same error whatever the threads.
  std::exception_ptr normals_failed, volumes_failed;
  tbb::parallel_invoke(
      [&] {
        try {
          for (const Unlit& mesh : unlit_) {
            MeshObject& water = output_.content.at(mesh.cell).mesh("mesh").objects[mesh.object];
            water = with_facet_normals(water);
          }
        } catch (...) {
          normals_failed = std::current_exception();
        }
      },
      [&] {
        try {
          write_volumes();
        } catch (...) {
          volumes_failed = std::current_exception();
        }
      });
  if (volumes_failed) std::rethrow_exception(volumes_failed);
  if (normals_failed) std::rethrow_exception(normals_failed);
}

void LakeContent::write_volumes() {
  if (lakes_.empty()) return;
  static auto* const fog_of =
      plugin_function<decltype(maquette_vdb_mesh_fog)>(kVdbPlugin, kVdbMeshFogEntry);
  static auto* const anchors_of =
      plugin_function<decltype(maquette_vdb_anchors)>(kVdbPlugin, kVdbAnchorsEntry);
  // First guess of each lake's owner: the cell of its mesh's bounding-box centre, in a frame at
  // its first vertex; the grid's active voxels are within a voxel of that box.
  std::vector<CellId> owners;
  for (const Lake& lake : lakes_) {
    const auto& first = lake.places.front();
    const EnuOrigin origin{first[0], first[1], first[2]};
    const auto [x, y, z] = box_centre(object(lake, origin).positions);
    const GeodeticPoint p = enu_frame(origin).to_geodetic(x, y, z);
    owners.push_back(owner(lake.where + ": the lake's volume", p.lon, p.lat));
  }
  // Built in each owner's frame; a grid whose anchor falls in another cell (a lake centred within
  // a voxel of a cell's edge) moves there once, and the volumes are built again (the runner then
  // checks every anchor).
  for (int pass = 0; pass < 2; ++pass) {
    bool moved = false;
    for (const CellId cell : std::set<CellId>(owners.begin(), owners.end())) {
      VolumeContent& volume = output_.content.at(cell).volume("volume");
      std::vector<FogBody> bodies;
      std::vector<size_t> which;
      for (size_t i = 0; i < lakes_.size(); ++i)
        if (owners[i] == cell) {
          FogBody& fog = bodies.emplace_back(lakes_[i].fog);
          fog.mesh = object(lakes_[i], volume.origin);
          fog.corner[2] = surface_height(lakes_[i], fog.mesh);
          which.push_back(i);
        }
      fog_of(bodies, volume.origin, "deform.water, cell " + cell.ToText(), volume);
      if (pass > 0) continue;
      std::vector<std::optional<std::array<double, 3>>> anchors;
      anchors_of(volume, "deform.water, cell " + cell.ToText(), anchors);
      const EnuFrame frame = enu_frame(volume.origin);
      for (size_t k = 0; k < anchors.size(); ++k) {
        if (!anchors[k]) continue;
        const GeodeticPoint p =
            frame.to_geodetic((*anchors[k])[0], (*anchors[k])[1], (*anchors[k])[2]);
        const CellId at = owner(lakes_[which[k]].where + ": the lake's volume", p.lon, p.lat);
        moved = moved || at != cell;
        owners[which[k]] = at;
      }
    }
    if (!moved) return;
    for (auto& [cell, content] : output_.content)
      if (content.volumes.count("volume")) content.volume("volume").vdb.clear();
  }
}

}  // namespace maquette::deform
