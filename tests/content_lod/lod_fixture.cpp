#include "lod_fixture.h"

#include <GeographicLib/LocalCartesian.hpp>

#include "core/grid.h"

namespace maquette::test {

CellId block_cell() { return default_grid().cell_from_point({-122.3321, 47.6062}, kBaseLevel - 2); }

std::vector<CellId> base_cells() { return base_cells_under(block_cell()); }

std::vector<CellId> base_cells_under(CellId cell) {
  std::vector<CellId> cells{cell};
  while (cells.front().level() < kBaseLevel) {
    std::vector<CellId> next;
    for (CellId c : cells)
      for (int k = 0; k < 4; ++k) next.push_back(c.child(k));
    cells = next;
  }
  return cells;
}

EnuOrigin base_origin(CellId cell) {
  const LonLat c = default_grid().centre(cell);
  return {c.lon, c.lat,
          30.0 + double(cell.digit(kBaseLevel)) * 1.25 + double(cell.digit(kBaseLevel - 1)) * 7.5};
}

std::array<double, 3> reframe(const EnuOrigin& from, const EnuOrigin& to,
                              const std::array<double, 3>& p) {
  const GeographicLib::LocalCartesian a(from.lat, from.lon, from.height);
  const GeographicLib::LocalCartesian b(to.lat, to.lon, to.height);
  double lat, lon, h;
  a.Reverse(p[0], p[1], p[2], lat, lon, h);
  std::array<double, 3> out;
  b.Forward(lat, lon, h, out[0], out[1], out[2]);
  return out;
}

std::unique_ptr<Store> content_store(const std::string& path, const std::string& name,
                                     LayerKind kind) {
  auto store = Store::open(path, Store::Mode::Create);
  LayerInfo info;
  info.name = name;
  info.kind = kind;
  info.level = kBaseLevel;
  store->create_layer(info);
  return store;
}

std::map<uint64_t, std::string> overview_blobs(const Store& store, const std::string& layer) {
  std::map<uint64_t, std::string> blobs;
  for (int level = 0; level < kBaseLevel; ++level)
    for (CellId cell : store.content_cells(layer, level))
      blobs[cell.id()] = *store.get_content(layer, cell);
  return blobs;
}

}  // namespace maquette::test
