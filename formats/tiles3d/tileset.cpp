#include "tiles3d/tileset.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/error.h"
#include "core/output_file.h"
#include "gltf/output_dir.h"

namespace maquette {
namespace {

using nlohmann::json;

json asset() { return {{"version", "1.1"}, {"generator", "maquette"}}; }

void write_json(const std::filesystem::path& path, const json& j) {
  write_file_whole(path.string(), j.dump(1) + "\n");
}

// A tile's JSON; `depth` counts levels below the top of the file being written, `prefix` leads
// from that file's folder to OUTDIR (uris are relative to the file holding them).
json tile_json(const std::filesystem::path& dir, const TileNode& n, int depth,
               const std::string& prefix) {
  json t = {{"boundingVolume", {{"region", n.region}}},
            {"geometricError", n.geometric_error},
            {"refine", "REPLACE"}};
  if (depth == kSubtreeDepth && !n.children.empty()) {
    const std::string uri = "subtrees/" + n.cell.ToText() + ".json";
    write_json(inside(dir, uri), {{"asset", asset()},
                                  {"geometricError", n.geometric_error},
                                  {"root", tile_json(dir, n, 0, "../")}});
    t["content"] = {{"uri", prefix + uri}};
    return t;
  }
  json contents = json::array();
  for (const std::string& uri : n.contents) contents.push_back({{"uri", prefix + uri}});
  if (contents.size() == 1) t["content"] = contents[0];
  if (contents.size() > 1) t["contents"] = contents;
  for (const auto& c : n.children) t["children"].push_back(tile_json(dir, *c, depth + 1, prefix));
  return t;
}

// The size (metres, the diagonal on a sphere of the equatorial radius) of a region: the error
// of drawing nothing in its place.
double region_extent(const std::array<double, 6>& r) {
  constexpr double kRadius = 6378137.0;
  const double east = r[2] < r[0] ? r[2] + 2 * std::numbers::pi : r[2];
  return kRadius * std::hypot(r[3] - r[1], std::cos(0.5 * (r[1] + r[3])) * (east - r[0]));
}

}  // namespace

void extend_region(std::array<double, 6>& r, const std::array<double, 6>& o) {
  r[0] = std::min(r[0], o[0]);
  r[1] = std::min(r[1], o[1]);
  r[2] = std::max(r[2], o[2]);
  r[3] = std::max(r[3], o[3]);
  r[4] = std::min(r[4], o[4]);
  r[5] = std::max(r[5], o[5]);
}

void write_tilesets(const std::filesystem::path& out_dir, const std::vector<TileNode*>& top,
                    double root_error, const std::array<double, 16>& transform) {
  std::array<double, 6> region = top.front()->region;
  json children = json::array();
  for (const TileNode* n : top) {
    extend_region(region, n->region);
    children.push_back(tile_json(out_dir, *n, 1, ""));
  }
  // The root has no content: drawing it shows nothing, so its error is the size of what it
  // covers. With the error of its children's content instead, a viewer far enough away to see
  // the whole region (CesiumJS's zoomTo) stopped at the empty root and drew nothing.
  root_error = std::max(root_error, region_extent(region));
  const json root = {{"boundingVolume", {{"region", region}}},
                     {"geometricError", root_error},
                     {"refine", "REPLACE"},
                     {"transform", transform},
                     {"children", children}};
  write_json(out_dir / "tileset.json",
             {{"asset", asset()}, {"geometricError", root_error}, {"root", root}});
}

}  // namespace maquette
