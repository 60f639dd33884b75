// Panoramas drawn and written in strips of rows, so a picture 16,000 pixels wide needs memory for
// one strip's fragments and guides (about 80 bytes a pixel) plus 4 bytes a pixel of the whole
// picture (its colours and silhouettes, kept until the PNGs are encoded), not 80 bytes a pixel of
// the whole. Every strip is rasterized as the same rows of the whole picture (render/
// rasterizer.h) with a row of margin above and below for the silhouettes, and shaded with the
// whole picture's display stretch (a first pass over the strips gathers its texels): the files
// hold the same pixels, bit for bit, whatever the strips.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gdal/image_file.h"
#include "render/panorama.h"

namespace maquette {

// The panorama's files: OUT (PNG, the picture), OUT's stem + "-guides.tif" (a float64 GeoTIFF,
// no georeferencing, one band each: altitude, distance, lon, lat, and land_cover and cast_shadow
// when computed, then shading, NaN on the sky; then, anti-aliased, coverage) and stem +
// "-silhouettes.png" (8-bit), filled strip by strip. Each file whole or not at all: nothing is in
// place before commit().
class PanoramaWriter {
 public:
  PanoramaWriter(const std::string& out, int width, int height, bool land_cover, bool cast_shadow,
                 bool coverage);
  ~PanoramaWriter();
  // Rows [first, last) of the picture, from `strip`, which holds them.
  void write(const Panorama& strip, int first, int last);
  // Pixels showing terrain (a distance guide) in the rows written so far, and the distance of the
  // nearest (infinity for none).
  int64_t terrain_pixels() const;
  double nearest_terrain() const;
  // Encodes the PNGs and puts the three files in place.
  void commit();

 private:
  struct Files;
  std::unique_ptr<Files> files_;
};

// The files PanoramaWriter writes for OUT: OUT, its guides and its silhouettes.
std::vector<std::string> panorama_files(const std::string& out);

// The picture's format, by OUT's extension (case aside): PNG for .png, JPEG (quality 90) for .jpg
// and .jpeg. Throws maquette::Error for another extension, or when OUT's directory does not exist
// (before anything is drawn: the guides' file, opened first, named it instead).
ImageFormat panorama_picture_format(const std::string& out);

// The whole panorama `p` written as PanoramaWriter does.
void write_panorama(const Panorama& p, const std::string& out);

// Rows per strip when none is asked for: strips of at most 16 M pixels, a multiple of the guides'
// 256-row blocks.
int default_strip_rows(int width);

// The whole panorama of `scene` in memory: its fragments drawn in strips of `fragment_rows` rows
// (0: about 2 M pixels; the same bits for any) into
// one strip's arrays (render/panorama.h shade_panorama; the mesh measured once, render/
// rasterizer.h RasterPlan), so that only the picture's guides, texels and colours are whole,
// writing into `scene` the attributes of the vertices each strip shows (attribute_vertices). With
// look.antialias K > 1 the colours are then made again from K x K samples a pixel
// (render/panorama_supersample.h), with the picture's display stretch.
Panorama draw_panorama(const Store& store, const Grid& grid, TerrainScene& scene,
                       const PinholeCamera& camera, const PanoramaLook& look,
                       int fragment_rows = 0);

// Rasterizes, shades and writes the panorama of `scene` in strips of `strip_rows` rows (> 0),
// writing into `scene` the attributes of the vertices each strip shows (attribute_vertices); with
// look.antialias, each strip's colours from its samples (the same bits as draw_panorama's).
// Throws maquette::Error, writing nothing, when no pixel shows terrain.
void render_strips(const Store& store, const Grid& grid, TerrainScene& scene,
                   const PinholeCamera& camera, const PanoramaLook& look, int strip_rows,
                   const std::string& out);

}  // namespace maquette
