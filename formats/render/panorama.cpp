#include "render/panorama.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "core/round_half_away.h"
#include "image/layer_sampler.h"
#include "image/stretch.h"
#include "render/edge_texels.h"
#include "render/sky.h"

namespace maquette {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
using Rgb = std::array<double, 3>;
constexpr Rgb kEarth{196, 184, 160};
// Terrain the texture has no texel for within the reach (a DEM reaching far past the imagery's
// edge): the middle of the display range, about a stretched texel's mean. The light earth colour
// drew such a strip along a far edge as a bright rim on the skyline.
constexpr Rgb kNoTexel{128, 128, 128};

Rgb mix(const Rgb& a, const Rgb& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

// Samplers of one thread (a LayerSampler is not shared between threads; its tiles are).
struct Samplers {
  // The texture at its level and at each coarser level of its overviews: textures[j] at the
  // texture's level - j (none without a texture).
  std::vector<LayerSampler> textures;
  std::optional<LayerSampler> land_cover;
  std::optional<EdgeTexels> edge;  // the texture past its edge (kTextureReach)
  // Each row a run of its own (LayerSampler::start_run): its values whatever rows came before.
  void start_row() {
    for (LayerSampler& t : textures) t.start_run();
    if (land_cover) land_cover->start_run();
  }
};

}  // namespace

int stretch_step(int width, int height) {
  return std::max(1, int(std::sqrt(double(width) * double(height) / 4e6)));
}

namespace {

// A pixel's triangle, its corners, their slots and attributes are loads each waiting on the last,
// mostly from beyond the caches: the corners of the triangle kAhead pixels on, the slots of that
// half as far on and the first corner's attributes a quarter as far on are asked of memory before
// they are read (no value changes; BM_PanoramaShade 3-5 % faster). `left`: the pixels of the row
// from i on.
constexpr int kAhead = 16;
[[gnu::always_inline]] inline void prefetch_corners(const TerrainScene& scene, const Fragments& f,
                                                    size_t i, int left) {
  if (left > kAhead)
    if (const uint32_t t = f.triangle[i + kAhead]; t != Fragments::kSky)
      __builtin_prefetch(&scene.mesh.indices[3 * size_t(t)]);
  if (left > kAhead / 2)
    if (const uint32_t t = f.triangle[i + kAhead / 2]; t != Fragments::kSky)
      for (size_t j = 0; j < 3; ++j)
        __builtin_prefetch(&scene.slot[scene.mesh.indices[3 * size_t(t) + j]]);
  if (left > kAhead / 4)
    if (const uint32_t t = f.triangle[i + kAhead / 4]; t != Fragments::kSky) {
      const size_t a = scene.slot[scene.mesh.indices[3 * size_t(t)]];
      __builtin_prefetch(&scene.lonlat[2 * a]);
      __builtin_prefetch(&scene.plane[2 * a]);
      __builtin_prefetch(&scene.altitude[a]);
      __builtin_prefetch(&scene.normals[3 * a]);
    }
}

// Where a terrain pixel `i` of `f` sees the surface: lon/lat and the grid's plane point,
// interpolated in its triangle (the plane's NaN when a corner is off its tile's face). Longitudes
// the short way round from the first corner's: a triangle across the antimeridian (179.99 and
// -179.99) gave the pixels between lon ~0, a wrong lon guide and, where the plane is NaN (a halo's
// square), a texel sampled half the globe away.
struct SurfacePoint {
  LonLat lonlat{0, 0};
  PlanePoint plane{0, 0};
};

// Inline: in the guides' pass its corners and weights are those of the pass's own interpolations
// (out of line, 145 M of the 4 MP benchmark picture's 1.9 G instructions of colour and guides).
[[gnu::always_inline]] inline SurfacePoint surface_point(const TerrainScene& scene,
                                                         const Fragments& f, size_t i) {
  const uint32_t* v = &scene.mesh.indices[3 * size_t(f.triangle[i])];
  const size_t a[3] = {scene.slot[v[0]], scene.slot[v[1]], scene.slot[v[2]]};  // attributes'
  const double b[3] = {1.0 - f.b1[i] - f.b2[i], f.b1[i], f.b2[i]};
  const double lon0 = scene.lonlat[2 * a[0]];
  SurfacePoint s;
  for (int j = 0; j < 3; ++j) {
    const double lon = scene.lonlat[2 * a[j]];
    s.lonlat.lon +=
        b[j] * (std::abs(lon - lon0) > 180 ? lon0 + std::remainder(lon - lon0, 360.0) : lon);
    s.lonlat.lat += b[j] * scene.lonlat[2 * a[j] + 1];
    s.plane.x += b[j] * scene.plane[2 * a[j]];
    s.plane.y += b[j] * scene.plane[2 * a[j] + 1];
  }
  if (std::abs(s.lonlat.lon) > 180) s.lonlat.lon = std::remainder(s.lonlat.lon, 360.0);
  return s;
}

// The sampler's layer's value at `p`: from the plane point (no projection) where it is known,
// else from the lon/lat. False where the layer has no tile.
bool sample_at(LayerSampler& sampler, const Grid& grid, const SurfacePoint& p, float* out) {
  if (!std::isnan(p.plane.x)) return sampler.sample(p.plane, out);
  return sampler.sample(p.lonlat, grid.cell_from_point(p.lonlat, sampler.level()), out);
}

// The rays' parts of the picture's columns through their pixels' centres
// (PinholeCamera::column_ray).
std::vector<Vec3d> column_rays(const PinholeCamera& camera) {
  std::vector<Vec3d> rays(size_t(camera.spec().width));
  for (size_t col = 0; col < rays.size(); ++col) rays[col] = camera.column_ray(double(col) + 0.5);
  return rays;
}

// Metres from the eye to what pixel i of `f` sees: `column` and `row` the parts of the ray
// through its centre (PinholeCamera::column_ray and row_ray; a row shares the one, a column the
// other: no division a pixel).
double pixel_distance(const Fragments& f, size_t i, const Vec3d& column, const Vec3d& row) {
  const Vec3d ray = PinholeCamera::ray(column, row);
  return f.depth[i] * std::sqrt(ray[0] * ray[0] + ray[1] * ray[1] + ray[2] * ray[2]);
}

// A pixel's footprint across, in texels of the texture's level, per metre of distance: the
// distance times this is the footprint, whose log2 picks the texture's levels (sample_texel).
double texel_footprint_scale(const Grid& grid, const PanoramaLook& look,
                             const PinholeCamera& camera) {
  return 1 /
         (camera.focal() * grid.level_info(look.texture->level, look.texture->tile_size).pixel_m);
}

// The texture's texel at `p` (3 bands; NaN where it has none), at the level the distance needs:
// `footprint` is the pixel's width on the ground in texels of the texture's level (its distance
// over the focal length; across the view, not along it, so that ground seen at a grazing angle is
// not blurred). Up to 1 the texture's own level; beyond, the two levels whose texels are about
// the footprint, blended by where log2(footprint) lies between them (trilinear, as a GPU's
// mipmaps; the overviews are their children's means), down to the coarsest overview. A level
// without the texel there leaves the other's.
void sample_texel(Samplers& s, const Grid& grid, const PanoramaLook& look, const SurfacePoint& p,
                  double footprint, float* out) {
  auto at_level = [&](size_t j, float* bands) {
    float texel[4] = {NAN, NAN, NAN, NAN};
    if (sample_at(s.textures[j], grid, p, texel))
      for (int k = 0; k < 3; ++k) bands[k] = texel[look.texture->channels < 3 ? 0 : k];
  };
  const size_t coarsest = s.textures.size() - 1;
  if (!(footprint > 1) || coarsest == 0) return at_level(0, out);
  const double lod = std::min(std::log2(footprint), double(coarsest));
  const auto j = size_t(lod);
  const double t = lod - double(j);
  float fine[3] = {NAN, NAN, NAN}, coarse[3] = {NAN, NAN, NAN};
  at_level(j, fine);
  if (j < coarsest && t > 0) at_level(j + 1, coarse);
  for (int k = 0; k < 3; ++k)
    out[k] = std::isnan(coarse[k]) ? fine[k]
             : std::isnan(fine[k]) ? coarse[k]
                                   : float((1 - t) * fine[k] + t * coarse[k]);
}

}  // namespace

// The texture's tiles at its level and at each coarser level its overviews hold without a gap
// (textures[j] at the level - j), read once for all threads.
std::vector<std::shared_ptr<LayerSampler::Tiles>> texture_levels(const Store& store,
                                                                 const Grid& grid,
                                                                 const PanoramaLook& look) {
  std::vector<std::shared_ptr<LayerSampler::Tiles>> levels;
  if (!look.texture) return levels;
  const std::vector<int> held = store.stats(look.texture->name).levels;  // ascending
  for (int level = look.texture->level;
       level == look.texture->level || std::binary_search(held.begin(), held.end(), level); --level)
    levels.push_back(LayerSampler::shared_tiles(store, grid, *look.texture, level));
  return levels;
}

struct PanoramaSamplers::Threads {
  Threads(const Store& store, const Grid& grid, const PanoramaLook& look)
      : textures(texture_levels(store, grid, look)),
        land_cover(look.land_cover ? LayerSampler::shared_tiles(store, grid, *look.land_cover,
                                                                look.land_cover->level)
                                   : nullptr),
        samplers([this, &grid, look] {
          Samplers s;
          for (const auto& tiles : textures)
            s.textures.emplace_back(tiles, LayerSampler::Read::kBilinear);
          if (look.texture) s.edge.emplace(textures.front(), grid, *look.texture, kTextureReach);
          if (look.land_cover)
            s.land_cover.emplace(land_cover, look.smooth_land_cover
                                                 ? LayerSampler::Read::kSmoothLabels
                                                 : LayerSampler::Read::kNearest);
          return s;
        }) {}

