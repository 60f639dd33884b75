#include "image/quicklook.h"

#include <gdal_priv.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/output_file.h"
#include "gdal/gdal_env.h"
#include "gdal/image_file.h"
#include "image/hillshade.h"
#include "image/legend.h"
#include "image/stretch.h"

namespace maquette {
namespace {

namespace fs = std::filesystem;

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

// How a one-channel picture is coloured: the style's ramp, or one chosen by the values (a
// diverging ramp when they span both signs, else viridis), between the values mapped to its ends:
// symmetric around 0 for a diverging ramp unless --range gave them, so that 0 gets its middle
// colour; the full range of heights for the hypsometric ramp's legend (it maps metres, not a
// stretch).
struct RampScale {
  Ramp ramp = Ramp::Grey;
  double low = 0, high = 1;
};

RampScale ramp_scale(const PictureRaster& m, const QuicklookStyle& style) {
  if (style.ramp == Ramp::Hypsometric) {
    const auto [low, high] = channel_quantiles(m, 0, 0.0, 1.0);
    return {Ramp::Hypsometric, low, high};
  }
  const auto [low, high] = stretch_range(m, style, 0);
  const Ramp ramp = style.ramp.value_or(low < 0 && high > 0 ? Ramp::Diverging : Ramp::Viridis);
  if (ramp != Ramp::Diverging || style.range) return {ramp, low, high};  // an asked range as is
  const double reach = std::max(std::abs(low), std::abs(high));
  return {ramp, -reach, reach};
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
  const RampScale scale = ramp_scale(m, style);
  return Legend{ColourBar{scale.ramp, scale.low, scale.high, style.units}};
}

// Writes the frame beside the PNG being written: as its .aux.xml (through GDAL's side-car
// mechanism, which a read-only PNG keeps there) and as the world file OUT.pgw.
void write_georeference(const PictureFrame& frame, OutputFile& png) {
  std::array<double, 6> gt = frame.geotransform();
  {
    const GdalErrorTrap trap;
    GDALDatasetUniquePtr ds(
        GDALDataset::Open(png.temp_path().c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    if (!ds || ds->SetGeoTransform(gt.data()) != CE_None ||
        ds->SetProjection(frame.crs_wkt().c_str()) != CE_None)
      throw Error("cannot georeference " + png.path() + ": " + CPLGetLastErrorMsg());
    ds.reset();  // writes the .aux.xml
    trap.check("cannot georeference " + png.path());
  }
  std::ostringstream text;
  text.precision(17);
  // The world file's order: x and y pixel sizes with the rotations between, then the centre of
  // the top-left pixel.
  for (const double v :
       {gt[1], gt[4], gt[2], gt[5], gt[0] + gt[1] / 2 + gt[2] / 2, gt[3] + gt[4] / 2 + gt[5] / 2})
    text << v << "\n";
  const std::string world = fs::path(png.path()).replace_extension("pgw").string();
  write_new_file(png.add_sidecar(world), text.str());
}

}  // namespace

void check_quicklook_style(const QuicklookStyle& style, int channels) {
  const auto refuse = [](const char* option, const std::string& why) {
    throw Error(std::string(option) + " does nothing here: " + why);
  };
  if (style.range && !(std::isfinite(style.range->first) && std::isfinite(style.range->second) &&
                       style.range->first != style.range->second))
    throw Error("--range " + std::to_string(style.range->first) + " " +
                std::to_string(style.range->second) + ": expected two finite, distinct values");
  const bool drawn_by_colour_table = channels == 0 || style.classes;
  if (drawn_by_colour_table) {
    const std::string why = channels == 0 ? "a features layer is drawn as its features"
                                          : "a categorical layer is drawn in its class colours";
    if (style.ramp) refuse("--ramp", why);
    if (style.range) refuse("--range", why);
    if (style.hillshade) refuse("--hillshade", why);
    if (!style.bands.empty()) refuse("--bands", why);
    return;
  }
  if (channels >= 3) {
    const std::string why = "the layer's " + std::to_string(channels) +
                            " channels are drawn as RGB (--bands), without a ramp";
    if (style.ramp) refuse("--ramp", why);
    if (style.hillshade) refuse("--hillshade", why);
    return;
  }
  if (!style.bands.empty())
    refuse("--bands", "the layer's channel 1 is drawn through a colour ramp");
  if (style.range && style.ramp == Ramp::Hypsometric)
    refuse("--range",
           "the hypsometric ramp tints fixed heights in metres; give another --ramp to stretch "
           "a range");
}

RgbaImage render_quicklook(const PictureRaster& m, const QuicklookStyle& style) {
  const std::vector<int> channels = drawn_channels(m, style);
  const bool rgb = channels.size() == 3;
  std::vector<std::pair<double, double>> ranges;
  if (rgb)
    for (int k : channels) ranges.push_back(stretch_range(m, style, k));
  const RampScale scale = rgb || style.classes ? RampScale{} : ramp_scale(m, style);
  const std::vector<float> shade =
      style.hillshade && !rgb && !style.classes ? hillshade(m) : std::vector<float>{};

  RgbaImage image(m.width, m.height);
  for (int r = 0; r < m.height; ++r) {
    for (int c = 0; c < m.width; ++c) {
      const float v0 = m.at(c, r, channels[0]);
      if (!std::isfinite(v0)) continue;  // transparent
      Rgb colour{};
      if (style.classes) {
        colour = class_colour(*style.classes, std::llround(v0));
      } else if (rgb) {
        for (size_t k = 0; k < 3; ++k) colour[k] = stretch_byte(m.at(c, r, channels[k]), ranges[k]);
      } else {
        colour = ramp_colour(scale.ramp, scale.ramp == Ramp::Hypsometric
                                             ? v0
                                             : (v0 - scale.low) / (scale.high - scale.low));
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
  OutputFile png(path, {".aux.xml"});
  png.write([&] {
    write_image(image.pixels, image.width, image.height, 4, {"PNG", {}}, png);
    if (m.frame) write_georeference(*m.frame, png);
  });
  png.commit();
}

}  // namespace maquette
