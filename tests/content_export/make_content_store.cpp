// Writes the content export tests' store (content_store.h) at ARGV[1] for the viewer's browser
// test (tests/viewer/content.mjs), and prints where its objects are as JSON: lon, lat (degrees)
// and height (metres above the ellipsoid) of the red box's top centre and of the middle of each
// green tree.
#include <GeographicLib/LocalCartesian.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "content_store.h"

int main(int argc, char** argv) {
  using namespace maquette::test;
  if (argc != 2) {
    std::cerr << "usage: make_content_store STORE\n";
    return 2;
  }
  const ContentStore s = write_content_store(argv[1]);
  auto geodetic = [](const maquette::EnuOrigin& o, double e, double n, double u) {
    double lat, lon, h;
    GeographicLib::LocalCartesian(o.lat, o.lon, o.height).Reverse(e, n, u, lat, lon, h);
    return nlohmann::json{lon, lat, h};
  };
  nlohmann::json out = {{"box", geodetic(s.origins[0], 0, 0, kBoxHeight)},
                        {"trees", nlohmann::json::array()}};
  for (int i = 0; i < kTreeCount; ++i) {
    const auto [e, n] = tree_offset(i);
    out["trees"].push_back(geodetic(s.origins[1], e, n, kTreeHeight / 2));
  }
  std::cout << out.dump() << "\n";
  return 0;
}
