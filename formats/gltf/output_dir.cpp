#include "gltf/output_dir.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"

namespace maquette {

void prepare_output_dir(const std::filesystem::path& dir, bool force) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw Error("output " + dir.string() + " exists and is not a directory");
  if (fs::is_directory(dir) && !fs::is_empty(dir) && !force)
    throw Error("output directory " + dir.string() +
                " is not empty: choose another, or pass --force to write into it");
  fs::create_directories(dir, ec);
  if (ec) throw Error("could not create " + dir.string() + ": " + ec.message());
}

std::filesystem::path inside(const std::filesystem::path& dir, const std::string& relative) {
  const bool safe_chars = std::all_of(relative.begin(), relative.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-' ||
           c == '/';
  });
  const std::filesystem::path rel(relative);
  bool dotdot = false;
  for (const auto& part : rel) dotdot = dotdot || part == "..";
  if (relative.empty() || !safe_chars || rel.is_absolute() || dotdot)
    throw Error("refusing to write '" + relative + "': not a safe file name inside " +
                dir.string());
  std::filesystem::create_directories((dir / rel).parent_path());
  return dir / rel;
}

}  // namespace maquette