  // The texture's (at each level) and land cover's tiles and halos, read once for all threads.
  std::vector<std::shared_ptr<LayerSampler::Tiles>> textures;
  std::shared_ptr<LayerSampler::Tiles> land_cover;
  tbb::enumerable_thread_specific<Samplers> samplers;
};

PanoramaSamplers::PanoramaSamplers(const Store& store, const Grid& grid, const PanoramaLook& look)
    : threads_(std::make_unique<Threads>(store, grid, look)) {}

PanoramaSamplers::~PanoramaSamplers() = default;

void PanoramaSamplers::forget_unused() {
  Threads& t = *threads_;
  for (const auto& tiles : t.textures) LayerSampler::forget_unused(*tiles);
  if (t.land_cover) LayerSampler::forget_unused(*t.land_cover);
  for (Samplers& s : t.samplers) {
    s.start_row();
    if (s.edge) s.edge->forget_unused();
  }
}

namespace {

// Appends to `texels` those of `found` (3 per pixel of the strip of rows of `f`; NaN for none; read
// on its terrain pixels only) on the stretch grid of `step`, in row order: each row's pixels
// counted, then their texels copied to their places, rows side by side (no serial share).
void append_stretch_texels(const float* found, const Fragments& f, int step,
                           StretchTexels& texels) {
  const int rows = f.height, width = f.width;
  auto each_pixel = [&](int row, auto&& take) {
    if ((f.first_row + row) % step != 0) return;
    for (int col = 0; col < width; col += step) {
      const size_t i = size_t(row) * size_t(width) + size_t(col);
      if (f.triangle[i] != Fragments::kSky) take(i);
    }
  };
  std::vector<size_t> offset(size_t(rows) + 1, 0);  // each row's first texel
  tbb::parallel_for(
      0, rows, [&](int row) { each_pixel(row, [&](size_t) { offset[size_t(row) + 1] += 3; }); });
  offset[0] = texels.size();
  for (size_t row = 1; row <= size_t(rows); ++row) offset[row] += offset[row - 1];
  texels.resize(offset[size_t(rows)]);
  tbb::parallel_for(0, rows, [&](int row) {
    size_t next = offset[size_t(row)];
    each_pixel(row, [&](size_t i) {
      std::copy_n(&found[3 * i], 3, &texels[next]);
      next += 3;
    });
  });
}

}  // namespace

void gather_stretch_texels(const Grid& grid, const TerrainScene& scene, const Fragments& f,
                           const PinholeCamera& camera, const PanoramaLook& look,
                           PanoramaSamplers& samplers, int step, StretchTexels& texels,
                           FreshArray<float>& found) {
  if (!look.texture || !look.stretch) return;
  const double footprint = texel_footprint_scale(grid, look, camera);
  // Written on the terrain pixels of the stretch grid only, the only ones read: the other rows'
  // pages are never touched.
  resize_fresh(found, 3 * size_t(f.width) * size_t(f.height));
  const std::vector<Vec3d> columns = column_rays(camera);
  tbb::parallel_for(0, f.height, [&](int row) {
    if ((f.first_row + row) % step != 0) return;
    Samplers& s = samplers.threads_->samplers.local();
    s.start_row();
    const Vec3d row_ray = camera.row_ray(f.first_row + row + 0.5);
    for (int col = 0; col < f.width; col += step) {
      const size_t i = size_t(row) * size_t(f.width) + size_t(col);
      if (f.triangle[i] == Fragments::kSky) continue;
      std::fill_n(&found[3 * i], 3, NAN);
      sample_texel(s, grid, look, surface_point(scene, f, i),
                   pixel_distance(f, i, columns[size_t(col)], row_ray) * footprint, &found[3 * i]);
    }
  });
  append_stretch_texels(found.data(), f, step, texels);
}

namespace {

// Whether a terrain pixel at distance `d` is on a silhouette, its 4-neighbours at `left`, `right`,
// `up` and `down` (colour_panorama): one is the sky (NaN) or more than `jump` times farther, i.e.
// not at most that far (!(n <= limit), one test for both). A sky pixel's NaN limit makes every
// neighbour beyond, so the sky is masked out. Branch-free.
inline uint8_t silhouette(double jump, float d, float left, float right, float up, float down) {
  const double limit = double(d) * jump;
  const bool beyond = !(left <= limit) | !(right <= limit) | !(up <= limit) | !(down <= limit);
  return uint8_t(!std::isnan(d) & beyond ? 255 : 0);
}

// The silhouettes of a row's columns [1, w - 1) from its distances `d` and those of the rows above
// and below. The pointers restrict: GCC then vectorizes the loop (through a lambda's captures it
// could not tell the rows read from the row written).
void inner_silhouettes(double jump, const float* __restrict d, const float* __restrict up,
                       const float* __restrict down, uint8_t* __restrict s, int w) {
  for (int col = 1; col + 1 < w; ++col)
    s[col] = silhouette(jump, d[col], d[col - 1], d[col + 1], up[col], down[col]);
}

// Each band's stretch: the quantile_ranges (image/stretch.h) `ranges(q0, q1)` makes of texels, 3
// a pixel; or the values as stored without a texture or with look.stretch false.
template <typename Ranges>
BandStretch band_stretch(const PanoramaLook& look, const Ranges& ranges) {
  BandStretch stretch{StretchRange{0, 255}, StretchRange{0, 255}, StretchRange{0, 255}};
  if (look.texture && look.stretch) {
    const std::vector<StretchRange> r = ranges(kDisplayStretch.first, kDisplayStretch.second);
    std::copy(r.begin(), r.end(), stretch.begin());
  }
  return stretch;
}

// The stretch of the whole picture's `texels` (shade_guides') on the grid of `step`, read in place
// a grid row at a time from `rows`: the imagery's own texels of its terrain pixels, those
// gather_stretch_texels would copy.
BandStretch picture_stretch(const FreshArray<float>& texels, const TexelRows& rows, int width,
                            const PanoramaLook& look, int step) {
  const auto w = size_t(width), grid = size_t(step);
  auto grid_row = [&](size_t c, std::vector<float>& values) {
    const size_t row = c * grid;
    const auto& runs = rows.terrain[row];
    const std::vector<uint32_t>& edge = rows.past_edge[row];
    // A row whose terrain is one run, none of it past the edge: its texels in place, not copied.
    if (grid == 1 && runs.size() == 1 && edge.empty())
      return std::span<const float>(&texels[3 * (row * w + runs[0][0])],
                                    3 * size_t(runs[0][1] - runs[0][0]));
    size_t e = 0;
    for (const auto& [first, end] : runs)
      for (size_t col = (first + grid - 1) / grid * grid; col < end; col += grid) {
        while (e < edge.size() && edge[e] < col) ++e;
        if (e < edge.size() && edge[e] == col) continue;
        for (size_t k = 0; k < 3; ++k) values.push_back(texels[3 * (row * w + col) + k]);
      }
    return std::span<const float>(values);
  };
  return band_stretch(look, [&](double q0, double q1) {
    return quantile_ranges((rows.terrain.size() + grid - 1) / grid, 3, grid_row, q0, q1);
  });
}

}  // namespace

BandStretch texel_stretch(const StretchTexels& texels, const PanoramaLook& look) {
  return band_stretch(look,
                      [&](double q0, double q1) { return quantile_ranges(texels, 3, q0, q1); });
}

void size_panorama(Panorama& p, int width, int first_row, int rows, const PanoramaLook& look) {
  const size_t n = size_t(width) * size_t(rows);
  p.width = width;
  p.height = rows;
  p.first_row = first_row;
  for (auto* a : {&p.distance, &p.lon_offset, &p.lat_offset, &p.altitude, &p.shading})
    resize_fresh(*a, n);
  resize_fresh(p.land_cover, look.land_cover ? n : 0);
  resize_fresh(p.cast_shadow, look.shadow ? n : 0);
  resize_fresh(p.rgb, 3 * n);
  resize_fresh(p.silhouette, n);
}

void shade_guides(const Grid& grid, const TerrainScene& scene, const Fragments& f,
                  const PinholeCamera& camera, const PanoramaLook& look, PanoramaSamplers& samplers,
                  Panorama& p, FreshArray<float>& texels, TexelRows* rows) {
  const int w = f.width, h = f.height;
  // f's pixels in p's arrays start at `offset`. Every pixel of f's rows of each guide is written
  // once below (fresh pages are not filled first). The surface's texel, NaN for none; written and
  // read on terrain pixels only (the sky's pages are never touched).
  const size_t offset = size_t(f.first_row - p.first_row) * size_t(w);
  p.origin = {camera.spec().eye.lon, camera.spec().eye.lat};  // of the lon/lat offsets
  resize_fresh(texels, 3 * size_t(p.width) * size_t(p.height));
  float* const texel_of = &texels[3 * offset];
  const double az = look.sun_azimuth * kDegree, alt = look.sun_altitude * kDegree;
  const Vec3d sun{std::sin(az) * std::cos(alt), std::cos(az) * std::cos(alt), std::sin(alt)};
  auto& threads = samplers.threads_->samplers;
  std::vector<uint8_t> untextured(size_t(h), 0);  // rows with a terrain pixel without a texel
  const double footprint = look.texture ? texel_footprint_scale(grid, look, camera) : 0;
  const std::vector<Vec3d> columns = column_rays(camera);

  // What each pixel sees: guides (its shading among them) and the surface's texel.
  tbb::parallel_for(0, h, [&](int row) {
    Samplers& s = threads.local();
    s.start_row();
    const Vec3d row_ray = camera.row_ray(f.first_row + row + 0.5);
    auto* runs = rows ? &rows->terrain[size_t(f.first_row + row)] : nullptr;
    for (int col = 0; col < w; ++col) {
      const size_t i = size_t(row) * size_t(w) + size_t(col), o = offset + i;
      if (f.triangle[i] == Fragments::kSky) {  // NaN guides, a run of sky at once
        int end = col + 1;
        while (end < w && f.triangle[i + size_t(end - col)] == Fragments::kSky) ++end;
        const auto run = size_t(end - col);
        for (auto* a : {&p.distance, &p.lon_offset, &p.lat_offset, &p.altitude, &p.shading,
                        &p.land_cover, &p.cast_shadow})
          if (!a->empty()) std::fill_n(&(*a)[o], run, NAN);
        col = end - 1;
        continue;
      }
      if (runs && (runs->empty() || runs->back()[1] != uint32_t(col)))
        runs->push_back({uint32_t(col), uint32_t(col)});
      if (runs) ++runs->back()[1];
      prefetch_corners(scene, f, i, w - col);
      float* texel = &texel_of[3 * i];
      texel[0] = texel[1] = texel[2] = NAN;
      const uint32_t* v = &scene.mesh.indices[3 * size_t(f.triangle[i])];
      const size_t a[3] = {scene.slot[v[0]], scene.slot[v[1]], scene.slot[v[2]]};  // attributes'
      const double b[3] = {1.0 - f.b1[i] - f.b2[i], f.b1[i], f.b2[i]};
      // `values` at the corners `at` (slots or vertices), `stride` a corner, its k-th.
      auto interpolate = [&](const auto& values, const auto& at, int stride, int k) {
        double sum = 0;
        for (int j = 0; j < 3; ++j) sum += b[j] * values[size_t(stride) * at[j] + size_t(k)];
        return sum;
      };
      const SurfacePoint at = surface_point(scene, f, i);
      // The short way round: both in [-180, 180], so one turn at most (std::remainder's value,
      // exactly, without its cost a pixel).
      double east = at.lonlat.lon - p.origin.lon;
      if (east > 180)
        east -= 360;
      else if (east < -180)
        east += 360;
      p.lon_offset[o] = float(east);
      p.lat_offset[o] = float(at.lonlat.lat - p.origin.lat);
      p.altitude[o] = float(interpolate(scene.altitude, a, 1, 0));
      const double distance = pixel_distance(f, i, columns[size_t(col)], row_ray);
      p.distance[o] = float(distance);
      if (look.texture) sample_texel(s, grid, look, at, distance * footprint, texel);
      if (std::isnan(texel[0])) untextured[size_t(row)] = 1;
      if (s.land_cover) {
        float label = NAN;
        p.land_cover[o] = sample_at(*s.land_cover, grid, at, &label) ? label : NAN;
      }
      const Vec3d normal{interpolate(scene.normals, a, 3, 0), interpolate(scene.normals, a, 3, 1),
                         interpolate(scene.normals, a, 3, 2)};
      const double len =
          std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      const double lit =
          len == 0 ? 1 : (normal[0] * sun[0] + normal[1] * sun[1] + normal[2] * sun[2]) / len;
      double sunlit = 1;
      if (look.shadow) {
        const double shadow = interpolate(*look.shadow, v, 1, 0);  // per vertex
        p.cast_shadow[o] = float(shadow);
        sunlit = 1 - shadow;
      }
      p.shading[o] = float(0.3 + 0.7 * std::max(0.0, lit) * sunlit);
    }
  });

  // Past the imagery's edge, its nearest texel within the reach.
  if (look.texture)
    tbb::parallel_for(0, h, [&](int row) {
      if (!untextured[size_t(row)]) return;
      Samplers& s = threads.local();
      for (int col = 0; col < w; ++col) {
        const size_t i = size_t(row) * size_t(w) + size_t(col);
        float* texel = &texel_of[3 * i];
        if (f.triangle[i] == Fragments::kSky || !std::isnan(texel[0])) continue;
        const SurfacePoint at = surface_point(scene, f, i);
        if (s.edge->sample(std::isnan(at.plane.x) ? grid.forward(at.lonlat) : at.plane, texel) &&
            rows)
          rows->past_edge[size_t(f.first_row + row)].push_back(uint32_t(col));
      }
    });
}

void colour_panorama(const PinholeCamera& camera, const PanoramaLook& look,
                     const BandStretch& stretch, const FreshArray<float>& texels, Panorama& p) {
  const int w = p.width, h = p.height;
  // Colour: the texel (or past the imagery's edge its nearest, not stretched over), shaded and
  // hazed; the sky (NaN distance) from sky_row.
  tbb::parallel_for(0, h, [&](int row) {
    const size_t start = size_t(row) * size_t(w);
    // The row's arrays and the look's values as locals: the bytes written could otherwise alias
    // them (a char may alias anything), and each would be read again after every byte.
    const float* const distance = &p.distance[start];
    const float* const shading = &p.shading[start];
    const float* const texel_row = &texels[3 * start];
    uint8_t* const rgb = &p.rgb[3 * start];
    const BandStretch bands = stretch;
    const Rgb base = look.texture ? kNoTexel : kEarth;
    const double haze_distance = look.haze_distance;
    auto sky = [distance](int col) { return std::isnan(distance[col]); };
    for (int col = 0; col < w; ++col)
      if (sky(col)) {
        sky_row(camera, p.first_row + row, rgb);  // the terrain drawn over it
        break;
      }
    for (int col = 0; col < w; ++col) {
      if (sky(col)) continue;
      Rgb colour = base;
      const float* texel = &texel_row[3 * size_t(col)];
      if (!std::isnan(texel[0]))
        for (size_t k = 0; k < 3; ++k) colour[k] = stretch_byte(texel[k], bands[k]);
      for (double& c : colour) c *= shading[col];
      colour = mix(colour, kHazeColour, 1 - std::exp(-distance[col] / haze_distance));
      for (size_t k = 0; k < 3; ++k)
        rgb[3 * size_t(col) + k] = uint8_t(round_half_away(std::clamp(colour[k], 0.0, 255.0)));
    }
  });

  // Silhouettes: a terrain pixel with a 4-neighbour in `p` that is the sky or more than
  // silhouette_jump times farther (silhouette). A neighbour beyond `p`'s rows or columns is read as
  // -infinity (never beyond). A row's first and last columns apart.
  const double jump = look.silhouette_jump;
  const std::vector<float> none(size_t(w), -INFINITY);
  tbb::parallel_for(0, h, [&](int row) {
    const size_t start = size_t(row) * size_t(w);
    const float* d = &p.distance[start];
    const float* up = row > 0 ? d - w : none.data();
    const float* down = row + 1 < h ? d + w : none.data();
    uint8_t* s = &p.silhouette[start];
    auto side = [&](int col) {
      s[col] = silhouette(jump, d[col], col > 0 ? d[col - 1] : -INFINITY,
                          col + 1 < w ? d[col + 1] : -INFINITY, up[col], down[col]);
    };
    side(0);
    inner_silhouettes(jump, d, up, down, s, w);
    if (w > 1) side(w - 1);
  });
}

Panorama shade_panorama(const Store& store, const Grid& grid, const TerrainScene& scene,
                        const PinholeCamera& camera, const PanoramaLook& look, int strip_rows,
                        const DrawRows& draw, BandStretch* stretch) {
  const int w = camera.spec().width, h = camera.spec().height;
  Panorama p;
  size_panorama(p, w, 0, h, look);
  FreshArray<float> texels;
  PanoramaSamplers samplers(store, grid, look);
  TexelRows rows(h);
  for (int first = 0; first < h; first += strip_rows) {
    shade_guides(grid, scene, draw(first, std::min(strip_rows, h - first)), camera, look, samplers,
                 p, texels, &rows);
    samplers.forget_unused();
  }
  const BandStretch picture = picture_stretch(texels, rows, w, look, stretch_step(w, h));
  colour_panorama(camera, look, picture, texels, p);
  if (stretch) *stretch = picture;
  return p;
}

}  // namespace maquette
