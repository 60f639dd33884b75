#include "core/cell_id.h"

#include <charconv>

#include "core/error.h"

namespace maquette {

std::optional<CellId> CellId::FromText(std::string_view text) {
  if (text.empty() || text.size() > size_t(kMaxLevel) + 1) return std::nullopt;
  const size_t face = kFaceLetters.find(text[0]);
  if (face == std::string_view::npos) return std::nullopt;
  const int level = int(text.size()) - 1;
  uint64_t id = uint64_t(face) << kPosBits;
  for (int k = 1; k <= level; ++k) {
    const char c = text[size_t(k)];
    if (c < '0' || c > '3') return std::nullopt;
    id |= uint64_t(c - '0') << (2 * (kMaxLevel - k) + 1);
  }
  return CellId(id | uint64_t(1) << (2 * (kMaxLevel - level)));
}

CellId CellId::Parse(std::string_view text) {
  if (const auto cell = FromText(text)) return *cell;
  uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc() && end == text.data() + text.size() && CellId(value).is_valid()) {
    return CellId(value);
  }
  throw Error("invalid cell id '" + std::string(text) +
              "': expected a face letter N O P Q R S followed by up to 29 digits 0-3, or a valid "
              "64-bit integer id");
}

std::string CellId::ToText() const {
  if (!is_valid()) throw Error("invalid cell id " + std::to_string(id_));
  std::string text(1, kFaceLetters[size_t(face())]);
  for (int k = 1; k <= level(); ++k) text += char('0' + digit(k));
  return text;
}

void CellId::CheckLevel(int level) {
  if (level < 0 || level > kMaxLevel)
    throw Error("invalid level " + std::to_string(level) + ": expected 0.." +
                std::to_string(kMaxLevel));
}

}  // namespace maquette
