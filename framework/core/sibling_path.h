// Names of the files a program writes beside its main output (OUT.png -> OUT-guides.tif).
#pragma once

#include <string>

namespace maquette {

// `path` without its extension (the last dot of its file name, if any) + `suffix`, in `path`'s
// directory: sibling_path("dir/out.png", "-guides.tif") is "dir/out-guides.tif".
std::string sibling_path(const std::string& path, const std::string& suffix);

}  // namespace maquette
