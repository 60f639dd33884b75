// A cell's content outputs (runtime/operator.h: CellContent) checked against their contract and
// encoded as the store's blobs (content/content_blob.h): meshes by the mesh plug-in
// (plugins/content_encode.h: Draco), instances by content/instances_codec.h, volumes counted by
// the volume plug-in (plugins/vdb_content.h: OpenVDB). The plug-ins are opened on first use, so a
// run without content outputs loads neither.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "core/grid.h"
#include "runtime/operator.h"

namespace maquette {

struct ContentBlob {
  std::string port;
  std::string blob;  // an envelope of the port's content kind, for Batch::put_content
};

// The blobs of `content`'s non-empty contents (an empty one writes nothing), by port. Throws
// maquette::Error "outputs.PORT: ..." naming the object or instance at fault with its feature id,
// for any breach of CellContent's contract (`cell` at its layer's level, on `grid`). Instances'
// prototypes are built-in names or among `models`, the store's model layers.
std::vector<ContentBlob> encode_cell_content(const CellContent& content, CellId cell,
                                             const Grid& grid,
                                             const std::set<std::string>& models = {});

}  // namespace maquette
