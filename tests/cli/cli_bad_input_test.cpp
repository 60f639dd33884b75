// Bad input through the real program, each refused as a class with a clear message and a bounded
// one: boxes without area, duplicated station ids, regions too fine to list, JSON numbers out of
// range, nesting too deep and huge bad values, missing and unreadable files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A refusal: exit 1, "maquette: error: ..." with each of `expected`, and a short message
// whatever the input.
void expect_errors(const CliResult& r, const std::vector<std::string>& expected) {
  EXPECT_EQ(r.exit_code, 1) << r.err.substr(0, 2000);
  EXPECT_NE(r.err.find("error: "), std::string::npos) << r.err.substr(0, 2000);
  for (const std::string& e : expected)
    EXPECT_NE(r.err.find(e), std::string::npos) << e << "\n" << r.err.substr(0, 2000);
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err.substr(0, 2000);
  EXPECT_LT(r.err.size(), 1000u) << r.err.substr(0, 2000);
}

void expect_error(const CliResult& r, const std::string& expected) { expect_errors(r, {expected}); }

// A small DEM around 7.5 E 45.5 N.
std::string small_dem(const std::string& dir) {
  const std::string path = dir + "/dem.tif";
  write_raster(path, lonlat_raster(7, 46, 50, 0.02, "Float32"),
               [](int, double lon, double lat) { return 100 * lon + 10 * lat; });
  return path;
}

TEST(BadInput, BoxesWithoutAreaAreRefusedEverywhere) {
  const std::string dir = temp_dir(), dem = small_dem(dir), store = dir + "/s.mqt";
  expect_error(run_maquette("ingest " + store + " --layer a --as dem --bbox 7.2 45 7.2 46 " + dem),
               "--bbox: west equals east (7.2)");
  expect_error(run_maquette("ingest " + store + " --layer a --as dem --bbox 7 45.5 8 45.5 " + dem),
               "--bbox: south equals north (45.5)");
  EXPECT_FALSE(fs::exists(store));
  expect_error(run_maquette("cells cover --bbox 10 40 10 41 --level 5"), "west equals east");
  const json pipeline = {{"store", store},
                         {"region", {{"bbox", {7, 45, 8, 45}}}},
                         {"level", 6},
                         {"steps", {{{"op", "terrain.synthesize"}, {"outputs", {{"dem", "d"}}}}}}};
  write_file(dir + "/p.json", pipeline.dump());
  expect_error(run_maquette("run " + dir + "/p.json"), "south equals north");
  // A polygon region whose outer ring is a line.
  write_file(dir + "/line.geojson",
             R"({"type": "Polygon", "coordinates": [[[7, 45], [7.5, 45.5], [8, 46], [7, 45]]]})");
  expect_error(run_maquette("cells cover --geojson " + dir + "/line.geojson --level 5"),
               "a polygon has no area");
  EXPECT_FALSE(fs::exists(store));
}

TEST(BadInput, DuplicatedStationIdIsRefused) {
  const std::string dir = temp_dir(), store = dir + "/s.mqt";
  write_file(dir + "/st.csv",
             "id,name,lon,lat,elev_m,precip\n"
             "A1,Alpha,-105.1,40.1,1600,400\n"
             "B2,Beta,-105.2,40.2,1700,410\n"
             "A1,Gamma,-105.3,40.3,1800,420\n");
  expect_error(run_maquette("ingest " + store + " --layer st --as stations " + dir + "/st.csv"),
               dir + "/st.csv line 4: column 'id': station id 'A1' is already given on line 2");
  EXPECT_FALSE(fs::exists(store));  // a failed ingest leaves no new store
}

// A word that names no command is told with the choices (CLI11 said "A subcommand is required").
TEST(BadInput, AnUnknownCommandIsNamedWithTheChoices) {
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"bogus", "maquette: 'bogus' is not one of cells, ingest, info,"},
           {"-q export bogus", "maquette export: 'bogus' is not one of gtiff, png,"},
           {"render pano", "maquette render: 'pano' is not one of panorama, fit"}}) {
    const CliResult r = run_maquette(args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_NE(r.err.find("maquette: error: " + message), std::string::npos) << r.err;
  }
  // --help prints the help, whatever else is given.
  const CliResult help = run_maquette("export bogus --help");
  EXPECT_EQ(help.exit_code, 0) << help.err;
  EXPECT_EQ(help.err.find("error"), std::string::npos) << help.err;
  EXPECT_NE(help.out.find("tiles3d"), std::string::npos) << help.out;
}

