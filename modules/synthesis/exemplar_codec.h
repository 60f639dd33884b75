// The analysed exemplar (transfer_exemplar.h) as the bytes of a cache file (exemplar_cache.h) and
// back. A file is a header (magic, format version, the key it was stored under) then the payload,
// every field of TransferExemplar in native byte order (the cache is a machine's own), as one zstd
// frame with its content size and checksum (core/zstd_frame.h: a header's size is never trusted
// before the frame is read).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "transfer_exemplar.h"

namespace maquette::synthesis {

// The cache files' format number: part of every key and checked in every file. Bump it when the
// file's layout or TransferExemplar's changes (a static_assert in exemplar_codec.cpp catches a
// field added to ExemplarLevel); older files then miss and are recomputed. A change of the
// analysis's code is told apart by the build holding it, in the key (exemplar_cache.h), but where
// the build cannot be found only its constants are: a change of its results bumps the number too
// (2: the k similar patches searched approximately; 3: each level's light guide; 4: the finest
// level's class edges; 5: each level's region quantiles, 6: as bytes).
inline constexpr uint32_t kExemplarCacheVersion = 6;

// The file holding `exemplar` stored under `key` (any bytes, e.g. a digest).
std::string encode_exemplar(const TransferExemplar& exemplar, std::string_view key);

// The exemplar of a file written by encode_exemplar under `key`. Throws maquette::Error saying
// what is wrong when the file is not one (magic), another version, stored under another key,
// truncated, its checksum or sizes do not match, or its fields disagree with their levels' sizes.
TransferExemplar decode_exemplar(std::string_view file, std::string_view key);

}  // namespace maquette::synthesis
