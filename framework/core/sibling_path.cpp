#include "core/sibling_path.h"

#include <filesystem>

namespace maquette {

std::string sibling_path(const std::string& path, const std::string& suffix) {
  const std::filesystem::path p(path);
  return (p.parent_path() / p.stem()).string() + suffix;
}

}  // namespace maquette
