// 8-bit images (PNG, JPEG) written through GDAL's raster drivers from interleaved pixels, so
// that quicklooks and GLB textures need no other image library.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace maquette {

class OutputFile;

struct ImageFormat {
  std::string driver;                // a GDAL driver with CreateCopy: "PNG", "JPEG"
  std::vector<std::string> options;  // its creation options, "KEY=VALUE"
};

// Writes `pixels` (width x height pixels of `bands` interleaved bytes, row-major) to `path`
// (any GDAL path, /vsimem/ included; a file whole or not at all: core/output_file.h); throws
// maquette::Error naming the path and GDAL's reason.
void write_image(std::span<const uint8_t> pixels, int width, int height, int bands,
                 const ImageFormat& format, const std::string& path);

// The same into the temporary file of `out`, for a writer that adds sidecars before committing it.
void write_image(std::span<const uint8_t> pixels, int width, int height, int bands,
                 const ImageFormat& format, const OutputFile& out);

// The same, encoded into memory: the file's bytes.
std::vector<uint8_t> encode_image(std::span<const uint8_t> pixels, int width, int height, int bands,
                                  const ImageFormat& format);

}  // namespace maquette
