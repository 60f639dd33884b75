// A panorama drawn by `maquette render panorama` (formats/render/README.md) read back as the
// target of the transfer in the picture: its colours and, from STEM-guides.tif beside it, the
// guides by band name (the reader also serves the painting's guides: painting_guides.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace maquette::synthesis {

struct PanoramaPicture {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // 3 per pixel, row-major: the rendered picture (its sky is kept)
  // Per pixel, NaN on the sky: land-cover class, altitude (metres), distance from the eye
  // (metres), and the shading factor the render applied (0.3 to 1; empty when the guides have no
  // `shading` band: rendered before it existed).
  std::vector<float> land_cover, altitude, distance, shading;
  // Rendered with --antialias: the share of each pixel's samples that see terrain (0 to 1, not
  // NaN on the sky); else empty.
  std::vector<float> coverage;
};

// A band of a guides file, found by its name (its GDAL band description); `hint` is said when it
// is missing and `required`.
struct GuideBand {
  std::string name, hint;
  bool required = true;
};

// The bands `wanted` of the guides GeoTIFF `path` (float, NaN on the sky, as `render panorama`
// and `render fit --panorama` write them), in their order: each width x height floats,
// row-major, or empty (absent and not required). Throws maquette::Error naming `path` and what
// is wrong: unreadable, not width x height pixels (then naming `of`, e.g. "the picture P.png",
// and both sizes), a required band missing (its name and hint).
std::vector<std::vector<float>> read_guide_bands(const std::string& path, int width, int height,
                                                 const std::string& of,
                                                 const std::vector<GuideBand>& wanted);

// Reads PICTURE (8-bit RGB) and its guides (core/sibling_path.h: PICTURE's stem + "-guides.tif");
// the `shading` band is required when `with_shading`, else read if present; `coverage` read if
// present. Throws
// maquette::Error naming the file and what is wrong: unreadable, a band missing (land_cover:
// render with --land-cover), another size.
PanoramaPicture read_panorama(const std::string& picture, bool with_shading);

}  // namespace maquette::synthesis
