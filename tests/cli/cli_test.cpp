// The `maquette` program as a user runs it: exact outputs of the documented forms, checked
// against the DESIGN.md reference table, PROJ and GeographicLib; and every bad input gives a
// clear message and a non-zero exit without touching the store.
#include <gtest/gtest.h>
#include <proj.h>

#include <GeographicLib/Geodesic.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>

#include "run_cli.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;

std::string trim(const std::string& s) { return s.substr(0, s.find_last_not_of("\n ") + 1); }

void write_file(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(CliCells, FromPointMatchesTheDesignReferenceTable) {
  struct Ref {
    const char* lonlat;
    const char* l1;
    const char* l3;
    const char* l8;
  };
  const Ref refs[] = {{"10 45", "N1", "N110", "N11011323"},
                      {"0 0", "Q2", "Q200", "Q20000000"},
                      {"174.77 -36.85", "R3", "R333", "R33330021"},
                      {"-43.2 -22.9", "P3", "P320", "P32002121"}};
  for (const Ref& r : refs) {
    for (auto [level, want] : {std::pair{1, r.l1}, {3, r.l3}, {8, r.l8}}) {
      const CliResult res = run_maquette(std::string("cells from-point ") + r.lonlat + " --level " +
                                         std::to_string(level));
      ASSERT_EQ(res.exit_code, 0) << res.err;
      EXPECT_EQ(trim(res.out), want) << r.lonlat << " level " << level;
    }
  }
}

TEST(CliCells, InfoAgreesWithProjAndGeographicLib) {
  const CliResult res = run_maquette("cells info N11011323 --json");
  ASSERT_EQ(res.exit_code, 0) << res.err;
  const json j = json::parse(res.out);
  EXPECT_EQ(j["id"], "N11011323");
  EXPECT_EQ(j["level"], 8);
  // Exact area: the ellipsoid's area (GeographicLib) shared by 6 * 4^8 cells.
  const double ellipsoid_area = GeographicLib::Geodesic::WGS84().EllipsoidArea();
  EXPECT_NEAR(j["area_m2"].get<double>(), ellipsoid_area / (6.0 * std::pow(4.0, 8)), 1e-3);
  // The centre projects (PROJ) to the middle of the plane square.
  PJ* pj =
      proj_create(PJ_DEFAULT_CTX, "+proj=rhealpix +ellps=WGS84 +north_square=0 +south_square=0");
  ASSERT_NE(pj, nullptr);
  auto forward = [pj](double lon, double lat) {
    return proj_trans(pj, PJ_FWD, proj_coord(proj_torad(lon), proj_torad(lat), 0, 0)).xy;
  };
  const PJ_XY centre = forward(j["centre"][0], j["centre"][1]);
  const PJ_XY reference = forward(10.0, 45.0);  // the point the id came from (DESIGN.md table)
  proj_destroy(pj);
  const json sq = j["plane_square"];
  const double side = sq["side"], x_min = sq["x_min"], y_max = sq["y_max"];
  EXPECT_NEAR(centre.x, x_min + side / 2, 1e-3);
  EXPECT_NEAR(centre.y, y_max - side / 2, 1e-3);
  EXPECT_GE(reference.x, x_min);
  EXPECT_LE(reference.x, x_min + side);
  EXPECT_GE(reference.y, y_max - side);
  EXPECT_LE(reference.y, y_max);
  EXPECT_EQ(j["boundary"]["type"], "Polygon");
  const json ring = j["boundary"]["coordinates"][0];
  EXPECT_EQ(ring.front(), ring.back());
}

TEST(CliCells, CoverHoldsTheCellOfEveryPointInTheBox) {
  const CliResult res = run_maquette("cells cover --bbox 170 -20 -170 -10 --level 5");
  ASSERT_EQ(res.exit_code, 0) << res.err;
  std::set<std::string> cover;
  std::istringstream lines(res.out);
  for (std::string id; std::getline(lines, id);) cover.insert(id);
  ASSERT_FALSE(cover.empty());
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> lon(170.0, 190.0), lat(-20.0, -10.0);
  for (int i = 0; i < 20; ++i) {
    std::ostringstream args;
    args.precision(10);
    args << "cells from-point " << std::remainder(lon(rng), 360.0) << " " << lat(rng)
         << " --level 5";
    const CliResult p = run_maquette(args.str());
    ASSERT_EQ(p.exit_code, 0) << p.err;
    EXPECT_TRUE(cover.count(trim(p.out))) << args.str() << " -> " << p.out;
  }
}

TEST(CliCells, LevelsTableListsEveryLevel) {
  const CliResult res = run_maquette("cells levels --tile-size 256 --json");
  ASSERT_EQ(res.exit_code, 0) << res.err;
  const json rows = json::parse(res.out);
  ASSERT_EQ(rows.size(), 30u);
  const double ellipsoid_area = GeographicLib::Geodesic::WGS84().EllipsoidArea();
  for (const json& r : rows) {
    const int level = r["level"];
    EXPECT_NEAR(r["area_m2"].get<double>() / (ellipsoid_area / (6.0 * std::pow(4.0, level))), 1.0,
                1e-9);
    EXPECT_NEAR(r["pixel_m"].get<double>(), r["cell_side_m"].get<double>() / 256, 1e-9);
  }
}

struct BadInput {
  const char* args;
  const char* message;  // must appear in stderr
};

TEST(CliBadInput, GridErrorsAreClearAndNonZero) {
  const BadInput cases[] = {
      {"cells from-point 10 95 --level 8", "95"},
      {"cells from-point 10 45 --level 30", "30"},
      {"cells from-point 10 45 --level -1", "-1"},
      {"cells info X123", "X123"},
      {"cells info N15", "N15"},
      {"cells cover --bbox 0 -95 10 10 --level 3", "-95"},
      {"cells levels --tile-size 100", "100"},
  };
  for (const BadInput& c : cases) {
    const CliResult res = run_maquette(c.args);
    EXPECT_NE(res.exit_code, 0) << c.args;
    EXPECT_NE(res.err.find(c.message), std::string::npos) << c.args << ": " << res.err;
  }
}

TEST(CliBadInput, NotAStoreIsNamed) {
  const std::string dir = temp_dir();
  write_file(dir + "/notes.txt", "hello, not a database\n");
  const std::string before = file_fingerprint(dir + "/notes.txt");
  const CliResult res = run_maquette("info " + dir + "/notes.txt");
  EXPECT_NE(res.exit_code, 0);
  EXPECT_NE(res.err.find("notes.txt"), std::string::npos) << res.err;
  EXPECT_NE(res.err.find("not a Maquette store"), std::string::npos) << res.err;
  EXPECT_EQ(file_fingerprint(dir + "/notes.txt"), before);

  const CliResult missing = run_maquette("info " + dir + "/nothing.mqt");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.err.find("nothing.mqt"), std::string::npos) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/nothing.mqt"));
}

// `maquette --help` names the environment variables the program reads (module_loader.cpp,
// the synthesis module's exemplar_cache.cpp).
TEST(CliHelp, NamesTheEnvironmentVariablesItReads) {
  const CliResult res = run_maquette("--help");
  EXPECT_EQ(res.exit_code, 0) << res.err;
  for (const char* name : {"MAQUETTE_MODULE_PATH", "MAQUETTE_CACHE_DIR", "MAQUETTE_CACHE_MAX_MB",
                           "GDAL_CACHEMAX", "'off'"})
    EXPECT_NE(res.out.find(name), std::string::npos) << name << " in\n" << res.out;
}

}  // namespace
}  // namespace maquette::test
