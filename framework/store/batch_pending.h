// The writes a Store::Batch holds until commit() (batch.cpp), and that Batch::serialize passes to
// another process (batch_wire.cpp).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "store/store_impl.h"

namespace maquette {

struct Store::Batch::Pending {
  struct TileWrite {
    int64_t layer;
    CellId cell;
    std::vector<std::byte> blob;
  };
  struct Done {
    int64_t run;
    int step;
    int64_t key;  // a cell id or another key
  };
  // The tiles of a parent's children written so far in this batch. Once all four are, the
  // parent's overview depends on nothing else: it is built and encoded here, from the tiles in
  // memory, and written by commit() in place of a stale mark (update_overviews would decode the
  // four tiles again to build the same bytes).
  struct Siblings {
    std::array<std::optional<RawTile>, 4> tiles;  // by child digit
  };
  std::map<std::pair<int64_t, CellId>, Siblings> siblings;  // by layer id and parent
  // An overview built from fewer than four children: written only if the store holds no other.
  struct PartialOverview {
    TileWrite write;
    int64_t children;
  };
  std::vector<TileWrite> tiles, overviews;
  std::vector<PartialOverview> partial_overviews;
  std::vector<ContentWrite> contents;
  std::vector<ModelWrite> models;
  std::vector<FeatureWrite> features;
  std::vector<Artifact> artifacts;
  std::vector<Done> done;
};

}  // namespace maquette
