// The volume plug-in's entry points: formats/vdb.
#include "plugins/vdb_content.h"

#include "content/content_blob.h"
#include "vdb/volume_coarsen.h"
#include "vdb/volume_vdb.h"

void maquette_vdb_mesh(const maquette::VolumeContent& volume,
                       const maquette::VolumeMeshSettings& settings, const std::string& where,
                       maquette::MeshContent& mesh) {
  mesh = maquette::volume_to_mesh(volume, settings, where);
}

void maquette_vdb_stats(const maquette::VolumeContent& volume, const std::string& where,
                        maquette::ContentStats& stats) {
  stats = maquette::volume_stats(maquette::decode_volume(volume, where));
}

void maquette_vdb_anchors(const maquette::VolumeContent& volume, const std::string& where,
                          std::vector<std::optional<std::array<double, 3>>>& anchors) {
  anchors = maquette::volume_anchors(maquette::decode_volume(volume, where));
}

void maquette_vdb_overview(const std::vector<std::string>& children,
                           const maquette::ContentLevel& level, const std::string& where,
                           std::optional<std::string>& overview) {
  using namespace maquette;
  std::vector<VolumeContent> volumes;
  for (const std::string& blob : children)
    volumes.push_back(
        {read_content_envelope(blob, where).origin, std::string(content_payload(blob))});
  const openvdb::GridPtrVec grids = coarsen_volumes(volumes, level, where);
  overview.reset();
  if (grids.empty()) return;
  ContentEnvelope envelope;
  envelope.kind = ContentKind::Volume;
  envelope.origin = level.origin;
  envelope.stats = volume_stats(grids);
  overview = wrap_content(envelope, encode_volume(grids, level.origin).vdb);
}

void maquette_vdb_column_fog(const std::vector<maquette::FogColumns>& bodies,
                             const maquette::EnuOrigin& origin, const std::string& where,
                             maquette::VolumeContent& volume) {
  volume = maquette::columns_to_fog(bodies, origin, where);
}
