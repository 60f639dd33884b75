// 3D content layers (see formats/gltf/README.md): per-cell meshes and per-cell instances of a
// prototype (e.g. vegetation), stored as store artifacts named content/<LAYER>/<CELL> holding
// JSON, until modules store them as layers of their own. `maquette export tiles3d --content`
// writes each as an additional content of the cell's tile.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/cell_id.h"
#include "store/store.h"

namespace maquette {

struct ContentInstance {
  double lon = 0, lat = 0, height = 0;  // degrees, metres above the ellipsoid (base)
  double scale = 1;                     // the prototype's size in metres
  double heading = 0;                   // degrees clockwise from north
};

struct ContentTile {
  enum class Kind { Mesh, Instances };
  Kind kind = Kind::Mesh;
  std::vector<double> positions;  // mesh: lon, lat, height per vertex
  std::vector<uint32_t> indices;  // mesh: triangles, counter-clockwise seen from outside
  std::string prototype;          // instances: "cone" or "box" (unit size, base at the origin)
  std::vector<ContentInstance> instances;
  std::array<double, 3> color{0.6, 0.6, 0.6};  // RGB, 0..1

  bool empty() const { return kind == Kind::Mesh ? indices.empty() : instances.empty(); }
};

std::string content_artifact_name(const std::string& layer, CellId cell);

// Writes a cell's content (checked: indices in range, known prototype).
void put_content(Store::Batch& batch, const std::string& layer, CellId cell,
                 const ContentTile& content);
std::optional<ContentTile> get_content(const Store& store, const std::string& layer, CellId cell);

// Throws maquette::Error when the store holds no content of `layer`.
void require_content_layer(const Store& store, const std::string& layer);

}  // namespace maquette
