#include "validator.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace maquette::test {

std::optional<ValidatorReport> validate_glb(const std::string& path) {
  const std::string node = MAQUETTE_NODE_DIR;
  if (!std::filesystem::exists(node + "/node_modules/gltf-validator")) return std::nullopt;
  const std::string cmd =
      "node " MAQUETTE_SOURCE_DIR "/tests/gltf_content/node/report.mjs " + node + " " + path;
  FILE* pipe = popen(cmd.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  std::string out;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  EXPECT_EQ(pclose(pipe), 0) << out;
  ValidatorReport report;
  const size_t last = out.rfind('{');
  const auto counts =
      nlohmann::json::parse(out.substr(last == std::string::npos ? 0 : last), nullptr, false);
  EXPECT_TRUE(counts.is_object()) << out;
  if (!counts.is_object()) return report;
  report.errors = counts.value("errors", -1);
  report.warnings = counts.value("warnings", -1);
  report.messages = out.substr(0, last);
  return report;
}

}  // namespace maquette::test
