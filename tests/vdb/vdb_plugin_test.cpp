// The volume plug-in libmaquette_vdb.so (framework/plugins/vdb_content.h): what its entries give
// is what formats/vdb gives, and the program does not load OpenVDB to start.
#include <gtest/gtest.h>

#include "core/error.h"
#include "plugins/vdb_content.h"
#include "run_cli.h"
#include "runtime/plugin.h"
#include "vdb/volume_vdb.h"
#include "vdb_fixture.h"

namespace maquette::test {
namespace {

TEST(VdbPlugin, EntriesMeshAndCountVolumes) {
  const VolumeContent volume = encode_volume({sphere_level_set("lake")}, kVolumeOrigin);
  auto* mesh_entry = plugin_function<decltype(maquette_vdb_mesh)>(kVdbPlugin, kVdbMeshEntry);
  auto* stats_entry = plugin_function<decltype(maquette_vdb_stats)>(kVdbPlugin, kVdbStatsEntry);

  MeshContent mesh;
  mesh_entry(volume, VolumeMeshSettings{}, "layer lakes, cell N3021", mesh);
  const MeshContent direct = volume_to_mesh(volume, {}, "direct");
  ASSERT_EQ(mesh.objects.size(), 1u);
  EXPECT_EQ(mesh.origin, kVolumeOrigin);
  EXPECT_EQ(mesh.objects[0].positions, direct.objects[0].positions);
  EXPECT_EQ(mesh.objects[0].indices, direct.objects[0].indices);

  ContentStats stats;
  stats_entry(volume, "layer lakes, cell N3021", stats);
  EXPECT_EQ(stats, volume_stats(decode_volume(volume, "direct")));
  EXPECT_EQ(stats.objects, 1u);

  // Errors cross the plug-in's boundary as maquette::Error, naming the caller's `where`.
  try {
    stats_entry(VolumeContent{kVolumeOrigin, "not a vdb"}, "layer lakes, cell N3021", stats);
    ADD_FAILURE() << "counted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("layer lakes, cell N3021"), std::string::npos) << e.what();
  }
}

TEST(VdbPlugin, StartDoesNotLoadOpenVdb) {
  const std::string trace = start_trace();
  EXPECT_EQ(trace.find("libopenvdb"), std::string::npos) << trace;
  EXPECT_EQ(trace.find(kVdbPlugin), std::string::npos) << trace;
}

}  // namespace
}  // namespace maquette::test
