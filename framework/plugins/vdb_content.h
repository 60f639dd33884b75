// The volume plug-in, libmaquette_vdb.so: volume blobs' payloads (VDB streams, formats/vdb)
// meshed for export and counted for the store, and volumes built for modules that must not link
// OpenVDB (voxel columns as a fog volume), opened by the commands that need them only, so
// no other command loads OpenVDB.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "content/content.h"
#include "content/content_overviews.h"
#include "vdb/column_fog.h"
#include "vdb/volume_mesh.h"

namespace maquette {

inline constexpr const char* kVdbPlugin = "libmaquette_vdb.so";
inline constexpr const char* kVdbMeshEntry = "maquette_vdb_mesh";
inline constexpr const char* kVdbStatsEntry = "maquette_vdb_stats";
inline constexpr const char* kVdbAnchorsEntry = "maquette_vdb_anchors";
inline constexpr const char* kVdbOverviewEntry = "maquette_vdb_overview";
inline constexpr const char* kVdbColumnFogEntry = "maquette_vdb_column_fog";

}  // namespace maquette

// volume_to_mesh (vdb/volume_mesh.h) into `mesh`. Errors name `where` (e.g. "layer lakes, cell
// N3021").
extern "C" void maquette_vdb_mesh(const maquette::VolumeContent& volume,
                                  const maquette::VolumeMeshSettings& settings,
                                  const std::string& where, maquette::MeshContent& mesh);
// volume_stats (vdb/volume_vdb.h) of the decoded volume into `stats`.
extern "C" void maquette_vdb_stats(const maquette::VolumeContent& volume, const std::string& where,
                                   maquette::ContentStats& stats);
// volume_anchors (vdb/volume_vdb.h) of the decoded volume into `anchors`, by grid.
extern "C" void maquette_vdb_anchors(const maquette::VolumeContent& volume,
                                     const std::string& where,
                                     std::vector<std::optional<std::array<double, 3>>>& anchors);
// A ContentOverviewBuilder (content/content_overviews.h): the children's volume blobs merged and
// resampled (vdb/volume_coarsen.h), encoded in the envelope of level.origin (grids and active
// voxels counted); nullopt when no grid is left.
extern "C" void maquette_vdb_overview(const std::vector<std::string>& children,
                                      const maquette::ContentLevel& level, const std::string& where,
                                      std::optional<std::string>& overview);
// columns_to_fog (vdb/column_fog.h) into `volume`: voxel columns as fog volumes.
extern "C" void maquette_vdb_column_fog(const std::vector<maquette::FogColumns>& bodies,
                                        const maquette::EnuOrigin& origin, const std::string& where,
                                        maquette::VolumeContent& volume);
