// maquette-paint: the transfer in the picture (README: maquette-paint). A program, not an
// operator: its target is a rendered picture, not the store's cells.
//   maquette-paint PANORAMA.png PARAMS.json OUT.png [-t N]
// writes OUT.png (the painted picture) and OUT-source.tif (float32, bands column and row: the
// painting pixel each pixel was copied from, NaN where nothing was painted).
#include <gdal_priv.h>
#include <tbb/global_control.h>

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

using namespace maquette;
using namespace maquette::synthesis;

namespace {

void write_source(const PaintedPanorama& painted, const std::string& path) {
  OutputFile file(path, {".aux.xml"});
  file.write([&] {
    const GdalSession gdal;
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
  });
  file.commit();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string usage = "usage: maquette-paint PANORAMA.png PARAMS.json OUT.png [-t THREADS]";
  std::optional<tbb::global_control> threads;
  if (argc == 6 && std::string(argv[4]) == "-t") {
    const int n = std::atoi(argv[5]);
    if (n < 1) {
      std::cerr << "maquette-paint: -t " << argv[5] << ": expected a thread count >= 1\n";
      return 2;
    }
    threads.emplace(tbb::global_control::max_allowed_parallelism, size_t(n));
  } else if (argc != 4) {
    std::cerr << usage << "\n";
    return 2;
  }
  try {
    const std::string picture_path = argv[1], params_path = argv[2], out = argv[3],
                      source = sibling_path(out, "-source.tif");
    const PaintParams params = paint_params(read_json_file(params_path), params_path);
    // Refused before anything is written: an output that is one of the run's inputs.
    check_outputs_spare_inputs({out, source}, paint_inputs(picture_path, params_path, params));
    const PanoramaPicture picture =
        read_panorama(picture_path, params.shading > 0 || params.synthesis.w_light > 0);
    const auto exemplar = transfer_exemplar(params.exemplar, params_path);
    const PaintedPanorama painted = paint_panorama(picture, *exemplar, params);
    write_image(painted.rgb, painted.width, painted.height, 3, ImageFormat{"PNG", {}}, out);
    write_source(painted, source);
    std::printf("%s: %d x %d pixels painted from %s\n", out.c_str(), painted.width, painted.height,
                params.exemplar.at("painting").get<std::string>().c_str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "maquette-paint: " << e.what() << "\n";
    return 1;
  }
}
