#include "water_content.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <set>
#include <span>
#include <tuple>
#include <utility>

#include "content/enu_transform.h"
#include "content/facet_normals.h"
#include "core/enu_frame.h"
#include "core/error.h"
#include "core/halo.h"
#include "core/parallel_chunks.h"
#include "core/srgb.h"
#include "core/unfolded_faces.h"
#include "plugins/vdb_content.h"
#include "runtime/plugin.h"
#include "stroke.h"
#include "water_mesh.h"
#include "water_stroke.h"

namespace maquette::deform {
namespace {

// The centre of the bounding box of places (lon, lat, height) in the frame at the first one.
GeodeticPoint box_centre(const std::vector<std::array<double, 3>>& places) {
  const auto& first = places.front();
  const EnuFrame frame = enu_frame({first[0], first[1], first[2]});
  std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const auto& [lon, lat, height] : places) {
    const auto [x, y, z] = frame.to_enu(lon, lat, height);
    lo = {std::min(lo[0], x), std::min(lo[1], y), std::min(lo[2], z)};
    hi = {std::max(hi[0], x), std::max(hi[1], y), std::max(hi[2], z)};
  }
  return frame.to_geodetic((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
}

// The lake's provenance: its stroke, level, area and volume.
ObjectProvenance lake_provenance(const VectorFeature& f, const WaterBody& body) {
  return {uint64_t(f.id),
          f.id,
          "deform.water",
          {{"level", body.level}, {"area_m2", body.area_m2}, {"volume_m3", body.volume_m3}}};
}

// Mesh vertices per parallel chunk.
constexpr size_t kChunk = 4096;

}  // namespace

Material water_material(const std::array<double, 3>& srgb) {
  Material m;
  m.name = "water";
  for (size_t k = 0; k < 3; ++k) {
    m.base_colour[k] = float(srgb_to_linear(srgb[k]));
  }
  m.metallic = 0;
  m.roughness = 0.2f;
  return m;
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

MeshObject LakeContent::object(const Lake& lake, const PlacedMesh& mesh,
                               const EnuOrigin& origin) const {
  const EnuFrame frame = enu_frame(origin);
  MeshObject object;
  object.provenance = lake.provenance;
  object.indices = mesh.indices;
  object.positions.resize(3 * mesh.places.size());
  parallel_chunks(mesh.places.size(), kChunk, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      const auto& [lon, lat, height] = mesh.places[i];
      const auto [x, y, z] = frame.to_enu(lon, lat, height);
      std::copy_n(std::array{float(x), float(y), float(z)}.begin(), 3, &object.positions[3 * i]);
    }
  });
  return object;
}

std::array<double, 3> LakeContent::place(const UnfoldedFaces& plane, double col, double row,
                                         double height) const {
  const UnfoldedFaces::FacePoint at =
      *plane.from_anchor(double(input_.origin_col) + col, double(input_.origin_row) + row);
  const LonLat p = face_point_lonlat(*ctx_.grid, at.face, at.col, at.row, input_.level);
  return {p.lon, p.lat, (*to_ellipsoid_)(p, height)};
}

LakeContent::PlacedMesh LakeContent::placed(const Lake& lake) const {
  LakeMesh mesh = lake_mesh(lake.basin, lake.body, lake.bottom);
  // Corner (col, row) of the mosaic lies on the face holding it in the plane unfolded around
  // the mosaic's face (a lake may cross a face seam).
  const UnfoldedFaces plane(*ctx_.grid, input_.face, input_.level);
  PlacedMesh placed;
  placed.places.resize(mesh.vertices.size());
  // In order within each chunk: a failure (of the geoid's grid) is the lowest vertex's.
  parallel_chunks(mesh.vertices.size(), kChunk, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      // A corner of a wet pixel.
      const LakeVertex& v = mesh.vertices[i];
      placed.places[i] = place(plane, v.col - 0.5, v.row - 0.5, v.height);
    }
  });
  placed.indices = std::move(mesh.indices);
  return placed;
}

LakeContent::Column LakeContent::columns(const Lake& lake) const {
  const UnfoldedFaces plane(*ctx_.grid, input_.face, input_.level);
  const WaterBody& body = lake.body;
  Column column{&lake, {}};
  const size_t wet = body.wet.size();
  const int64_t width = lake.basin.width;
  const double seed_col = double(body.seed % width), seed_row = double(body.seed / width);
  const std::array<std::array<double, 2>, 4> sides{{{seed_col + 0.5, seed_row},
                                                    {seed_col - 0.5, seed_row},
                                                    {seed_col, seed_row + 0.5},
                                                    {seed_col, seed_row - 0.5}}};
  column.places.resize(wet + sides.size());
  parallel_chunks(column.places.size(), kChunk, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i)
      column.places[i] = i < wet ? place(plane, double(body.wet[i] % width),
                                         double(body.wet[i] / width), body.level)
                                 : place(plane, sides[i - wet][0], sides[i - wet][1], body.level);
  });
  return column;
}

