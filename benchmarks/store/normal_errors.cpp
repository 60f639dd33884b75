// Not a Google Benchmark: a normal layer stored with codec normal_oct against the same layer in
// float32 (zstd), from two runs of one pipeline (before and after the operator declared the codec):
//   normal_errors FLOAT_STORE OCT_STORE LAYER
// prints both layers' bytes (overviews included) and their ratio, and the largest and mean angle
// between the float and the decoded normals over the full-resolution tiles and over the overview
// tiles (means of normals, stored as their directions).
#include <cmath>
#include <cstring>
#include <iostream>
#include <numbers>
#include <set>
#include <vector>

#include "store/store.h"

namespace {

using maquette::CellId;
using maquette::RawTile;
using maquette::Store;

struct Errors {
  double max = 0, sum = 0;
  int64_t count = 0;

  void add(const RawTile& reference, const RawTile& decoded) {
    std::vector<float> a(reference.sample_count()), b(decoded.sample_count());
    std::memcpy(a.data(), reference.bytes.data(), reference.bytes.size());
    std::memcpy(b.data(), decoded.bytes.data(), decoded.bytes.size());
    for (size_t i = 0; i + 2 < a.size(); i += 3) {
      if (std::isnan(a[i])) continue;
      const double ax = a[i], ay = a[i + 1], az = a[i + 2], bx = b[i], by = b[i + 1], bz = b[i + 2];
      const double cross = std::hypot(ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx);
      const double e = std::atan2(cross, ax * bx + ay * by + az * bz) * 180 / std::numbers::pi;
      max = std::max(max, e);
      sum += e;
      ++count;
    }
  }
  void print(const char* what) const {
    std::cout << what << ": " << count << " normals, max " << max << " mean " << sum / double(count)
              << " degrees\n";
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: normal_errors FLOAT_STORE OCT_STORE LAYER\n";
    return 2;
  }
  try {
    const auto floats = Store::open(argv[1], Store::Mode::ReadOnly);
    const auto octs = Store::open(argv[2], Store::Mode::ReadOnly);
    const std::string layer = argv[3];
    const int64_t float_bytes = floats->stats(layer).bytes, oct_bytes = octs->stats(layer).bytes;
    std::cout << layer << ": " << floats->require_layer(layer).codec << " " << float_bytes
              << " bytes, " << octs->require_layer(layer).codec << " " << oct_bytes
              << " bytes: " << double(float_bytes) / double(oct_bytes) << "x smaller\n";
    Errors base, overviews;
    std::set<CellId> parents;
    for (const CellId cell : floats->tile_cells(layer)) {
      base.add(*floats->get_tile(layer, cell), *octs->get_tile(layer, cell));
      for (CellId p = cell; p.level() > 0;) {
        p = p.parent();
        parents.insert(p);
      }
    }
    for (const CellId cell : parents) {
      const auto a = floats->get_overview(layer, cell), b = octs->get_overview(layer, cell);
      if (a && b) overviews.add(*a, *b);
    }
    base.print("full resolution");
    overviews.print("overviews");
  } catch (const std::exception& e) {
    std::cerr << "normal_errors: " << e.what() << '\n';
    return 1;
  }
}
