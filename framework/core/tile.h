// Tiles: the raster held by one stored cell. A tile of cell c at level L has N x N samples
// (N a power of two) at the centres of c's descendants at level L + log2(N), row-major from
// the top-left, each with `channels` interleaved values. A tile may carry a halo of h pixels on
// every side (assembled from neighbouring tiles, see core/halo.h): then at(col, row) accepts
// col, row in [-h, N + h). Anything that must be seamless across tiles is a function of global
// face pixel coordinates (global_col/global_row), never of tile-local ones.
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/cell_id.h"

namespace maquette {

enum class DType : uint8_t { U8, U16, I16, U32, I32, F32, F64 };

size_t dtype_size(DType t);
std::string_view dtype_name(DType t);
// Parses "uint8", "uint16", "int16", "uint32", "int32", "float32", "float64"; throws
// maquette::Error.
DType parse_dtype(std::string_view name);

template <typename T>
constexpr DType dtype_of();
template <>
constexpr DType dtype_of<uint8_t>() {
  return DType::U8;
}
template <>
constexpr DType dtype_of<uint16_t>() {
  return DType::U16;
}
template <>
constexpr DType dtype_of<int16_t>() {
  return DType::I16;
}
template <>
constexpr DType dtype_of<uint32_t>() {
  return DType::U32;
}
template <>
constexpr DType dtype_of<int32_t>() {
  return DType::I32;
}
template <>
constexpr DType dtype_of<float>() {
  return DType::F32;
}
template <>
constexpr DType dtype_of<double>() {
  return DType::F64;
}

// An allocator whose value-less construct() default-initializes (construction from values is
// std::construct_at's, through std::allocator_traits): a vector<T> of arithmetic T resized with
// it leaves its samples uninitialized (Tile::uninitialized), instead of zeroing them.
template <typename T>
struct DefaultInitAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  using std::allocator<T>::allocator;
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
};

template <typename T>
class Tile {
 public:
  Tile() = default;
  Tile(int size, int channels, int halo = 0, T fill = T{})
      : size_(size), channels_(channels), halo_(halo), data_(sample_count(), fill) {}

  // A tile whose samples (halo included) hold indeterminate values: for a caller that writes
  // every one of them before reading any, and so saves the fill of a large tile.
  static Tile uninitialized(int size, int channels, int halo = 0) {
    Tile tile;
    tile.size_ = size;
    tile.channels_ = channels;
    tile.halo_ = halo;
    tile.data_.resize(tile.sample_count());
    return tile;
  }

  int size() const { return size_; }
  int channels() const { return channels_; }
  int halo() const { return halo_; }
  int stride() const { return size_ + 2 * halo_; }  // samples per row, halo included

  T& at(int col, int row, int channel = 0) { return data_[index(col, row, channel)]; }
  const T& at(int col, int row, int channel = 0) const { return data_[index(col, row, channel)]; }

  // All samples, halo included, row-major with interleaved channels.
  std::span<T> data() { return data_; }
  std::span<const T> data() const { return data_; }

  // The tile without its halo (a copy), as stored.
  Tile<T> interior() const {
    Tile<T> out(size_, channels_);
    for (int r = 0; r < size_; ++r)
      for (int c = 0; c < size_; ++c)
        for (int k = 0; k < channels_; ++k) out.at(c, r, k) = at(c, r, k);
    return out;
  }

 private:
  size_t sample_count() const { return size_t(stride()) * size_t(stride()) * size_t(channels_); }
  size_t index(int col, int row, int channel) const {
    assert(col >= -halo_ && col < size_ + halo_ && row >= -halo_ && row < size_ + halo_);
    return (size_t(row + halo_) * size_t(stride()) + size_t(col + halo_)) * size_t(channels_) +
           size_t(channel);
  }

  int size_ = 0;
  int channels_ = 0;
  int halo_ = 0;
  std::vector<T, DefaultInitAllocator<T>> data_;
};

// A tile of any sample type, as the store keeps it (no halo): `bytes` holds
// size * size * channels samples of `dtype`, native byte order.
struct RawTile {
  DType dtype = DType::F32;
  int size = 0;
  int channels = 1;
  std::vector<std::byte> bytes;

  size_t sample_count() const { return size_t(size) * size_t(size) * size_t(channels); }
};

// Conversions between RawTile and typed tiles. to_tile<float> maps `nodata` to NaN;
// from_tile<T> maps NaN back to `nodata` (and rounds/clamps for integer types).
template <typename T>
Tile<T> to_tile(const RawTile& raw, const double* nodata = nullptr);
template <typename T>
RawTile from_tile(const Tile<T>& tile, DType dtype, const double* nodata = nullptr);

// Global pixel coordinates on the tile's face (at level cell.level() + log2(size)).
inline int64_t global_col(CellId cell, int size, int col) {
  return int64_t(cell.col()) * size + col;
}
inline int64_t global_row(CellId cell, int size, int row) {
  return int64_t(cell.row()) * size + row;
}
int log2_tile_size(int size);  // throws maquette::Error unless size is a power of two in [1, 4096]
// The tile size of a layer that gets overviews (ingest, pipelines): a power of two in [2, 4096],
// since each overview halves the tiles. Throws maquette::Error saying which rule `size` breaks.
void check_overview_tile_size(int size);

}  // namespace maquette
