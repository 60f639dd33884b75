// Output directories of exports: refused when they exist and are not empty (unless forced), and
// file names checked so that nothing is written outside them.
#pragma once

#include <filesystem>
#include <string>

namespace maquette {

// Creates `dir` (and parents); throws maquette::Error when it holds files and !force.
void prepare_output_dir(const std::filesystem::path& dir, bool force);

// dir / relative, refusing absolute paths, "..", and characters other than [A-Za-z0-9_.-/].
std::filesystem::path inside(const std::filesystem::path& dir, const std::string& relative);

}  // namespace maquette
