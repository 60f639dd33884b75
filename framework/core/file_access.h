// Why an input file cannot be read, for error messages that tell a missing file from an
// unreadable one.
#pragma once

#include <optional>
#include <string>

namespace maquette {

// "no such file", "permission denied", "a directory, not a file", ... ; nothing when the file
// opens for reading (a reader that still fails then has a problem with its content).
std::optional<std::string> file_access_problem(const std::string& path);

}  // namespace maquette
