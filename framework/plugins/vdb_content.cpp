// The volume plug-in's entry points: formats/vdb.
#include "plugins/vdb_content.h"

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
