// maquette-paint: the transfer in the picture (README: maquette-paint). A program, not an
// operator: its target is a rendered picture, not the store's cells.
//   maquette-paint PANORAMA.png PARAMS.json OUT.png [-t N]   (--help: what each is)
// writes OUT.png (the painted picture; .jpg: JPEG) and OUT-source.tif (float32, bands column and
// row: the painting pixel each pixel was copied from, NaN where nothing was painted).
#include <gdal_priv.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/json_file.h"
#include "core/output_clash.h"
#include "core/output_file.h"
#include "core/sibling_path.h"
#include "gdal/gdal_env.h"
#include "gdal/image_file.h"
#include "paint_panorama.h"
#include "render/panorama_strips.h"

using namespace maquette;
using namespace maquette::synthesis;

namespace {

// Into the temporary file of `file`; a failure GDAL reports only while it closes the file (a full
// disk) is one too.
void write_source(const PaintedPanorama& painted, const OutputFile& file) {
  const std::string& path = file.path();
  const GdalSession gdal;
  const GdalErrorTrap trap;
  std::unique_ptr<GDALDataset> ds(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
      file.temp_path().c_str(), painted.width, painted.height, 2, GDT_Float32, nullptr));
  if (!ds) gdal_error(path + ": GDAL cannot create it");
  int bands[2] = {1, 2};
  const char* names[2] = {"column", "row"};
  for (int b = 0; b < 2; ++b) {
    ds->GetRasterBand(b + 1)->SetDescription(names[b]);
    ds->GetRasterBand(b + 1)->SetNoDataValue(NAN);
  }
  if (ds->RasterIO(GF_Write, 0, 0, painted.width, painted.height,
                   const_cast<float*>(painted.source.data()), painted.width, painted.height,
                   GDT_Float32, 2, bands, 8, 8 * long(painted.width), 4, nullptr) != CE_None)
    gdal_error(path + ": GDAL cannot write it");
  ds.reset();
  trap.check(path + ": GDAL cannot write it");
}

}  // namespace

int main(int argc, char** argv) {
  spdlog::set_default_logger(spdlog::stderr_color_mt("maquette-paint"));  // as maquette's
  spdlog::set_pattern("%^%l%$: %v");
  CLI::App app{
      "maquette-paint: paints a rendered panorama in the hand of a painting (paper 000's transfer "
      "in the picture). PANORAMA is `maquette render panorama`'s PNG, read with its "
      "PANORAMA-guides.tif (land cover, altitude, distance, light); PARAMS the painting and the "
      "weights (modules/synthesis/README.md, \"The transfer in the picture\"). Writes OUT "
      "(PNG, or JPEG for .jpg) and OUT-source.tif beside it (float32, bands column and row: the "
      "painting pixel each "
      "pixel was copied from, NaN where nothing was painted); a failure writes neither (older "
      "files stay).",
      "maquette-paint"};
  std::string picture_path, params_path, out;
  int thread_count = 0;
  app.add_option("PANORAMA", picture_path, "The rendered panorama (PNG)")->required();
  app.add_option("PARAMS", params_path, "The params (JSON)")->required();
  app.add_option("OUT", out, "The painted panorama (.png, or .jpg at JPEG quality 90)")->required();
  app.add_option("-t,--threads", thread_count, "Threads (0: every core)")
      ->check(CLI::Range(0, 4096));
  CLI11_PARSE(app, argc, argv);
  std::optional<tbb::global_control> threads;
  if (thread_count > 0)
    threads.emplace(tbb::global_control::max_allowed_parallelism, size_t(thread_count));
  try {
    const std::string source = sibling_path(out, "-source.tif");
    const PaintParams params = paint_params(read_json_file(params_path), params_path);
    // Refused before anything is written: an output that is one of the run's inputs.
    check_outputs_spare_inputs({out, source}, paint_inputs(picture_path, params_path, params));
    const ImageFormat format = panorama_picture_format(out);  // by its extension, as render's
    const PanoramaPicture picture =
        read_panorama(picture_path, params.shading > 0 || params.synthesis.w_light > 0);
    const auto exemplar = transfer_exemplar(params.exemplar, params_path);
    const PaintedPanorama painted = paint_panorama(picture, *exemplar, params);
    // Both written before either replaces an older file: a failure leaves the old pair.
    OutputFile picture_file(out), source_file(source, {".aux.xml"});
    write_image(painted.rgb, painted.width, painted.height, 3, format, picture_file);
    source_file.write([&] { write_source(painted, source_file); });
    picture_file.commit();
    source_file.commit();
    std::printf("%s: %d x %d pixels painted from %s\n", out.c_str(), painted.width, painted.height,
                params.exemplar.at("painting").get<std::string>().c_str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "maquette-paint: error: " << e.what() << "\n";
    return 1;
  }
}