FogColumns LakeContent::fog(const Column& column, const EnuOrigin& origin) {
  const EnuFrame frame = enu_frame(origin);
  const WaterBody& body = column.lake->body;
  const size_t wet = body.wet.size();
  std::vector<std::array<double, 3>> at(column.places.size());
  parallel_chunks(at.size(), kChunk, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      const auto& [lon, lat, height] = column.places[i];
      const auto [x, y, z] = frame.to_enu(lon, lat, height);
      at[i] = {x, y, z};
    }
  });
  const auto& [east, west, south, north] = std::tie(at[wet], at[wet + 1], at[wet + 2], at[wet + 3]);
  const size_t seed =
      size_t(std::lower_bound(body.wet.begin(), body.wet.end(), body.seed) - body.wet.begin());
  const PixelLattice lattice{at[seed],
                             {east[0] - west[0], east[1] - west[1], east[2] - west[2]},
                             {south[0] - north[0], south[1] - north[1], south[2] - north[2]}};
  FogColumns fog =
      lake_columns(column.lake->basin, body, lattice, std::span(at).first(wet), kVoxelsDeep);
  fog.provenance = column.lake->provenance;
  return fog;
}

void LakeContent::add(const VectorFeature& f, const BasinRaster& basin, const WaterBody& body) {
  if (!to_ellipsoid_) to_ellipsoid_.emplace(ellipsoidal_heights(ctx_.input_layer("dem")));
  lakes_.push_back({{basin.width, basin.height, {}, {}, basin.pixel_area_m2},
                    body,
                    lake_flat_bottom(basin, body),
                    lake_provenance(f, body),
                    describe(f)});
}

void LakeContent::finish() {
  if (lakes_.empty()) return;
  const CellContent& any = output_.content.begin()->second;
  // Each side's failure kept, the meshes' rethrown first: the same error whatever the threads.
  std::exception_ptr meshes_failed, volumes_failed;
  tbb::parallel_invoke(
      [&] {
        try {
          if (any.wants("mesh")) add_meshes();
        } catch (...) {
          meshes_failed = std::current_exception();
        }
      },
      [&] {
        try {
          if (any.wants("volume")) write_volumes();
        } catch (...) {
          volumes_failed = std::current_exception();
        }
      });
  if (meshes_failed) std::rethrow_exception(meshes_failed);
  if (volumes_failed) std::rethrow_exception(volumes_failed);
}

void LakeContent::add_meshes() {
  for (const Lake& lake : lakes_) {
    const PlacedMesh mesh = placed(lake);
    const auto& first = mesh.places.front();
    const CellId cell = owner(lake.where + ": the lake's mesh", first[0], first[1]);
    MeshContent& content = output_.content.at(cell).mesh("mesh");
    if (content.materials.empty()) content.materials.push_back(material_);
    content.objects.push_back(with_facet_normals(object(lake, mesh, content.origin)));
    content.objects.back().material = 0;
  }
}

void LakeContent::write_volumes() {
  std::vector<Column> lakes;
  for (const Lake& lake : lakes_) lakes.push_back(columns(lake));
  static auto* const fog_of =
      plugin_function<decltype(maquette_vdb_column_fog)>(kVdbPlugin, kVdbColumnFogEntry);
  static auto* const anchors_of =
      plugin_function<decltype(maquette_vdb_anchors)>(kVdbPlugin, kVdbAnchorsEntry);
  // First guess of each lake's owner: the cell of the bounding-box centre of its wet pixels'
  // centres, in a frame at the first; the grid's active voxels are within a voxel of that box.
  std::vector<CellId> owners;
  for (const Column& lake : lakes) {
    const GeodeticPoint p = box_centre(lake.places);
    owners.push_back(owner(lake.lake->where + ": the lake's volume", p.lon, p.lat));
  }
  // Built in each owner's frame; a grid whose anchor falls in another cell (a lake centred within
  // a voxel of a cell's edge) moves there once, and the volumes are built again (the runner then
  // checks every anchor).
  for (int pass = 0; pass < 2; ++pass) {
    bool moved = false;
    for (const CellId cell : std::set<CellId>(owners.begin(), owners.end())) {
      VolumeContent& volume = output_.content.at(cell).volume("volume");
      std::vector<FogColumns> bodies;
      std::vector<size_t> which;
      for (size_t i = 0; i < lakes.size(); ++i)
        if (owners[i] == cell) {
          bodies.push_back(fog(lakes[i], volume.origin));
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
        const CellId at = owner(lakes[which[k]].lake->where + ": the lake's volume", p.lon, p.lat);
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
