#include "render/panorama.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>

#include "core/output_file.h"
#include "gdal/image_file.h"
#include "geotiff/gdal_util.h"
#include "image/layer_sampler.h"
#include "image/stretch.h"

namespace maquette {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
using Rgb = std::array<double, 3>;
constexpr Rgb kHaze{205, 216, 228}, kZenith{92, 140, 200}, kEarth{196, 184, 160};

Rgb mix(const Rgb& a, const Rgb& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

// Samplers of one thread (LayerSampler caches tiles and is not shared between threads).
struct Samplers {
  std::optional<LayerSampler> texture, land_cover;
};

}  // namespace

Panorama shade_panorama(const Store& store, const Grid& grid, const TerrainScene& scene,
                        const Fragments& f, const PinholeCamera& camera, const PanoramaLook& look) {
  const int w = f.width, h = f.height;
  const size_t n = size_t(w) * size_t(h);
  Panorama p;
  p.width = w;
  p.height = h;
  p.rgb.assign(3 * n, 0);
  for (auto* guide : {&p.altitude, &p.distance, &p.lon, &p.lat}) guide->assign(n, NAN);
  if (look.land_cover) p.land_cover.assign(n, NAN);
  if (look.shadow) p.cast_shadow.assign(n, NAN);
  p.silhouette.assign(n, 0);
  const double az = look.sun_azimuth * kDegree, alt = look.sun_altitude * kDegree;
  const Vec3d sun{std::sin(az) * std::cos(alt), std::cos(az) * std::cos(alt), std::sin(alt)};
  tbb::enumerable_thread_specific<Samplers> samplers([&] {
    Samplers s;
    if (look.texture) s.texture.emplace(store, grid, *look.texture, look.texture->level, true);
    if (look.land_cover)
      s.land_cover.emplace(store, grid, *look.land_cover, look.land_cover->level, false);
    return s;
  });

  // What each pixel sees: guides, the surface's texel (NaN for none) and its shade.
  std::vector<float> texels(3 * n, NAN), shades(n, 0);
  tbb::parallel_for(0, h, [&](int row) {
    Samplers& s = samplers.local();
    for (int col = 0; col < w; ++col) {
      const size_t i = size_t(row) * size_t(w) + size_t(col);
      if (f.triangle[i] == Fragments::kSky) continue;
      const uint32_t* v = &scene.mesh.indices[3 * size_t(f.triangle[i])];
      const double b[3] = {1.0 - f.b1[i] - f.b2[i], f.b1[i], f.b2[i]};
      auto interpolate = [&](const auto& values, int stride, int k) {
        double sum = 0;
        for (int j = 0; j < 3; ++j) sum += b[j] * values[size_t(stride) * v[j] + size_t(k)];
        return sum;
      };
      const LonLat ll{interpolate(scene.lonlat, 2, 0), interpolate(scene.lonlat, 2, 1)};
      p.lon[i] = ll.lon;
      p.lat[i] = ll.lat;
      p.altitude[i] = interpolate(scene.altitude, 1, 0);
      const Vec3d ray = camera.ray(col + 0.5, row + 0.5);
      p.distance[i] = f.depth[i] * std::sqrt(ray[0] * ray[0] + ray[1] * ray[1] + ray[2] * ray[2]);
      if (s.texture) {
        float texel[4] = {NAN, NAN, NAN, NAN};
        if (s.texture->sample(ll, grid.cell_from_point(ll, look.texture->level), texel))
          for (int k = 0; k < 3; ++k)
            texels[3 * i + size_t(k)] = texel[look.texture->channels < 3 ? 0 : k];
      }
      if (s.land_cover) {
        float label = NAN;
        if (s.land_cover->sample(ll, grid.cell_from_point(ll, look.land_cover->level), &label))
          p.land_cover[i] = label;
      }
      const Vec3d normal{interpolate(scene.normals, 3, 0), interpolate(scene.normals, 3, 1),
                         interpolate(scene.normals, 3, 2)};
      const double len =
          std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      const double lit =
          len == 0 ? 1 : (normal[0] * sun[0] + normal[1] * sun[1] + normal[2] * sun[2]) / len;
      double sunlit = 1;
      if (look.shadow) {
        p.cast_shadow[i] = interpolate(*look.shadow, 1, 0);
        sunlit = 1 - p.cast_shadow[i];
      }
      shades[i] = float(0.3 + 0.7 * std::max(0.0, lit) * sunlit);
    }
  });

  // The display stretch of the texels seen (image/stretch.h), per band.
  std::array<StretchRange, 3> stretch{StretchRange{0, 255}, StretchRange{0, 255},
                                      StretchRange{0, 255}};
  if (look.texture && look.stretch)
    for (size_t k = 0; k < 3; ++k) {
      std::vector<float> band(n);
      for (size_t i = 0; i < n; ++i) band[i] = texels[3 * i + k];
      stretch[k] = quantile_range(band, kDisplayStretch.first, kDisplayStretch.second);
    }

  tbb::parallel_for(0, h, [&](int row) {
    for (int col = 0; col < w; ++col) {
      const size_t i = size_t(row) * size_t(w) + size_t(col);
      Rgb colour;
      if (f.triangle[i] == Fragments::kSky) {
        const Vec3d ray = camera.ray(col + 0.5, row + 0.5);
        const double elevation = std::atan2(ray[2], std::hypot(ray[0], ray[1]));
        colour = mix(kHaze, kZenith, std::clamp(elevation / (30 * kDegree), 0.0, 1.0));
      } else {
        colour = kEarth;
        if (!std::isnan(texels[3 * i]))
          for (size_t k = 0; k < 3; ++k) colour[k] = stretch_byte(texels[3 * i + k], stretch[k]);
        for (double& c : colour) c *= shades[i];
        colour = mix(colour, kHaze, 1 - std::exp(-p.distance[i] / look.haze_distance));
      }
      for (int k = 0; k < 3; ++k)
        p.rgb[3 * i + size_t(k)] = uint8_t(std::lround(std::clamp(colour[size_t(k)], 0.0, 255.0)));
    }
  });

  tbb::parallel_for(0, h, [&](int row) {
    for (int col = 0; col < w; ++col) {
      const size_t i = size_t(row) * size_t(w) + size_t(col);
      if (f.triangle[i] == Fragments::kSky) continue;
      const double limit = p.distance[i] * look.silhouette_jump;
      auto beyond = [&](int c, int r) {
        if (c < 0 || r < 0 || c >= w || r >= h) return false;
        const size_t j = size_t(r) * size_t(w) + size_t(c);
        return f.triangle[j] == Fragments::kSky || p.distance[j] > limit;
      };
      if (beyond(col - 1, row) || beyond(col + 1, row) || beyond(col, row - 1) ||
          beyond(col, row + 1))
        p.silhouette[i] = 255;
    }
  });
  return p;
}

namespace {

void write_guides(const Panorama& p, const std::string& path) {
  OutputFile out(path, {".aux.xml"});
  out.write([&] {
    GdalSession gdal;
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    std::vector<std::pair<const char*, const std::vector<double>*>> bands = {
        {"altitude", &p.altitude}, {"distance", &p.distance}, {"lon", &p.lon}, {"lat", &p.lat}};
    if (!p.land_cover.empty()) bands.emplace_back("land_cover", &p.land_cover);
    if (!p.cast_shadow.empty()) bands.emplace_back("cast_shadow", &p.cast_shadow);
    DatasetPtr ds(driver->Create(out.temp_path().c_str(), p.width, p.height, int(bands.size()),
                                 GDT_Float64, geotiff_creation_options(true).List()));
    if (!ds) gdal_error("cannot create " + out.temp_path());
    for (size_t b = 0; b < bands.size(); ++b) {
      GDALRasterBand* band = ds->GetRasterBand(int(b) + 1);
      band->SetDescription(bands[b].first);
      band->SetNoDataValue(NAN);
      if (band->RasterIO(GF_Write, 0, 0, p.width, p.height,
                         const_cast<double*>(bands[b].second->data()), p.width, p.height,
                         GDT_Float64, 0, 0) != CE_None)
        gdal_error("cannot write " + out.temp_path());
    }
    ds.reset();  // flushes the last blocks
  });
  out.commit();
}

}  // namespace

void write_panorama(const Panorama& p, const std::string& out) {
  const std::filesystem::path path(out);
  const std::string stem = (path.parent_path() / path.stem()).string();
  write_image(p.rgb, p.width, p.height, 3, {"PNG", {}}, out);
  write_image(p.silhouette, p.width, p.height, 1, {"PNG", {}}, stem + "-silhouettes.png");
  write_guides(p, stem + "-guides.tif");
}

}  // namespace maquette
