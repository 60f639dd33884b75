#include "image/quicklook.h"

#include <gdal_priv.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "gdal/image_file.h"
#include "image/hillshade.h"
#include "image/legend.h"
#include "image/stretch.h"

namespace maquette {
namespace {

// The q0 and q1 quantiles of the finite values of one channel.
std::pair<double, double> channel_quantiles(const PictureRaster& m, int channel, double q0,
                                            double q1) {
  std::vector<float> v;
  v.reserve(size_t(m.width) * size_t(m.height));
  for (int r = 0; r < m.height; ++r)
    for (int c = 0; c < m.width; ++c) v.push_back(m.at(c, r, channel));
  return quantile_range(v, q0, q1);
}

// The channels drawn: the chosen bands for imagery, else channel 0.
std::vector<int> drawn_channels(const PictureRaster& m, const QuicklookStyle& style) {
  if (style.classes || m.channels < 3) return {0};
  std::vector<int> bands = style.bands.empty() ? std::vector<int>{0, 1, 2} : style.bands;
  if (bands.size() != 3) throw Error("--bands needs three bands (R,G,B)");
  for (int b : bands)
    if (b < 0 || b >= m.channels)
      throw Error("band " + std::to_string(b + 1) + " out of range: the layer has " +
                  std::to_string(m.channels) + " channels");
  return bands;
}

// The values a stretched channel maps to 0 and 1: the given range or the 2-98 % one.
std::pair<double, double> stretch_range(const PictureRaster& m, const QuicklookStyle& style,
                                        int channel) {
  return style.range ? *style.range
                     : channel_quantiles(m, channel, kDisplayStretch.first, kDisplayStretch.second);
}

// The legend of a one-channel or categorical picture; none for imagery.
std::optional<Legend> legend_of(const PictureRaster& m, const QuicklookStyle& style) {
  if (style.classes) {
    std::vector<bool> seen;
    Legend legend{ClassKey{}};
    auto& key = std::get<ClassKey>(legend);
    for (const auto& [value, entry] : *style.classes) {
      bool present = false;
      for (size_t i = 0; i < m.values.size() && !present; i += size_t(m.channels))
        present = std::isfinite(m.values[i]) && std::llround(m.values[i]) == value;
      if (present)
        key.push_back({class_colour(*style.classes, value),
                       entry.name.empty() ? std::to_string(value) : entry.name});
    }
    return legend;
  }
  if (m.channels >= 3) return std::nullopt;
  ColourBar bar{style.ramp, 0, 1, style.units};
  std::tie(bar.low, bar.high) = style.ramp == Ramp::Hypsometric ? channel_quantiles(m, 0, 0.0, 1.0)
                                                                : stretch_range(m, style, 0);
  return Legend{bar};
}

// Writes the frame as OUT.aux.xml (through GDAL's side-car mechanism, which a read-only PNG
// keeps there) and as the world file OUT.pgw.
void write_georeference(const PictureFrame& frame, const std::string& path) {
  std::array<double, 6> gt = frame.geotransform();
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds || ds->SetGeoTransform(gt.data()) != CE_None ||
      ds->SetProjection(frame.crs_wkt().c_str()) != CE_None)
    throw Error("cannot georeference " + path + ": " + CPLGetLastErrorMsg());
  ds.reset();
  if (!GDALWriteWorldFile(path.c_str(), "pgw", gt.data()))
    throw Error("cannot write the world file of " + path + ": " + CPLGetLastErrorMsg());
}

}  // namespace

RgbaImage render_quicklook(const PictureRaster& m, const QuicklookStyle& style) {
  const std::vector<int> channels = drawn_channels(m, style);
  const bool rgb = channels.size() == 3;
  std::vector<std::pair<double, double>> ranges;
  if (!style.classes)
    for (int k : channels) ranges.push_back(stretch_range(m, style, k));
  const std::vector<float> shade =
      style.hillshade && !rgb && !style.classes ? hillshade(m) : std::vector<float>{};

  RgbaImage image(m.width, m.height);
  for (int r = 0; r < m.height; ++r) {
    for (int c = 0; c < m.width; ++c) {
      const float v0 = m.at(c, r, channels[0]);
      if (!std::isfinite(v0)) continue;  // transparent
      auto t = [&](size_t k) {
        return (m.at(c, r, channels[k]) - ranges[k].first) / (ranges[k].second - ranges[k].first);
      };
      Rgb colour{};
      if (style.classes) {
        colour = class_colour(*style.classes, std::llround(v0));
      } else if (rgb) {
        for (size_t k = 0; k < 3; ++k) colour[k] = stretch_byte(m.at(c, r, channels[k]), ranges[k]);
      } else {
        colour = ramp_colour(style.ramp, style.ramp == Ramp::Hypsometric ? v0 : t(0));
      }
      if (!shade.empty()) {
        const float s = shade[size_t(r) * size_t(m.width) + size_t(c)];
        for (auto& x : colour) x = uint8_t(std::lround(x * s));
      }
      uint8_t* p = image.at(c, r);
      std::copy(colour.begin(), colour.end(), p);
      p[3] = 255;
    }
  }
  return image;
}

void write_quicklook_png(const PictureRaster& m, const QuicklookStyle& style,
                         const std::string& path, const Overlay& overlay) {
  RgbaImage image = render_quicklook(m, style);
  if (overlay && m.frame) overlay(image, *m.frame);
  if (style.legend)
    if (const auto legend = legend_of(m, style)) add_legend(image, *legend);
  write_image(image.pixels, image.width, image.height, 4, {"PNG", {}}, path);
  if (m.frame) write_georeference(*m.frame, path);
}

}  // namespace maquette
