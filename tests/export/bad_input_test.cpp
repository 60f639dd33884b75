// Bad export requests: a clear message, a non-zero exit and no output file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "export_fixture.h"
#include "run_cli.h"
#include "store/store.h"

namespace maquette::test {
namespace {

void expect_refused(const std::string& args, const std::string& message,
                    const std::string& out_name = "out.tif") {
  const std::string dir = temp_dir();
  const std::string out = out_name[0] == '/' ? out_name : dir + "/" + out_name;
  const CliResult r =
      run_maquette("export gtiff " + export_fixture().store_path + " " + out + " " + args);
  EXPECT_NE(r.exit_code, 0) << args;
  EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
  EXPECT_FALSE(std::filesystem::exists(out)) << args;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    ADD_FAILURE() << "left behind: " << entry.path();
}

TEST(ExportBadInput, UnknownLayer) { expect_refused("--layer nope", "unknown layer 'nope'"); }

TEST(ExportBadInput, NoTilesInTheRegion) {
  expect_refused("--layer dem --bbox -100 -50 -99 -49", "no tiles in the region");
  expect_refused("--layer dem --cells S0", "no tiles in the region");
}

TEST(ExportBadInput, BadCrs) {
  expect_refused("--layer dem --crs foo", "bad --crs 'foo'");
  expect_refused("--layer dem --crs EPSG:abc", "bad --crs 'EPSG:abc'");
  expect_refused("--layer dem --crs EPSG:99999999", "no such EPSG code");
}

TEST(ExportBadInput, CrsWithoutTransformationIsNamed) {
  // EGM96 height: a vertical CRS, no transformation from it to lon/lat.
  expect_refused("--layer dem --crs EPSG:5773", "cannot transform --crs EPSG:5773 to lon/lat");
}

TEST(ExportBadInput, LevelFinerThanTheLayer) {
  expect_refused("--layer dem --level 9", "--level 9 must be in 0..6");
}

TEST(ExportBadInput, MaxMibIsAWholeNumberOfMib) {
  for (const char* bad : {"abc", "1.5", "-5", "9000000000000"})
    expect_refused(
        std::string("--layer dem --max-mib ") + bad,
        std::string("--max-mib: expected a whole number of MiB in 0..1073741824, got '") + bad +
            "'");
}

TEST(ExportBadInput, UnwritableOutput) {
  expect_refused("--layer dem", "cannot create", "/nonexistent-dir/out.tif");
  expect_refused("--layer dem --crs EPSG:4326", "/nonexistent-dir/out.tif",
                 "/nonexistent-dir/out.tif");
}

// The store given as OUT (however spelled) was replaced by the picture, exit 0; a file given as
// tiles3d's or drc's directory, the store too, was removed by the failed export's clean-up (an
// audit's finds). Each is refused and left as it was.
TEST(ExportBadInput, TheStoreOrAFileGivenAsTheOutputIsLeftAsItWas) {
  const std::string dir = temp_dir(), store = dir + "/s.mqt", notes = dir + "/notes.txt";
  std::filesystem::copy_file(export_fixture().store_path, store);
  std::ofstream(notes) << "precious\n";
  const std::string before = file_fingerprint(store), notes_before = file_fingerprint(notes);
  for (const std::string& args :
       {"png " + store + " " + store + " --layer dem",
        "gtiff " + store + " " + store + " --layer dem",
        "png " + store + " " + dir + "/./s.mqt --layer dem",
        "tiles3d " + store + " " + store + " --dem dem",
        "drc " + store + " " + store + " --dem dem --cells " +
            Store::open(store, Store::Mode::ReadOnly)->tile_cells("dem").front().ToText()}) {
    const CliResult r = run_maquette("export " + args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_NE(r.err.find("is the store " + store + ": it would be replaced"), std::string::npos)
        << args << ": " << r.err;
    EXPECT_EQ(file_fingerprint(store), before) << args;
  }
  const CliResult r = run_maquette("export tiles3d " + store + " " + notes + " --dem dem");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(notes), std::string::npos) << r.err;
  EXPECT_EQ(file_fingerprint(notes), notes_before);
}

// --levels takes whole levels A <= B (-5..-1 wrote the default tileset, 9..10x was taken); a
// cell given twice to glb is meshed once (it was twice: a file of twice the size).
TEST(ExportBadInput, LevelsAreWholeAndInOrderARepeatedCellCountsOnce) {
  const std::string dir = temp_dir(), store = export_fixture().store_path;
  for (const char* levels : {"-5..-1", "3..-1", "9..10x", "5..3", "4", "4..40"}) {
    const CliResult r =
        run_maquette("export tiles3d " + store + " " + dir + "/t --dem dem --levels=" + levels);
    EXPECT_NE(r.exit_code, 0) << levels;
    EXPECT_NE(r.err.find(std::string("--levels '") + levels + "': expected A..B, levels 0 <= A"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/t")) << levels;
  }
  const std::string cell =
      Store::open(store, Store::Mode::ReadOnly)->tile_cells("dem").front().ToText();
  ASSERT_EQ(
      run_maquette("-q export glb " + store + " " + dir + "/once.glb --dem dem --cells " + cell)
          .exit_code,
      0);
  ASSERT_EQ(run_maquette("-q export glb " + store + " " + dir + "/twice.glb --dem dem --cells " +
                         cell + " " + cell)
                .exit_code,
            0);
  EXPECT_EQ(file_fingerprint(dir + "/twice.glb"), file_fingerprint(dir + "/once.glb"));
}

// Each quantization option is named with its value and range (one message named all three); a
// categorical --dem is refused (its classes were meshed as heights).
TEST(ExportBadInput, QuantizationBitsAndTheDemAreNamed) {
  const std::string dir = temp_dir(), store = export_fixture().store_path;
  const std::string cell =
      Store::open(store, Store::Mode::ReadOnly)->tile_cells("dem").front().ToText();
  for (const auto& [option, message] : std::vector<std::pair<std::string, std::string>>{
           {"--dem dem --position-bits 30", "--position-bits 30 is out of range 8..23"},
           {"--dem dem --texcoord-bits 5", "--texcoord-bits 5 is out of range 6..24"},
           {"--dem dem --normal-bits 25", "--normal-bits 25 is out of range 6..24"},
           {"--dem landcover", "--dem layer 'landcover' is categorical (classes, not heights)"}}) {
    const CliResult r =
        run_maquette("export glb " + store + " " + dir + "/t.glb --cells " + cell + " " + option);
    EXPECT_NE(r.exit_code, 0) << option;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/t.glb")) << option;
  }
}

TEST(ExportBadInput, PngUnknownLayerAndBadBands) {
  const std::string out = temp_dir() + "/out.png";
  CliResult r = run_maquette("export png " + export_fixture().store_path + " --layer nope " + out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("unknown layer 'nope'"), std::string::npos) << r.err;
  r = run_maquette("export png " + export_fixture().store_path + " --layer rgb --bands 1,2,9 " +
                   out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("band 9 out of range"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// An option that would do nothing for the layer is refused, naming it (it was ignored, exit 0).
TEST(ExportBadInput, PngOptionsThatDoNothingForTheLayerAreNamed) {
  const std::string out = temp_dir() + "/out.png";
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"--layer dem --range 0 100",
            "--range does nothing here: the hypsometric ramp tints fixed heights"},
           {"--layer dem --range nan 100", "--range nan 100.000000: expected two finite"},
           {"--layer dem --range 5 5", "expected two finite, distinct values"},
           {"--layer dem --bands 1,2,3", "--bands does nothing here"},
           {"--layer rgb --hillshade",
            "--hillshade does nothing here: the layer's 3 channels are drawn as RGB"},
           {"--layer rgb --ramp grey", "--ramp does nothing here"},
           {"--layer landcover --ramp viridis",
            "--ramp does nothing here: a categorical layer is drawn in its class colours"},
           {"--layer landcover --hillshade", "--hillshade does nothing here"}}) {
    const CliResult r =
        run_maquette("export png " + export_fixture().store_path + " " + out + " " + args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
  }
  // What does something still draws: a range on a stretched ramp, a hillshaded height.
  for (const std::string args : {"--layer dem --ramp grey --range 0 100", "--layer dem --hillshade",
                                 "--layer rgb --range 0 255"}) {
    const CliResult r =
        run_maquette("-q export png " + export_fixture().store_path + " " + out + " " + args);
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
  }
}

}  // namespace
}  // namespace maquette::test
