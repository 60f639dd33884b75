#include "vdb/leaf_buffers.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/avx2_clones.h"
#include "core/error.h"

namespace maquette {
namespace {

namespace io = openvdb::io;
using Leaf = openvdb::FloatTree::LeafNodeType;

// Leaves per part: a part's work (~64 leaves' compression) outweighs a task's cost, and a lake's
// thousands of leaves still make many parts to share.
constexpr size_t kLeavesPerPart = 64;

// A float leaf's buffer as LeafNode::writeBuffers writes it (io::writeCompressedValues): its value
// mask, the mask compression kind (one byte), the inactive values that kind names (0 to 2
// floats), the mask selecting between two inactive values when the kind has one, the values'
// byte count (int64, negative when Blosc could not compress them and they are stored raw), the
// values. Returns the kind and what OpenVDB's delayed-load metadata records as the compressed size:
// the byte count's magnitude and its own 8 bytes.
std::pair<int8_t, int64_t> delayed_load_entry(std::string_view leaf) {
  const size_t mask_bytes = Leaf::NodeMaskType::memUsage();
  const auto refuse = [&] {
    return Error("VDB writer: a leaf's " + std::to_string(leaf.size()) +
                 " bytes are not laid out as OpenVDB 10 writes them");
  };
  if (leaf.size() < mask_bytes + 1) throw refuse();
  const int8_t kind = int8_t(leaf[mask_bytes]);
  size_t at = mask_bytes + 1;
  if (kind == io::NO_MASK_AND_ONE_INACTIVE_VAL || kind == io::MASK_AND_ONE_INACTIVE_VAL)
    at += sizeof(float);
  if (kind == io::MASK_AND_TWO_INACTIVE_VALS) at += 2 * sizeof(float);
  if (kind == io::MASK_AND_NO_INACTIVE_VALS || kind == io::MASK_AND_ONE_INACTIVE_VAL ||
      kind == io::MASK_AND_TWO_INACTIVE_VALS)
    at += mask_bytes;
  int64_t count = 0;
  if (leaf.size() < at + sizeof count) throw refuse();
  std::memcpy(&count, leaf.data() + at, sizeof count);
  const int64_t bytes = std::abs(count) + int64_t(sizeof count);
  if (leaf.size() != at + size_t(bytes)) throw refuse();
  return {kind, bytes};
}

// Whether every voxel of a leaf's `values` holds `on_bits` where its `mask` is on and `off_bits`
// where it is off, bit for bit: by bytes of the mask (a voxel column's 8 values), the expected bits
// made from each mask bit without a branch, so that the loop vectorizes.
MAQUETTE_AVX2_CLONES bool values_follow_mask(const float* values, const uint64_t* mask,
                                             uint32_t on_bits, uint32_t off_bits) {
  const uint32_t flip = on_bits ^ off_bits;
  uint32_t differ = 0;
  for (openvdb::Index i = 0; i < Leaf::SIZE; i += 8) {
    const uint32_t byte = uint32_t(mask[i >> 6] >> (i & 63)) & 0xffu;
    for (openvdb::Index z = 0; z < 8; ++z)
      differ |= std::bit_cast<uint32_t>(values[i + z]) ^ off_bits ^ (flip & -((byte >> z) & 1u));
  }
  return differ == 0;
}

// A leaf's active values' count and value bits when they are all one value and its inactive
// values all the background, bit for bit; nothing otherwise (or without active values, or for a
// NaN background, which OpenVDB's mask compression does not find equal to itself).
std::optional<uint64_t> uniform_key(const Leaf& leaf, float background) {
  if (std::isnan(background)) return std::nullopt;
  const auto& mask = leaf.valueMask();
  const openvdb::Index first = mask.findFirstOn();
  if (first >= Leaf::SIZE) return std::nullopt;
  const float* values = leaf.buffer().data();
  const uint32_t value = std::bit_cast<uint32_t>(values[first]);
  std::array<uint64_t, Leaf::SIZE / 64> words;
  for (openvdb::Index w = 0; w < words.size(); ++w) words[w] = mask.template getWord<uint64_t>(w);
  if (!values_follow_mask(values, words.data(), value, std::bit_cast<uint32_t>(background)))
    return std::nullopt;
  return uint64_t(mask.countOn()) << 32 | value;
}

// The values' stream (io::writeData) of `key`'s count of its value.
std::string uniform_values(uint64_t key, uint32_t compression) {
  const uint32_t bits = uint32_t(key);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  const std::vector<float> values(size_t(key >> 32), value);
  std::ostringstream out(std::ios::binary);
  io::writeData(out, values.data(), openvdb::Index(values.size()), compression);
  return std::move(out).str();
}

}  // namespace

LeafBuffers leaf_buffers(const openvdb::FloatTree& tree, uint32_t compression,
                         uint32_t archive_compression) {
  // getNodes lists the leaves in the order Tree::writeBuffers writes them (the root's children in
  // order, each internal node's children in order): OpenVDB's leaf index.
  std::vector<const Leaf*> leaves;
  tree.getNodes(leaves);
  // The uniform leaves' keys, then each key's values compressed once.
  std::vector<std::optional<uint64_t>> keys(leaves.size());
  if (compression & io::COMPRESS_ACTIVE_MASK)
    tbb::parallel_for(size_t(0), leaves.size(),
                      [&](size_t l) { keys[l] = uniform_key(*leaves[l], tree.background()); });
  std::vector<uint64_t> distinct;
  for (const auto& key : keys)
    if (key) distinct.push_back(*key);
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  std::vector<std::string> streams(distinct.size());
  tbb::parallel_for(size_t(0), distinct.size(),
                    [&](size_t k) { streams[k] = uniform_values(distinct[k], compression); });
  LeafBuffers out;
  out.parts.resize((leaves.size() + kLeavesPerPart - 1) / kLeavesPerPart);
  std::vector<std::pair<int8_t, int64_t>> entries(leaves.size());
  tbb::parallel_for(size_t(0), out.parts.size(), [&](size_t p) {
    std::ostringstream part(std::ios::binary);
    io::setDataCompression(part, compression);
    io::setGridBackgroundValuePtr(part, &tree.background());
    const size_t first = p * kLeavesPerPart, end = std::min(leaves.size(), first + kLeavesPerPart);
    std::vector<size_t> starts;
    for (size_t l = first; l < end; ++l) {
      starts.push_back(size_t(part.tellp()));
      if (!keys[l]) {
        leaves[l]->writeBuffers(part, /*toHalf=*/false);
        continue;
      }
      // What LeafNode::writeBuffers writes for it: io::writeCompressedValues of a leaf whose
      // inactive values are the background writes the kind and its active values only.
      leaves[l]->valueMask().save(part);
      part.put(char(io::NO_MASK_OR_INACTIVE_VALS));
      const std::string& values = streams[size_t(
          std::lower_bound(distinct.begin(), distinct.end(), *keys[l]) - distinct.begin())];
      part.write(values.data(), std::streamsize(values.size()));
    }
    starts.push_back(size_t(part.tellp()));
    out.parts[p] = std::move(part).str();
    const std::string_view bytes = out.parts[p];
    for (size_t l = first; l < end; ++l)
      entries[l] = delayed_load_entry(
          bytes.substr(starts[l - first], starts[l - first + 1] - starts[l - first]));
  });
  if (leaves.empty()) return out;  // OpenVDB leaves a tree without leaves' metadata empty
  out.delayed.resizeMask(leaves.size());
  const bool sizes = archive_compression & (io::COMPRESS_BLOSC | io::COMPRESS_ZIP);
  if (sizes) out.delayed.resizeCompressedSize(leaves.size());
  for (size_t l = 0; l < leaves.size(); ++l) {
    out.delayed.setMask(l, entries[l].first);
    if (sizes) out.delayed.setCompressedSize(l, entries[l].second);
  }
  return out;
}

}  // namespace maquette
