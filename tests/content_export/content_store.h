// A store for the content export tests: `dem` (float32, kHeight metres everywhere) on a 2 x 2
// block of level-kLevel cells, and a content layer of each kind at kLevel, each object standing
// on the terrain at the centre of its cell:
// - `buildings` (mesh), block[0]: a red box kBoxHalf x 2 wide and kBoxHeight high, axis-aligned
//   in its frame; its parent (level kLevel - 1) holds the same box as a simplified copy;
// - `trees` (instances), block[1]: kTreeCount green builtin:conifer instances, instance i at
//   tree_offset(i) metres east and north of the centre, kTreeHeight high, turned by 30 i degrees;
// - `lakes` (volume), block[2]: a fog volume box of water, 80 m x 80 m x 20 m from the centre up;
// - `orchard` (instances), block[3]: one instance of an unknown prototype "oak";
// - `parks` (mesh) at level kLevel - 1, empty.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "content/content.h"
#include "core/grid.h"

namespace maquette::test {

inline constexpr int kLevel = 13;
inline constexpr double kHeight = 100;
inline constexpr double kBoxHalf = 60, kBoxHeight = 40;
inline constexpr int kTreeCount = 4;
inline constexpr double kTreeHeight = 80;
inline constexpr uint32_t kTreeColour = 0xFF20D020;  // RGBA8, R in the low byte

struct ContentStore {
  std::string path;
  std::vector<CellId> block;         // 2 x 2, one parent
  std::array<EnuOrigin, 4> origins;  // the content's frame in each cell
};
// Writes the store at `path` (which must not exist).
ContentStore write_content_store(const std::string& path);

std::array<double, 2> tree_offset(int i);  // metres east, north

}  // namespace maquette::test
