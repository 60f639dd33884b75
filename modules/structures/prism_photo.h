// structures.prism's photo: its pixels, and its focal length in pixels when the strokes do not
// give it: from its EXIF tags (read by GDAL as EXIF_* metadata), else a prior to start from.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>

class GDALDataset;

namespace maquette::structures {

struct Photo {
  cv::Mat pixels;                  // 8-bit BGR (OpenCV's order), or grey
  std::optional<double> focal_px;  // from EXIF (exif_focal_px)
};

// Any image GDAL reads with 1 band (grey) or 3-4 (RGB, alpha dropped), 8-bit. Throws
// maquette::Error naming the file when GDAL cannot open or read it, its bands do not fit, or its
// EXIF_Orientation is other than 1 (upright: the clicks would be on a turned picture).
Photo read_photo(const std::string& path);

// The diagonal of a 36 x 24 mm frame, by which cameras scale EXIF_FocalLengthIn35mmFilm (the
// crop factor is a ratio of diagonals).
inline constexpr double kFullFrameDiagonalMm = 43.266615305567875;

// From EXIF_FocalLengthIn35mmFilm (f_px = f35 * the image's diagonal in pixels /
// kFullFrameDiagonalMm), else EXIF_FocalLength (mm) with EXIF_FocalPlaneXResolution and
// EXIF_FocalPlaneResolutionUnit (2: inch, 3: cm; the sensor's pixels per unit), times the image's
// width over EXIF_PixelXDimension when the photo was resized. Nothing when the photo has neither.
std::optional<double> exif_focal_px(GDALDataset& photo);

// The prior without EXIF: the image's diagonal in pixels, a 35 mm-equivalent focal length of
// 43 mm (53 degrees of diagonal field of view, a "normal" lens). solve_prism then estimates the
// focal length when the clicks over-determine the prism (tests/prism_solver_test.cpp: median
// 3.6 % from starts 0.6-1.7 times the truth with two more extrusion ends).
double prior_focal_px(int width, int height);

}  // namespace maquette::structures