TEST(BadInput, UnknownKindListsEveryKind) {
  const std::string dir = temp_dir();
  expect_error(run_maquette("ingest " + dir + "/s.mqt --layer a --as vectors " + small_dem(dir)),
               "--as 'vectors' is not one of dem, imagery, climate, landcover, raster (rasters), "
               "features, stations (vectors), model (a glTF file)");
  // --classes names a land cover's classes: with vectors it was ignored.
  expect_error(run_maquette("ingest " + dir + "/s.mqt --layer a --as features --classes '{}' " +
                            dir + "/none.json"),
               "--classes is for class layers (--as landcover), not --as features");
  EXPECT_FALSE(fs::exists(dir + "/s.mqt"));
}

// A missing file, a file this user may not read, and a file GDAL cannot read get three messages.
TEST(BadInput, MissingUnreadableAndForeignFilesAreTold) {
  const std::string dir = temp_dir(), dem = small_dem(dir), store = dir + "/s.mqt";
  expect_error(run_maquette("ingest " + store + " --layer a --as dem " + dir + "/none.tif"),
               dir + "/none.tif: cannot read the raster: no such file");
  write_file(dir + "/text.tif", "a text file, not a raster\n");
  expect_error(run_maquette("ingest " + store + " --layer a --as dem " + dir + "/text.tif"),
               "not a raster GDAL can read");
  expect_error(run_maquette("ingest " + store + " --layer a --as features " + dir + "/none.json"),
               dir + "/none.json: no such file");
  expect_error(run_maquette("ingest " + store + " --layer a --as stations " + dir + "/none.csv"),
               dir + "/none.csv: no such file");
  expect_error(run_maquette("run " + dir + "/none.json"), dir + "/none.json: no such file");
  // A directory was read as an empty file ("parse error at line 1, column 1").
  fs::create_directory(dir + "/folder.json");
  expect_error(run_maquette("run " + dir + "/folder.json"),
               "cannot read " + dir + "/folder.json: it is a directory");

  // Unreadable: run as user nobody (root reads any file), the directories open to all.
  if (std::system("command -v setpriv >/dev/null") != 0) GTEST_SKIP() << "no setpriv";
  for (fs::path p = dir; p != fs::temp_directory_path(); p = p.parent_path())
    fs::permissions(p, fs::perms::all, fs::perm_options::add);
  fs::permissions(dem, fs::perms::owner_read | fs::perms::owner_write);
  const std::string nobody = "setpriv --reuid=65534 --regid=65534 --clear-groups";
  expect_error(run_maquette_under(nobody, "ingest " + dir + "/n.mqt --layer a --as dem " + dem),
               dem + ": cannot read the raster: permission denied");
  write_file(dir + "/p.json", "{}");
  fs::permissions(dir + "/p.json", fs::perms::owner_read | fs::perms::owner_write);
  expect_error(run_maquette_under(nobody, "run " + dir + "/p.json"),
               dir + "/p.json: permission denied");
}

