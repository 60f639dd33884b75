#include "render/panorama_strips.h"

#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/output_file.h"
#include "core/sibling_path.h"
#include "gdal/image_file.h"
#include "geotiff/gdal_util.h"
#include "render/panorama_supersample.h"
#include "render/strip_drawer.h"

namespace maquette {

constexpr int kGuideBlockRows = 256;  // geotiff_creation_options' blocks
constexpr double kStripPixels = 16e6;
constexpr double kFragmentPixels = 1 << 21;

struct PanoramaWriter::Files {
  std::string out;
  int width = 0, height = 0;
  std::vector<uint8_t> rgb, silhouette;  // the whole picture's
  bool land_cover = false, cast_shadow = false, coverage = false;
  int64_t terrain_pixels = 0;  // written so far
  double nearest_terrain = INFINITY;
  // Every file written under its temporary name before any is put in place (a picture without its
  // guides was left when they could not be written); a path in the way is told before drawing.
  OutputFile picture_file, guides_file, silhouettes_file;
  GdalSession gdal;
  DatasetPtr guides;
  Files(const std::string& path, int w, int h)
      : out(path),
        width(w),
        height(h),
        rgb(3 * size_t(w) * size_t(h)),
        silhouette(size_t(w) * size_t(h)),
        picture_file(panorama_files(path)[0], {".aux.xml"}),
        guides_file(panorama_files(path)[1], {".aux.xml"}),
        silhouettes_file(panorama_files(path)[2], {".aux.xml"}) {}
};

std::vector<std::string> panorama_files(const std::string& out) {
  return {out, sibling_path(out, "-guides.tif"), sibling_path(out, "-silhouettes.png")};
}

ImageFormat panorama_picture_format(const std::string& out) {
  const std::filesystem::path path(out);
  if (path.has_parent_path() && !std::filesystem::is_directory(path.parent_path()))
    throw Error(out + ": the directory " + path.parent_path().string() + " does not exist");
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  // zlib level 3: a third of the default level's (6) time for a file ~8 % larger.
  if (ext == ".png") return {"PNG", {"ZLEVEL=3"}};
  if (ext == ".jpg" || ext == ".jpeg") return {"JPEG", {"QUALITY=90"}};
  throw Error(out + ": a panorama is written as PNG (.png) or JPEG (.jpg, .jpeg), not '" + ext +
              "'");
}

namespace {

// A guide's values (float32, render/panorama.h), or none (the file's bands named); lon and lat
// are made from their offsets (Panorama::lonlat) as they are written.
struct GuideBand {
  const char* name;
  const float* values = nullptr;
  int degrees = -1;  // 0 lon, 1 lat: the pixels' own, float64
};

GuideBand guide_band(const char* name, const FreshArray<float>* values) {
  return {name, values ? values->data() : nullptr};
}

// The guides written, in band order: the four always there, those computed, then the shading
// (so that the earlier bands keep their numbers) and, anti-aliased, the coverage.
std::vector<GuideBand> guide_bands(const Panorama* p, bool land_cover, bool cast_shadow,
                                   bool coverage) {
  std::vector<GuideBand> bands = {guide_band("altitude", p ? &p->altitude : nullptr),
                                  guide_band("distance", p ? &p->distance : nullptr),
                                  {"lon", nullptr, 0},
                                  {"lat", nullptr, 1}};
  if (land_cover) bands.push_back(guide_band("land_cover", p ? &p->land_cover : nullptr));
  if (cast_shadow) bands.push_back(guide_band("cast_shadow", p ? &p->cast_shadow : nullptr));
  bands.push_back(guide_band("shading", p ? &p->shading : nullptr));
  if (coverage) bands.push_back(guide_band("coverage", p ? &p->coverage : nullptr));
  return bands;
}

}  // namespace

PanoramaWriter::PanoramaWriter(const std::string& out, int width, int height, bool land_cover,
                               bool cast_shadow, bool coverage)
    : files_(std::make_unique<Files>(out, width, height)) {
  Files& f = *files_;
  f.land_cover = land_cover;
  f.cast_shadow = cast_shadow;
  f.coverage = coverage;
  f.guides_file.write([&] {
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    const auto bands = guide_bands(nullptr, land_cover, cast_shadow, coverage);
    // DEFLATE at its fastest level: at GDAL's default (6) the guides' compression took ~4.4 s
    // of a 4 MP picture's ~6 s, ten times its rendering; level 1 takes ~1.5 s for a file 3.6 %
    // larger (benchmarks/README.md, "The command's files"). Its blocks compressed by as many
    // threads as the caller allows oneTBB (the same bytes for any count; GDAL writes the blocks in
    // order). With 1, GDAL compresses on the calling thread; with more, in strips its pool may
    // compress a strip's blocks while oneTBB draws the next, up to twice that many threads busy.
    CPLStringList options = geotiff_creation_options(true);
    options.SetNameValue("ZLEVEL", "1");
    options.SetNameValue("NUM_THREADS",
                         std::to_string(tbb::global_control::active_value(
                                            tbb::global_control::max_allowed_parallelism))
                             .c_str());
    f.guides.reset(driver->Create(f.guides_file.temp_path().c_str(), width, height,
                                  int(bands.size()), GDT_Float64, options.List()));
    if (!f.guides) gdal_error("cannot create " + f.guides_file.temp_path());
    for (size_t b = 0; b < bands.size(); ++b) {
      GDALRasterBand* band = f.guides->GetRasterBand(int(b) + 1);
      band->SetDescription(bands[b].name);
      band->SetNoDataValue(NAN);
    }
  });
}

PanoramaWriter::~PanoramaWriter() = default;

void PanoramaWriter::write(const Panorama& strip, int first, int last) {
  Files& f = *files_;
  const size_t offset = size_t(first - strip.first_row) * size_t(f.width);
  const size_t pixels = size_t(last - first) * size_t(f.width);
  std::copy_n(strip.rgb.begin() + std::ptrdiff_t(3 * offset), 3 * pixels,
              f.rgb.begin() + std::ptrdiff_t(3 * size_t(first) * size_t(f.width)));
  std::copy_n(strip.silhouette.begin() + std::ptrdiff_t(offset), pixels,
              f.silhouette.begin() + std::ptrdiff_t(size_t(first) * size_t(f.width)));
  for (size_t i = offset; i < offset + pixels; ++i)
    if (const double d = strip.distance[i]; !std::isnan(d)) {
      ++f.terrain_pixels;
      f.nearest_terrain = std::min(f.nearest_terrain, d);
    }
  const auto bands = guide_bands(&strip, f.land_cover, f.cast_shadow, f.coverage);
  f.guides_file.write([&] {
    for (const GuideBand& band : bands) {
      GDALRasterBand* out = f.guides->GetRasterBand(int(&band - bands.data()) + 1);
      auto write_rows = [&](int row, int rows, void* values, GDALDataType type) {
        if (out->RasterIO(GF_Write, 0, row, f.width, rows, values, f.width, rows, type, 0, 0) !=
            CE_None)
          gdal_error("cannot write " + f.guides_file.temp_path());
      };
      if (band.values) {
        write_rows(first, last - first, const_cast<float*>(band.values + offset), GDT_Float32);
        continue;
      }
      // lon or lat, a block of rows at a time (a strip's float64 degrees would be twice its
      // offsets' memory).
      std::vector<double> degrees;
      for (int row = first; row < last; row += kGuideBlockRows) {
        const int rows = std::min(kGuideBlockRows, last - row);
        degrees.resize(size_t(rows) * size_t(f.width));
        const size_t at = size_t(row - strip.first_row) * size_t(f.width);
        for (size_t i = 0; i < degrees.size(); ++i) {
          const LonLat p = strip.lonlat(at + i);
          degrees[i] = band.degrees == 0 ? p.lon : p.lat;
        }
        write_rows(row, rows, degrees.data(), GDT_Float64);
      }
    }
  });
}

int64_t PanoramaWriter::terrain_pixels() const { return files_->terrain_pixels; }

double PanoramaWriter::nearest_terrain() const { return files_->nearest_terrain; }

void PanoramaWriter::commit() {
  Files& f = *files_;
  f.guides.reset();  // flushes the last blocks
  write_image(f.rgb, f.width, f.height, 3, panorama_picture_format(f.out), f.picture_file);
  write_image(f.silhouette, f.width, f.height, 1,
              panorama_picture_format(f.silhouettes_file.path()), f.silhouettes_file);
  f.picture_file.commit();
  f.silhouettes_file.commit();
  f.guides_file.commit();
}

void write_panorama(const Panorama& p, const std::string& out) {
  PanoramaWriter writer(out, p.width, p.height, !p.land_cover.empty(), !p.cast_shadow.empty(),
                        !p.coverage.empty());
  writer.write(p, 0, p.height);
  writer.commit();
}

int default_strip_rows(int width) {
  const int rows = int(kStripPixels / width) / kGuideBlockRows * kGuideBlockRows;
  return std::max(rows, kGuideBlockRows);
}

namespace {

// Rows of fragments drawn at once for a picture in memory: about 2 M pixels (40 MB of fragments),
// a multiple of the rasterizer's bands of 8 rows.
int fragment_rows(int width) { return std::max(8, int(kFragmentPixels / width) / 8 * 8); }

// Rasterizes and shades the panorama of `scene` in strips of `strip_rows` rows into `writer`
// (render_strips). One strip's arrays are drawn into strip after strip, each sized for the largest
// strip at its first use (render/fresh_array.h resize_fresh): their pages are given once a picture,
// and freed when this returns, before the files are encoded.
void draw_strips(const Store& store, const Grid& grid, TerrainScene& scene,
                 const PinholeCamera& camera, const PanoramaLook& look, int strip_rows,
                 PanoramaWriter& writer) {
  const int w = camera.spec().width, h = camera.spec().height;
  if (strip_rows >= h) {
    writer.write(draw_panorama(store, grid, scene, camera, look), 0, h);
    return;
  }
  StripDrawer draw(scene, camera);
  PanoramaSamplers samplers(store, grid, look);
  std::optional<Supersampler> samples;
  if (look.antialias > 1) samples.emplace(store, grid, scene, camera, look);
  FreshArray<float> texels;
  StretchTexels stretch_texels;
  if (look.texture && look.stretch) {
    // Room for every pixel of the stretch grid (untouched pages cost nothing): the strips' texels
    // appended without regrowth, whose copies into twice the capacity gave pages twice.
    const int step = stretch_step(w, h);
    stretch_texels.reserve(3 * size_t((w + step - 1) / step) * size_t((h + step - 1) / step));
    for (int first = 0; first < h; first += strip_rows) {
      gather_stretch_texels(grid, scene, draw(first, strip_rows), camera, look, samplers, step,
                            stretch_texels, texels);
      samplers.forget_unused();
    }
  }
  const BandStretch stretch = texel_stretch(stretch_texels, look);
  Panorama strip;
  for (int first = 0; first < h; first += strip_rows) {
    const int last = std::min(h, first + strip_rows);
    // A row of margin each side: the silhouettes of the strip's edge rows look at their
    // neighbours. Every strip but the last drawn strip_rows + 2 rows (the first its margin below
    // and one more row), so that the first is the largest and its arrays serve every other.
    const int top = std::max(0, first - 1), bottom = std::min(h, top + strip_rows + 2);
    size_panorama(strip, w, top, bottom - top, look);
    shade_guides(grid, scene, draw(top, bottom - top), camera, look, samplers, strip, texels,
                 nullptr);
    samplers.forget_unused();
    colour_panorama(camera, look, stretch, texels, strip);
    if (samples) samples->colour(stretch, strip);
    writer.write(strip, first, last);
  }
}

}  // namespace

Panorama draw_panorama(const Store& store, const Grid& grid, TerrainScene& scene,
                       const PinholeCamera& camera, const PanoramaLook& look, int rows) {
  StripDrawer draw(scene, camera);
  BandStretch stretch;
  Panorama p = shade_panorama(store, grid, scene, camera, look,
                              rows > 0 ? rows : fragment_rows(camera.spec().width), std::ref(draw),
                              &stretch);
  if (look.antialias > 1) Supersampler(store, grid, scene, camera, look).colour(stretch, p);
  return p;
}

void render_strips(const Store& store, const Grid& grid, TerrainScene& scene,
                   const PinholeCamera& camera, const PanoramaLook& look, int strip_rows,
                   const std::string& out) {
  PanoramaWriter writer(out, camera.spec().width, camera.spec().height, look.land_cover != nullptr,
                        look.shadow != nullptr, look.antialias > 1);
  draw_strips(store, grid, scene, camera, look, strip_rows, writer);
  // Nothing of the terrain drawn, though tiles were in or near the view: an all-sky picture, exit
  // 0.
  if (writer.terrain_pixels() == 0)
    throw Error("the picture shows none of the terrain (the camera " + view_text(camera.spec()) +
                "): aimed away from it, at ground beyond the DEM's data, or a bend rolling it "
                "over the eye; nothing written");
  // Haze covers 1 - exp(-distance / haze_distance) of a pixel: beyond 3 haze distances, 95 %.
  if (const double nearest = writer.nearest_terrain(); nearest > 3 * look.haze_distance)
    spdlog::warn(
        "the nearest terrain in the picture is {:.1f} km away, {:.1f} times --haze-distance {:g} "
        "m: all of it is drawn at least 95 % in the haze's colour; raise --haze-distance",
        nearest / 1000, nearest / look.haze_distance, look.haze_distance);
  writer.commit();
}

}  // namespace maquette
