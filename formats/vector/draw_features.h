// Features drawn over a quicklook (`maquette export png --overlay FEATURES`), or alone on a plain
// background (`export png --layer FEATURES`): polygon outlines and lines as magenta lines in a
// dark casing, points as dots, antialiased, in the picture's projection.
#pragma once

#include <vector>

#include "image/layer_cells.h"
#include "image/mosaic.h"
#include "image/rgba_image.h"
#include "store/store.h"

namespace maquette {

// Draws `features` (WKB in lon/lat) on `image`, whose pixels lie in `frame`.
void draw_features(RgbaImage& image, const PictureFrame& frame,
                   const std::vector<Feature>& features);

// Makes the transparent pixels of `image` (no data) a plain light grey.
void fill_background(RgbaImage& image);

// A picture without data framing the region (a box or cells), or without one the features'
// bounding box with a margin, in `projection`, with pixels of 1 m doubled until its longer side
// fits `max_side`: what features are drawn on alone.
PictureRaster blank_picture(const Grid& grid, const RegionSpec& region,
                            const std::vector<Feature>& features, Projection projection,
                            int max_side);

}  // namespace maquette