// GDAL's own lines ("ERROR 1: At line 2, character 1: Unterminated array", "Warning 1: Non
// closed ring detected") were printed besides the error (an audit's find): the error says it.
TEST(BadInput, AFeaturesSourceGdalCannotReadIsToldOnce) {
  const std::string dir = temp_dir(), store = dir + "/s.mqt";
  write_file(dir + "/cut.json", "{\"type\": \"FeatureCollection\", \"features\": [\n");
  const CliResult r =
      run_maquette("ingest " + store + " --layer a --as features " + dir + "/cut.json");
  expect_error(r, "cannot open " + dir + "/cut.json: ");
  EXPECT_EQ(r.err.find("ERROR 1"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("\n", r.err.find("maquette: error: ")), r.err.size() - 1) << r.err;
}

TEST(BadInput, JsonNumberOutOfRangeNamesFileLineAndField) {
  const std::string dir = temp_dir();
  write_file(dir + "/p.json",
             "{\"store\": \"s.mqt\",\n \"region\": {\"bbox\": [7, 45, 8, 46]},\n"
             " \"level\": 6,\n \"steps\": [{\"op\": \"terrain.synthesize\",\n"
             "   \"outputs\": {\"dem\": \"d\"}, \"params\": {\"seed\": 1e999}}]}\n");
  expect_error(
      run_maquette("run " + dir + "/p.json"),
      dir + "/p.json: line 5, column 52: steps[0].params.seed: number 1e999 is out of range");
  // --classes: inline JSON too.
  expect_error(
      run_maquette("ingest " + dir + "/s.mqt --layer a --as landcover --classes '{\"1\": 1e400}' " +
                   small_dem(dir)),
      "1: number 1e400 is out of range");
  EXPECT_FALSE(fs::exists(dir + "/s.mqt"));
}

TEST(BadInput, DeepNestingAndHugeValuesGiveShortErrors) {
  const std::string dir = temp_dir();
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  write_file(dir + "/deep.json",
             "{\"store\": \"s.mqt\", \"region\": {\"bbox\": [7, 45, 8, 46]}, \"level\": 6,\n"
             "\"steps\": [{\"op\": \"terrain.synthesize\", \"outputs\": {\"dem\": \"d\"},\n"
             "\"params\": {\"seed\": " +
                 deep + "}}]}");
  expect_errors(run_maquette("run " + dir + "/deep.json"),
                {dir + "/deep.json: line 3, column 144: steps[0].params.seed[0][0][0][0]...: ",
                 "nested deeper than 128 levels"});
  // The same depth in a GeoJSON region.
  write_file(dir + "/deep.geojson", deep);
  expect_errors(run_maquette("cells cover --geojson " + dir + "/deep.geojson --level 3"),
                {"deep.geojson: line 1, column 129: [0]", "nested deeper than 128 levels"});

  // A 10 MB operator name is quoted shortened, once.
  const std::string name(10 << 20, 'x');
  write_file(dir + "/name.json",
             "{\"store\": \"s.mqt\", \"region\": {\"bbox\": [7, 45, 8, 46]}, \"level\": 6, "
             "\"steps\": [{\"op\": \"" +
                 name + "\", \"outputs\": {\"dem\": \"d\"}}]}");
  expect_error(run_maquette("run " + dir + "/name.json"),
               "unknown operator '" + name.substr(0, 60) + "... (10485760 characters)'");
  // A 10 MB bad value of a parameter and of a field.
  write_file(dir + "/value.json",
             "{\"store\": \"s.mqt\", \"region\": {\"bbox\": [7, 45, 8, 46]}, \"level\": \"" + name +
                 "\", \"steps\": [{\"op\": \"terrain.synthesize\", \"outputs\": {\"dem\": \"d\"}, "
                 "\"params\": {\"seed\": \"" +
                 name + "\"}}]}");
  expect_error(run_maquette("run " + dir + "/value.json"), "... (10485762 characters)");
  // An unterminated string: the parser's message quotes what it read, shortened.
  write_file(dir + "/garbage.json", "{\"store\": \"" + name);
  expect_errors(run_maquette("run " + dir + "/garbage.json"),
                {"garbage.json: parse error at line 1, column", "... (10485761 characters)"});
}

// The whole globe at level 29 is some 1.7e18 cells: refused at once with the estimate (over
// `cells cover --max-cells`, a billion by default; pipelines hold their cells: 2e7), under a
// memory cap that an attempt to list them would exceed at once.
TEST(BadInput, CoverTooFineIsRefusedWithTheEstimateUnderAMemoryCap) {
  if (const std::string why = address_space_cap_unavailable(); !why.empty()) GTEST_SKIP() << why;
  const std::string cap = "prlimit --as=2000000000";
  for (const char* compact : {"", " --compact"}) {
    const CliResult r = run_maquette_under(
        cap, std::string("cells cover --bbox -180 -90 180 90 --level 29") + compact);
    expect_error(r,
                 "--bbox holds about 1.73e+18 cells at level 29, over the limit of 1000000000 "
                 "cells a cover lists: use a coarser level or a smaller region, or raise "
                 "--max-cells");
  }
  const std::string dir = temp_dir();
  write_file(dir + "/globe.geojson",
             R"({"type": "Polygon", "coordinates": [[[-180, -90], [180, -90], [180, 90],
                 [-180, 90], [-180, -90]]]})");
  expect_error(
      run_maquette_under(cap, "cells cover --geojson " + dir + "/globe.geojson --level 20"),
      "holds about 6.6e+12 cells at level 20");
  // A pipeline region listing a face, at level 29.
  const json pipeline = {{"store", dir + "/s.mqt"},
                         {"region", {{"cells", {"N"}}}},
                         {"level", 29},
                         {"steps", {{{"op", "terrain.synthesize"}, {"outputs", {{"dem", "d"}}}}}}};
  write_file(dir + "/p.json", pipeline.dump());
  expect_error(run_maquette_under(cap, "run " + dir + "/p.json"),
               "region.cells: the cells hold 288230376151711744 cells at level 29");
  // The limit is the user's: the globe at level 8 (393216 cells) over a limit of 300000.
  expect_error(run_maquette("cells cover --bbox -180 -90 180 90 --level 8 --max-cells 3e5"),
               "--bbox holds about 3.93e+05 cells at level 8, over the limit of 300000");
}

TEST(BadInput, CoverWithNoCellSaysSo) {
  // Full mode needs a level-3 cell (some 1,200 km) wholly inside a 1 degree box: there is none.
  const CliResult r = run_maquette("cells cover --bbox 7 45 8 46 --level 3 --mode full");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("no cell at level 3 lies wholly inside the region"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace maquette::test
