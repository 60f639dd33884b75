// Not a Google Benchmark: our placements of plants over a square, for compare_poisson_disk.sh to
// time and check beside peer samplers.
//
// Usage: vegetation_points poisson|random SIDE_M SPACING_M RUNS OUT_FILE
// Places plants over the square [0, SIDE_M)^2 at the average spacing SPACING_M RUNS times:
// `poisson` is poisson_disk (one window, the minimum distance poisson_min_distance(SPACING_M)),
// `random` the paper's placement (vegetation_random.h). Writes the last run's points to OUT_FILE
// as little-endian float64 x, y pairs, and prints one JSON line: the count, the minimum distance
// (null for `random`) and the CPU seconds of this process for each run (the placement only).
#include <time.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "poisson_disk.h"
#include "vegetation_random.h"

namespace {

using maquette::PlanePoint;
using namespace maquette::structures;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

std::vector<PlanePoint> place(const std::string& placement, double side, double spacing) {
  if (placement == "poisson") {
    const maquette::PolygonSet square({{{{0, 0}, {side, 0}, {side, side}, {0, side}, {0, 0}}}});
    return poisson_disk(square, poisson_min_distance(spacing), 1, {0, 0, side, side});
  }
  return random_placement(make_footprint({{{0, 0}, {side, 0}, {side, side}, {0, side}}}), spacing,
                          1);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string placement = argc == 6 ? argv[1] : "";
  if (placement != "poisson" && placement != "random") {
    std::cerr << "usage: vegetation_points poisson|random SIDE_M SPACING_M RUNS OUT_FILE\n";
    return 2;
  }
  const double side = std::stod(argv[2]), spacing = std::stod(argv[3]);
  const int runs = std::stoi(argv[4]);
  std::vector<PlanePoint> points;
  std::string cpu;
  for (int run = 0; run < runs; ++run) {
    const double start = cpu_seconds();
    points = place(placement, side, spacing);
    cpu += (run ? ", " : "") + std::to_string(cpu_seconds() - start);
  }
  std::ofstream out(argv[5], std::ios::binary);
  for (const PlanePoint& p : points) {
    out.write(reinterpret_cast<const char*>(&p.x), sizeof p.x);
    out.write(reinterpret_cast<const char*>(&p.y), sizeof p.y);
  }
  if (!out) {
    std::cerr << "vegetation_points: cannot write " << argv[5] << "\n";
    return 1;
  }
  // The random placement keeps no minimum distance: null.
  char min_distance[32] = "null";
  if (placement == "poisson")
    std::snprintf(min_distance, sizeof min_distance, "%.17g", poisson_min_distance(spacing));
  std::printf("{\"count\": %zu, \"min_distance\": %s, \"cpu_s\": [%s]}\n", points.size(),
              min_distance, cpu.c_str());
}
