// The payload of `instances` content blobs (store/README.md, "Instances payload"): lossless and
// columnar. Each column is contiguous (vector columns component by component: all x, then all
// y, ...), numbers little endian and byte shuffled as store/codec.h's tiles are, strings
// length-prefixed, the whole compressed as one zstd frame with its content size and checksum.
// Decoding gives back every value bit for bit (NaN payloads, -0, subnormals included).
#pragma once

#include <string>
#include <string_view>

#include "content/content.h"

namespace maquette {

// What every InstancesContent written or read must satisfy; a fault throws maquette::Error
// naming `where`, and the instance (with its feature id when it has provenance):
// - every column has size() entries (position, scale x3; rotation x4; provenance 0 or size()),
//   at most 2^32 - 1 instances, at most 65536 prototypes, every prototype index below their
//   count, every prototype name non-empty;
// - rotations are unit quaternions (| |q| - 1 | <= kUnitQuaternionTolerance), scales finite;
// - provenance attributes are JSON objects.
// Positions are carried as they are (the writer places each instance in the cell of its
// position, the anchor rule of content.h).
inline constexpr double kUnitQuaternionTolerance = 1e-5;
void check_instances(const InstancesContent& content, const std::string& where);

// The payload alone (the origin is the envelope's). Checks the content first (check_instances).
std::string encode_instances(const InstancesContent& content);
// Throws maquette::Error naming `where` and the fault for any bytes that are not such a payload
// (truncated, corrupt, trailing bytes, columns of the wrong length, values breaking
// check_instances); never reads outside `payload`. The origin is left default.
InstancesContent decode_instances(std::string_view payload, const std::string& where);

// The whole blob: the envelope (kind instances, the content's origin, objects = instances)
// around encode_instances' payload; and back, checking the envelope's kind and object count.
std::string wrap_instances(const InstancesContent& content);
InstancesContent unwrap_instances(std::string_view blob, const std::string& where);

}  // namespace maquette
