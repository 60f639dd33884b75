// Program start: the libraries that most of the dynamic loader's start-up symbol lookups resolve
// to are loaded first (cmake/StartupLibraries.cmake), so that each lookup finds its symbol in one
// of the first libraries it tries. Measured on the real program with the loader's own trace.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "run_cli.h"

namespace maquette::test {
namespace {

std::string file_name(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

TEST(Startup, SymbolLookupsEndInTheFirstLibrariesLoaded) {
  const CliResult r = run_maquette("--version", "LD_DEBUG=scopes,bindings");
  ASSERT_EQ(r.exit_code, 0) << r.err.substr(0, 2000);
  // "scope 0: PROGRAM LIB LIB ..." (the global scope, in load order), then one
  // "binding file A [0] to B [0]: normal symbol `s'" per lookup.
  std::map<std::string, int> position;
  std::map<std::string, int> lookups;
  std::istringstream lines(r.err);
  for (std::string line; std::getline(lines, line);) {
    if (const size_t at = line.find("scope 0:"); at != std::string::npos && position.empty()) {
      std::istringstream paths(line.substr(at + 8));
      int k = 0;
      for (std::string path; paths >> path;) position.emplace(file_name(path), k++);
    } else if (const size_t to = line.find("] to ");
               line.find("binding file ") != std::string::npos && to != std::string::npos) {
      const size_t begin = to + 5;
      ++lookups[file_name(line.substr(begin, line.find(' ', begin) - begin))];
    }
  }
  ASSERT_GT(position.size(), 50u) << "no loader trace of the global scope";
  int64_t total = 0, weighted = 0;
  for (const auto& [library, count] : lookups) {
    if (!position.count(library)) continue;  // the vDSO, searched outside the global scope
    total += count;
    weighted += int64_t(count) * position.at(library);
  }
  ASSERT_GT(total, 10000) << "too few lookups traced";
  // ~12 with the list in place, ~37 (of ~120 libraries) without it.
  EXPECT_LT(double(weighted) / double(total), 18.0)
      << "start-up symbol lookups try too many libraries before the one defining the symbol: "
         "regenerate cmake/StartupLibraries.cmake with scripts/startup-order.sh";
}

}  // namespace
}  // namespace maquette::test
