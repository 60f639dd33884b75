// CellId: a 64-bit id of a cell of an aperture-4 hierarchical grid with up to 8 base faces.
//
// Encoding (in the style of S2's S2CellId, with one level fewer so every id is < 2^62
// and is a valid, correctly sorting SQLite INTEGER):
//
//   bit 61..59  face (0..5 for rHEALPix: N O P Q R S)
//   then 2 bits per level, from level 1 down to the cell's level: the child digit
//   then a single 1 bit (the sentinel), then zeros.
//
//   id = face << 59 | digit_1 << 57 | ... | digit_L << (59 - 2L) | 1 << (58 - 2L)
//
// A child digit is row-major from the top-left of the parent (0 1 / 2 3), i.e.
// digit = 2 * row_bit + col_bit, so the digits of a cell are the Morton interleaving
// of its row (high bit) and column (low bit) within its face. All descendants of a cell
// form the contiguous id range [range_min(), range_max()], and sorting by id is a
// depth-first (Z-order) walk of the cell tree. Levels 0..29; level 29 uses bit 0 as sentinel.
// The id 0 is never a valid cell.
//
// Text ids are the face letter followed by one digit per level: "N", "Q2013", ...
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace maquette {

class CellId {
 public:
  static constexpr int kMaxLevel = 29;
  static constexpr int kFaceBits = 3;
  static constexpr int kPosBits = 2 * kMaxLevel + 1;  // 59
  static constexpr int kNumFaces = 6;
  static constexpr std::string_view kFaceLetters = "NOPQRS";

  constexpr CellId() = default;
  constexpr explicit CellId(uint64_t id) : id_(id) {}

  // The cell at `level` with column `col` and row `row` (both in [0, 2^level)) on `face`.
  static constexpr CellId FromFaceColRow(int face, int level, uint32_t col, uint32_t row) {
    const uint64_t pos = (Spread(row) << 1) | Spread(col);
    const int shift = 2 * (kMaxLevel - level) + 1;
    return CellId((uint64_t(face) << kPosBits) | (pos << shift) | (uint64_t(1) << (shift - 1)));
  }
  static constexpr CellId FromFace(int face) { return FromFaceColRow(face, 0, 0, 0); }

  // Parses a text id ("Q2013"); nullopt when malformed or deeper than kMaxLevel.
  static std::optional<CellId> FromText(std::string_view text);
  // Parses a text id or a decimal integer id; throws maquette::Error naming the bad value.
  static CellId Parse(std::string_view text);

  constexpr uint64_t id() const { return id_; }
  constexpr bool is_valid() const {
    return (lsb() & 0x5555555555555555ULL) != 0 && id_ < (uint64_t(kNumFaces) << kPosBits);
  }
  constexpr int face() const { return int(id_ >> kPosBits); }
  constexpr uint64_t lsb() const { return id_ & (~id_ + 1); }
  constexpr int level() const { return kMaxLevel - (__builtin_ctzll(id_) >> 1); }
  constexpr bool is_face() const { return level() == 0; }
  constexpr bool is_leaf() const { return level() == kMaxLevel; }

  // Child digit (0..3) of this cell at `level` (1 <= level <= this->level()).
  constexpr int digit(int level) const { return int((id_ >> (2 * (kMaxLevel - level) + 1)) & 3); }
  constexpr uint32_t col() const { return Compact(position()); }
  constexpr uint32_t row() const { return Compact(position() >> 1); }

  constexpr CellId parent() const { return parent(level() - 1); }
  constexpr CellId parent(int level) const {
    const uint64_t new_lsb = uint64_t(1) << (2 * (kMaxLevel - level));
    return CellId((id_ & (~new_lsb + 1)) | new_lsb);
  }
  constexpr CellId child(int digit) const {
    const uint64_t new_lsb = lsb() >> 2;
    return CellId(id_ + (uint64_t(2 * digit + 1) - 4) * new_lsb);
  }
  constexpr CellId child_begin() const { return child(0); }
  // Next cell at the same level in id order (may leave the face: check is_valid()).
  constexpr CellId next() const { return CellId(id_ + (lsb() << 1)); }

  // The smallest and largest leaf-level ids among the descendants of this cell.
  constexpr CellId range_min() const { return CellId(id_ - (lsb() - 1)); }
  constexpr CellId range_max() const { return CellId(id_ + (lsb() - 1)); }
  constexpr bool contains(CellId other) const {
    return other.id_ >= range_min().id_ && other.id_ <= range_max().id_;
  }
  constexpr bool intersects(CellId other) const {
    return other.range_min().id_ <= range_max().id_ && other.range_max().id_ >= range_min().id_;
  }

  std::string ToText() const;

  // Throws maquette::Error "invalid level L: expected 0..29" unless 0 <= level <= kMaxLevel.
  static void CheckLevel(int level);

  friend constexpr bool operator==(CellId a, CellId b) = default;
  friend constexpr auto operator<=>(CellId a, CellId b) = default;

 private:
  // The Morton-interleaved digits of the cell, right-aligned.
  constexpr uint64_t position() const {
    return (id_ & ((uint64_t(1) << kPosBits) - 1)) >> (2 * (kMaxLevel - level()) + 1);
  }
  // Moves bit k of x to bit 2k (Morton interleaving without a loop) and back.
  static constexpr uint64_t Spread(uint64_t x) {
    x = (x | (x << 16)) & 0x0000FFFF0000FFFFULL;
    x = (x | (x << 8)) & 0x00FF00FF00FF00FFULL;
    x = (x | (x << 4)) & 0x0F0F0F0F0F0F0F0FULL;
    x = (x | (x << 2)) & 0x3333333333333333ULL;
    return (x | (x << 1)) & 0x5555555555555555ULL;
  }
  static constexpr uint32_t Compact(uint64_t x) {
    x &= 0x5555555555555555ULL;
    x = (x | (x >> 1)) & 0x3333333333333333ULL;
    x = (x | (x >> 2)) & 0x0F0F0F0F0F0F0F0FULL;
    x = (x | (x >> 4)) & 0x00FF00FF00FF00FFULL;
    x = (x | (x >> 8)) & 0x0000FFFF0000FFFFULL;
    return uint32_t((x | (x >> 16)) & 0xFFFFFFFFULL);
  }

  uint64_t id_ = 0;
};

}  // namespace maquette

template <>
struct std::hash<maquette::CellId> {
  size_t operator()(maquette::CellId c) const noexcept { return std::hash<uint64_t>()(c.id()); }
};
