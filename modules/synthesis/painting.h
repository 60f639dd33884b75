// Reading a painting (an 8-bit or 16-bit image GDAL reads) and its hand-made masks (8-bit), and
// the automatic segmentation of a painting into colour classes when no hand-drawn class image is
// given.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "exemplar.h"

namespace maquette::synthesis {

// The painting's pixels (RGB 0..255; a grey image's band repeated, a palette image's indices
// through its colour table, 16-bit values divided by 257), excluded where it is transparent (an
// alpha band, a palette's transparent entries, nodata: GDAL's mask), with no labels or altitude
// yet; warns when an EXIF orientation turns it in a viewer (it is read as stored). Throws
// maquette::Error naming the file when GDAL cannot open or read it, or its bands' count or type
// (8-bit or 16-bit unsigned) do not fit, calling it `what`.
Exemplar read_painting(const std::string& path, const std::string& what = "painting");

// Throws maquette::Error "WHAT: an empty path" for "", and "PATH: WHAT: no such file" (and for a
// relative path the working directory it is relative to) when GDAL finds nothing at `path`
// (VSIStatL: virtual paths too).
void require_file(const std::string& path, const std::string& what);

// A one-band 8-bit image (a class image, an exclusion mask, an altitude) that must have the
// painting's size; `what` names it in errors.
std::vector<uint8_t> read_mask(const std::string& path, int width, int height,
                               const std::string& what);

// A one-band image of any type GDAL reads, as floats (its nodata NaN), row-major; its size in
// `width` and `height`. Throws maquette::Error naming the file, calling it `what`, when it has
// another count of bands or GDAL cannot read it.
std::vector<float> read_value_band(const std::string& path, int& width, int& height,
                                   const std::string& what);

// The painting's class image: a one-band 8-bit image of the painting's size (read_mask), or
// polygons drawn by hand: a vector file GDAL reads (GeoJSON...) whose coordinates are painting
// pixels (x the column, y the row downwards, (0, 0) the top-left corner of the top-left pixel)
// with an integer attribute "class" in 0..254 on every feature. Each pixel takes the class of the
// last polygon, in the file's order, that holds its centre (GDAL's rasterizer), so a region drawn
// later is drawn over those before it. Throws maquette::Error naming the file when a feature has
// no class, one out of range or not a number (a "class" written in quotes), when a feature is
// not a polygon or multipolygon, or when a pixel lies in no polygon.
std::vector<uint8_t> read_class_image(const std::string& path, int width, int height);

// The radius, in painting pixels, of segment_by_colour's majority filter.
inline constexpr int kClassSmoothingRadius = 4;

// Classes 0..k-1 by colour: k-means (texture/kmeans.h: deterministic seeding, no random state)
// of the painting's CIELAB histogram (texture/hs_histogram.h's "lab" bins and weights), each
// pixel the class of its bin; then each pixel takes the most frequent class of the
// (2 kClassSmoothingRadius + 1)^2 window around it, clipped to the painting (texture's
// majority_filter; ties: its own class, else the lowest). The filter makes classes regions rather
// than speckle: a painting's strokes mix colours, and a pixel-wise class leaves few pixels whose
// whole 3 x 3 neighbourhood has one class, the only ones the synthesis' label cost lets fill a
// class's interior (on Bruegel's Harvesters in 8 classes, 11 % of the foliage class's pixels at
// exemplar_scale 2). 1 <= k <= 254.
std::vector<uint8_t> segment_by_colour(const Exemplar& painting, int k);

}  // namespace maquette::synthesis
