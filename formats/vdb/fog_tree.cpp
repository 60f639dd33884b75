#include "vdb/fog_tree.h"

#include <algorithm>
#include <compare>
#include <string>
#include <utility>

#include "core/error.h"

namespace maquette {
namespace {

using Leaf = openvdb::FloatTree::LeafNodeType;                                 // 8^3 voxels
using Lower = openvdb::FloatTree::RootNodeType::ChildNodeType::ChildNodeType;  // 16^3 leaves
using Upper = openvdb::FloatTree::RootNodeType::ChildNodeType;                 // 32^3 lowers

// Where an origin lies in OpenVDB's tree: its upper node's origin (the root's key, whose map
// orders its children by x, then y, then z) and its offsets in that node and in its lower node
// (InternalNode::coordToOffset): tree order is the order of these.
struct Place {
  int32_t x, y, z;
  uint32_t upper, lower;
  auto operator<=>(const Place&) const = default;
};

Place place(const openvdb::Coord& at) {
  const openvdb::Coord root = at & ~int32_t(Upper::DIM - 1);
  const auto offset = [&](int32_t dim, int32_t child_dim, uint32_t log2) {
    return (uint32_t((at.x() & (dim - 1)) / child_dim) << (2 * log2)) |
           (uint32_t((at.y() & (dim - 1)) / child_dim) << log2) |
           uint32_t((at.z() & (dim - 1)) / child_dim);
  };
  return {root.x(), root.y(), root.z(),
          offset(int32_t(Upper::DIM), int32_t(Lower::DIM), Upper::LOG2DIM),
          offset(int32_t(Lower::DIM), int32_t(Leaf::DIM), Lower::LOG2DIM)};
}

// `items` ordered by their origins' places, sorted as (place, index) pairs and gathered once.
template <typename T, typename Origin>
void sort_by_place(std::vector<T>& items, const Origin& origin) {
  std::vector<std::pair<Place, uint32_t>> order(items.size());
  for (size_t i = 0; i < items.size(); ++i) order[i] = {place(origin(items[i])), uint32_t(i)};
  std::sort(order.begin(), order.end());
  std::vector<T> sorted;
  sorted.reserve(items.size());
  for (const auto& [where, i] : order) sorted.push_back(items[i]);
  items = std::move(sorted);
}

static_assert(sizeof(openvdb::Coord) == 3 * sizeof(int32_t));

template <typename T>
void put(std::ostream& os, const T& value) {
  os.write(reinterpret_cast<const char*>(&value), sizeof value);
}

// A child of a lower node: a leaf (its index) or an active tile (leaf < 0).
struct Child {
  Place where;
  int64_t leaf;
};

}  // namespace

void sort_in_tree_order(FogTree& tree) {
  sort_by_place(tree.leaves, [](const FogLeaf& leaf) { return leaf.origin; });
  sort_by_place(tree.tiles, [](const openvdb::Coord& tile) { return tile; });
}

void write_fog_topology(std::ostream& os, const FogTree& tree) {
  // TreeBase::writeTopology, then RootNode::writeTopology: the background, no tiles of the root,
  // its children (upper nodes) by origin; each upper node's masks and values, then its children
  // (lower nodes) by offset; each lower node's masks and values (its active tiles at the density),
  // then its leaves' value masks (LeafNode::writeTopology).
  put(os, int32_t(1));  // one buffer per leaf
  put(os, kFogBackground);
  openvdb::io::setGridBackgroundValuePtr(os, &kFogBackground);
  std::vector<Child> children(tree.leaves.size() + tree.tiles.size());
  {
    size_t l = 0, t = 0;
    for (Child& child : children) {
      const bool leaf =
          t == tree.tiles.size() ||
          (l < tree.leaves.size() && place(tree.leaves[l].origin) < place(tree.tiles[t]));
      child = leaf ? Child{place(tree.leaves[l].origin), int64_t(l++)}
                   : Child{place(tree.tiles[t++]), -1};
    }
  }
  for (size_t c = 1; c < children.size(); ++c)
    if (!(children[c - 1].where < children[c].where)) {
      const Place& at = children[c].where;
      throw Error(
          "VDB writer: a fog tree's leaves and tiles are not in tree order or hold an "
          "origin twice (in the upper node at " +
          std::to_string(at.x) + ", " + std::to_string(at.y) + ", " + std::to_string(at.z) +
          ", lower " + std::to_string(at.upper) + ", leaf " + std::to_string(at.lower) + ")");
    }
  // Child slots hold zero in OpenVDB's InternalNode::writeTopology: the background here.
  static_assert(kFogBackground == 0.0f);
  const auto same_upper = [](const Child& a, const Child& b) {
    return a.where.x == b.where.x && a.where.y == b.where.y && a.where.z == b.where.z;
  };
  uint32_t uppers = 0;
  for (size_t c = 0; c < children.size(); ++c)
    uppers += c == 0 || !same_upper(children[c - 1], children[c]);
  put(os, uint32_t(0));  // the root's tiles
  put(os, uppers);
  std::vector<float> upper_values(Upper::NUM_VALUES, kFogBackground);  // no tiles: background
  std::vector<float> lower_values(Lower::NUM_VALUES);
  for (size_t first = 0; first < children.size();) {
    size_t end = first;
    while (end < children.size() && same_upper(children[first], children[end])) ++end;
    put(os,
        openvdb::Coord(children[first].where.x, children[first].where.y, children[first].where.z));
    Upper::NodeMaskType upper_children, upper_active;
    for (size_t c = first; c < end; ++c) upper_children.setOn(children[c].where.upper);
    upper_children.save(os);
    upper_active.save(os);
    openvdb::io::writeCompressedValues(os, upper_values.data(), Upper::NUM_VALUES, upper_active,
                                       upper_children, /*toHalf=*/false);
    for (size_t lower = first; lower < end;) {
      size_t lower_end = lower;
      while (lower_end < end && children[lower_end].where.upper == children[lower].where.upper)
        ++lower_end;
      Lower::NodeMaskType lower_children, lower_active;
      std::fill(lower_values.begin(), lower_values.end(), kFogBackground);
      for (size_t c = lower; c < lower_end; ++c)
        if (children[c].leaf >= 0) {
          lower_children.setOn(children[c].where.lower);
        } else {
          lower_active.setOn(children[c].where.lower);
          lower_values[children[c].where.lower] = kFogDensity;
        }
      lower_children.save(os);
      lower_active.save(os);
      openvdb::io::writeCompressedValues(os, lower_values.data(), Lower::NUM_VALUES, lower_active,
                                         lower_children, /*toHalf=*/false);
      for (size_t c = lower; c < lower_end; ++c)
        if (children[c].leaf >= 0) put(os, tree.leaves[size_t(children[c].leaf)].mask);
      lower = lower_end;
    }
    first = end;
  }
}

}  // namespace maquette
