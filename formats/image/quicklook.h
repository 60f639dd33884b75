// PNG quicklooks of a picture raster: class colours for categorical layers, three chosen channels
// as RGB (imagery), else one channel through a colour ramp, optionally multiplied by a
// hillshade of the layer itself. Stretched ramps and imagery go between the given or the 2-98 %
// range of each drawn channel; the hypsometric ramp maps metres to fixed colours. No data is
// transparent. A legend (colour bar with values and units, or class names) can go below.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "image/class_table.h"
#include "image/colour_ramp.h"
#include "image/mosaic.h"
#include "image/rgba_image.h"

namespace maquette {

struct QuicklookStyle {
  // One-channel layers; none: chosen by the values (diverging when they span both signs, else
  // viridis).
  std::optional<Ramp> ramp = std::nullopt;
  std::optional<std::pair<double, double>> range;  // value mapped to 0 and to 1
  bool hillshade = false;                          // one-channel layers: shade the ramp
  std::vector<int> bands = {};  // 0-based channels drawn as R, G, B (3+ channels; default 0 1 2)
  std::optional<ClassTable> classes = std::nullopt;  // set for categorical layers
  bool legend = false;                               // a legend below the picture
  std::string units = "";                            // of the values, for the legend
};

// Throws maquette::Error naming the option of `style` that would do nothing on a layer of
// `channels` channels (0: a features layer, drawn alone): --ramp, --range, --hillshade or --bands
// on class colours or features; --ramp or --hillshade on imagery (3+ channels, drawn as RGB);
// --bands on one channel; --range under the hypsometric ramp (fixed tints by metres). Also a
// --range not two finite, distinct values.
void check_quicklook_style(const QuicklookStyle& style, int channels);

// The picture of `m` in `style`, without a legend: one image pixel per raster pixel (a legend
// added later goes below and to the right, so the frame stays valid). Throws
// maquette::Error when a band is out of range.
RgbaImage render_quicklook(const PictureRaster& m, const QuicklookStyle& style);

// Draws over the map (e.g. vector features) before the legend is added; the frame tells where
// the pixels lie.
using Overlay = std::function<void(RgbaImage& map, const PictureFrame& frame)>;

// Writes an RGBA PNG (the overlay drawn when `m` has a frame, then the legend when asked for)
// and, when `m` has a frame, its georeferencing beside it: OUT.aux.xml (CRS and geotransform,
// read by GDAL and QGIS) and the world file OUT.pgw. Throws maquette::Error naming the path when
// it cannot be written.
void write_quicklook_png(const PictureRaster& m, const QuicklookStyle& style,
                         const std::string& path, const Overlay& overlay = nullptr);

}  // namespace maquette
