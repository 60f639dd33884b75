// One zstd frame holding its content size and checksum (XXH64): the instances' payload
// (content/instances_codec.h) and the synthesis's exemplar cache files store their bytes so.
#pragma once

#include <string>
#include <string_view>

namespace maquette {

// Appends `content` to `out` compressed at zstd level `level` as one frame with its content size
// and checksum. Throws maquette::Error when zstd fails.
void append_zstd_frame(std::string_view content, int level, std::string& out);

// The content of `frame`, which must be exactly one whole zstd frame (nothing after it) declaring
// its content size. The output grows as the frame decompresses, never sized from the header: a
// frame claiming more than it holds (any size, 2^60 bytes) is refused having allocated memory in
// proportion to what it holds (plus one ZSTD_DStreamOutSize() chunk). The checksum, when the frame
// has one, is verified. Throws maquette::Error saying what is wrong: "not a zstd frame with its
// content size", "N bytes after the zstd frame", "the zstd frame is truncated", "the zstd frame
// holds more than its content size", "the zstd frame holds N bytes, not the M it declares", or
// zstd's own error ("zstd frame: ...", e.g. a checksum that does not match).
std::string zstd_frame_content(std::string_view frame);

}  // namespace maquette
