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
#include <utility>
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

// The values' streams (io::writeData) of uniform leaves: for each distinct key (the count of
// active values << 32 | their value's bits), that count of that value, compressed once.
class UniformStreams {
 public:
  UniformStreams(std::vector<uint64_t> keys, uint32_t compression) : keys_(std::move(keys)) {
    std::sort(keys_.begin(), keys_.end());
    keys_.erase(std::unique(keys_.begin(), keys_.end()), keys_.end());
    streams_.resize(keys_.size());
    tbb::parallel_for(size_t(0), keys_.size(), [&](size_t k) {
      const uint32_t bits = uint32_t(keys_[k]);
      const std::vector<float> values(size_t(keys_[k] >> 32), std::bit_cast<float>(bits));
      std::ostringstream out(std::ios::binary);
      io::writeData(out, values.data(), openvdb::Index(values.size()), compression);
      streams_[k] = std::move(out).str();
    });
  }

  // The stream of a key among those given.
  const std::string& of(uint64_t key) const {
    return streams_[size_t(std::lower_bound(keys_.begin(), keys_.end(), key) - keys_.begin())];
  }

 private:
  std::vector<uint64_t> keys_;
  std::vector<std::string> streams_;
};

// What LeafNode::writeBuffers writes for a leaf of value mask `mask` whose active values are one
// value and whose inactive values are the background (io::writeCompressedValues by active mask):
// the mask, the kind "no inactive values" and the active values' stream.
void write_uniform_leaf(std::ostream& part, const uint64_t* mask, const std::string& values) {
  part.write(reinterpret_cast<const char*>(mask), Leaf::NodeMaskType::memUsage());
  part.put(char(io::NO_MASK_OR_INACTIVE_VALS));
  part.write(values.data(), std::streamsize(values.size()));
}

// The buffers of `count` leaves, leaf l written by write(l, part), in parts of kLeavesPerPart
// leaves made in parallel on streams of `compression` and the grid's `background`, and their
// delayed-load metadata for `archive_compression`, read from their bytes.
template <typename Write>
LeafBuffers by_parts(size_t count, uint32_t compression, uint32_t archive_compression,
                     const float* background, const Write& write) {
  LeafBuffers out;
  out.parts.resize((count + kLeavesPerPart - 1) / kLeavesPerPart);
  std::vector<std::pair<int8_t, int64_t>> entries(count);
  tbb::parallel_for(size_t(0), out.parts.size(), [&](size_t p) {
    std::ostringstream part(std::ios::binary);
    io::setDataCompression(part, compression);
    io::setGridBackgroundValuePtr(part, background);
    const size_t first = p * kLeavesPerPart, end = std::min(count, first + kLeavesPerPart);
    std::vector<size_t> starts;
    for (size_t l = first; l < end; ++l) {
      starts.push_back(size_t(part.tellp()));
      write(l, part);
    }
    starts.push_back(size_t(part.tellp()));
    out.parts[p] = std::move(part).str();
    const std::string_view bytes = out.parts[p];
    for (size_t l = first; l < end; ++l)
      entries[l] = delayed_load_entry(
          bytes.substr(starts[l - first], starts[l - first + 1] - starts[l - first]));
  });
  if (count == 0) return out;  // OpenVDB leaves a tree without leaves' metadata empty
  out.delayed.resizeMask(count);
  const bool sizes = archive_compression & (io::COMPRESS_BLOSC | io::COMPRESS_ZIP);
  if (sizes) out.delayed.resizeCompressedSize(count);
  for (size_t l = 0; l < count; ++l) {
    out.delayed.setMask(l, entries[l].first);
    if (sizes) out.delayed.setCompressedSize(l, entries[l].second);
  }
  return out;
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
  std::vector<uint64_t> uniform;
  for (const auto& key : keys)
    if (key) uniform.push_back(*key);
  const UniformStreams streams(std::move(uniform), compression);
  return by_parts(leaves.size(), compression, archive_compression, &tree.background(),
                  [&](size_t l, std::ostream& part) {
                    if (!keys[l]) return leaves[l]->writeBuffers(part, /*toHalf=*/false);
                    std::array<uint64_t, Leaf::SIZE / 64> mask;
                    for (openvdb::Index w = 0; w < mask.size(); ++w)
                      mask[w] = leaves[l]->valueMask().template getWord<uint64_t>(w);
                    write_uniform_leaf(part, mask.data(), streams.of(*keys[l]));
                  });
}

LeafBuffers fog_leaf_buffers(const FogTree& tree, uint32_t compression,
                             uint32_t archive_compression) {
  if (!(compression & io::COMPRESS_ACTIVE_MASK))
    throw Error(
        "VDB writer: a fog tree's leaves are written with active-mask compression only "
        "(compression flags " +
        std::to_string(compression) + ")");
  // Every leaf is uniform: its active values kFogDensity, its inactive ones the background.
  std::vector<uint64_t> keys(tree.leaves.size());
  for (size_t l = 0; l < keys.size(); ++l) {
    uint64_t on = 0;
    for (const uint64_t word : tree.leaves[l].mask) on += uint64_t(std::popcount(word));
    keys[l] = on << 32 | std::bit_cast<uint32_t>(kFogDensity);
  }
  const UniformStreams streams(keys, compression);
  return by_parts(tree.leaves.size(), compression, archive_compression, &kFogBackground,
                  [&](size_t l, std::ostream& part) {
                    write_uniform_leaf(part, tree.leaves[l].mask.data(), streams.of(keys[l]));
                  });
}

}  // namespace maquette
