// The envelope of a content blob (store/README.md): what the store's tiles and overviews tables
// hold for layers of kind mesh, instances and volume. A 64-byte header, then the payload:
//
//   0  magic "MQCT"         4  format version (u16 LE, 1)   6  kind (ContentKind)
//   7  encoding (1: mesh GLB, instances columnar zstd, volume VDB stream)
//   8  origin lon (f64 LE, degrees)  16  origin lat (f64 LE)  24  origin height (f64 LE, metres)
//   32 objects (u64 LE)      40  triangles (u64 LE)          48  voxels (u64 LE)
//   56 payload bytes (u64 LE)
//
// The header is all `maquette info` reads (SQLite substr of the blob), and the ENU origin is kept
// in double precision beside payloads that hold float32 positions.
#pragma once

#include <string>
#include <string_view>

#include "content/content.h"

namespace maquette {

inline constexpr size_t kContentHeaderBytes = 64;

struct ContentEnvelope {
  ContentKind kind = ContentKind::Mesh;
  uint8_t encoding = 1;
  EnuOrigin origin;
  ContentStats stats;
};

// "mesh", "instances", "volume": also the names of the store's layer kinds that hold them.
std::string_view content_kind_name(ContentKind kind);

// What is wrong with an ENU origin (not finite, or lon/lat outside [-180, 180] x [-90, 90]), or
// nothing: an empty string.
std::string origin_fault(const EnuOrigin& origin);

// Throws maquette::Error for an unknown kind or encoding, or an origin that is not finite or
// outside [-180, 180] x [-90, 90].
std::string wrap_content(const ContentEnvelope& envelope, std::string_view payload);
// Throws maquette::Error naming `where` (e.g. "layer buildings, cell N3021") and what is wrong:
// too short, bad magic, unknown version, kind or encoding, an origin wrap_content refuses, payload
// size disagreeing.
ContentEnvelope read_content_envelope(std::string_view blob, const std::string& where);
std::string_view content_payload(std::string_view blob);  // after read_content_envelope
// The same checks from the blob's first bytes (at least its header) and its size, for a reader
// that does not fetch the payload (Store::content_stats).
ContentEnvelope read_content_header(std::string_view head, uint64_t blob_bytes,
                                    const std::string& where);

}  // namespace maquette
