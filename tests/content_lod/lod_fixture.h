// Content layers written by the tests of coarser levels (content/content_overviews.h): 4 x 4
// cells at kBaseLevel (the grandchildren of one cell at kBaseLevel - 2), their origins, and an
// independent ENU oracle (GeographicLib::LocalCartesian).
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "content/content.h"
#include "core/cell_id.h"
#include "store/store.h"

namespace maquette::test {

inline constexpr int kBaseLevel = 14;

// The level kBaseLevel - 2 cell the tests fill (around Seattle), and its 16 grandchildren in
// id order.
CellId block_cell();
std::vector<CellId> base_cells();

// A cell's centre at a height that differs from cell to cell (so that parents' heights are
// means of distinct values).
EnuOrigin base_origin(CellId cell);

// A point of frame `from` in frame `to`, through geodetic coordinates (LocalCartesian).
std::array<double, 3> reframe(const EnuOrigin& from, const EnuOrigin& to,
                              const std::array<double, 3>& p);

// A new store with one content layer `name` of `kind` at kBaseLevel.
std::unique_ptr<Store> content_store(const std::string& path, const std::string& name,
                                     LayerKind kind);

// Every overview blob of the layer, by cell id (all levels below the layer's).
std::map<uint64_t, std::string> overview_blobs(const Store& store, const std::string& layer);

// The stored base cells under `cell` (inclusive), in id order.
std::vector<CellId> base_cells_under(CellId cell);

}  // namespace maquette::test
