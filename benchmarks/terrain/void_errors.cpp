// Side-by-side measures of DEM void fills on GeoTIFFs of one grid (fill_voids_vs_gdal.sh):
//   void_errors punch IN OUT SIZE      OUT = IN with a square void of SIZE pixels at its centre
//                                      (nodata -32768; IN's own voids inside it are not compared:
//                                      TRUTH has no height there)
//   void_errors compare TRUTH VOIDS NAME=FILLED...
//                                      over the samples that are voids in VOIDS and known in
//                                      TRUTH: holes left by each fill, its RMSE and largest
//                                      error against TRUTH, and the RMSE between two fills
//   void_errors seams VOIDS FILLED TILE
//                                      mean |difference| of neighbouring filled samples across
//                                      tile edges (every TILE pixels) and elsewhere
//   void_errors montage OUT IN...      the RGB images IN side by side (4 white pixels between
//                                      them, top-aligned) as OUT (PNG or JPEG by its extension)
#include <gdal_priv.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Raster {
  int width = 0, height = 0;
  std::vector<double> v;  // NaN where nodata
  double at(int x, int y) const { return v[size_t(y) * size_t(width) + size_t(x)]; }
};

Raster read(const std::string& path) {
  const std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  if (!ds) throw std::runtime_error("cannot open " + path);
  GDALRasterBand* band = ds->GetRasterBand(1);
  Raster r{ds->GetRasterXSize(), ds->GetRasterYSize(), {}};
  r.v.resize(size_t(r.width) * size_t(r.height));
  if (band->RasterIO(GF_Read, 0, 0, r.width, r.height, r.v.data(), r.width, r.height, GDT_Float64,
                     0, 0) != CE_None)
    throw std::runtime_error("cannot read " + path);
  int has = 0;
  const double nodata = band->GetNoDataValue(&has);
  for (double& x : r.v)
    if ((has && x == nodata) || !std::isfinite(x)) x = NAN;
  return r;
}

void punch(const std::string& in, const std::string& out, int size) {
  const std::unique_ptr<GDALDataset> src(GDALDataset::Open(in.c_str(), GDAL_OF_RASTER));
  if (!src) throw std::runtime_error("cannot open " + in);
  const Raster r = read(in);
  if (size > r.width || size > r.height) throw std::runtime_error("no room for the void");
  const int x0 = (r.width - size) / 2, y0 = (r.height - size) / 2;
  std::vector<double> punched = r.v;
  for (int y = y0; y < y0 + size; ++y)
    for (int x = x0; x < x0 + size; ++x) punched[size_t(y) * size_t(r.width) + size_t(x)] = NAN;
  std::printf("punched %d x %d at column %d, row %d\n", size, size, x0, y0);
  for (double& x : punched)
    if (std::isnan(x)) x = -32768;
  GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
  const std::unique_ptr<GDALDataset> dst(
      gtiff->Create(out.c_str(), r.width, r.height, 1, GDT_Float32, nullptr));
  double transform[6];
  src->GetGeoTransform(transform);
  dst->SetGeoTransform(transform);
  dst->SetSpatialRef(src->GetSpatialRef());
  GDALRasterBand* band = dst->GetRasterBand(1);
  band->SetNoDataValue(-32768);
  if (band->RasterIO(GF_Write, 0, 0, r.width, r.height, punched.data(), r.width, r.height,
                     GDT_Float64, 0, 0) != CE_None)
    throw std::runtime_error("cannot write " + out);
}

void compare(const std::string& truth_path, const std::string& voids_path,
             const std::vector<std::string>& fills) {
  const Raster voids = read(voids_path), truth = read(truth_path);
  std::vector<std::string> names;
  std::vector<Raster> filled;
  for (const std::string& f : fills) {
    const size_t eq = f.find('=');
    names.push_back(f.substr(0, eq));
    filled.push_back(read(f.substr(eq + 1)));
    if (filled.back().width != voids.width || filled.back().height != voids.height)
      throw std::runtime_error(f + ": not the grid of " + voids_path);
  }
  size_t count = 0;
  std::vector<size_t> holes(fills.size(), 0);
  std::vector<double> sq(fills.size(), 0), worst(fills.size(), 0);
  double between = 0;
  size_t both = 0;
  for (size_t i = 0; i < voids.v.size(); ++i) {
    if (!std::isnan(voids.v[i]) || std::isnan(truth.v[i])) continue;
    ++count;
    for (size_t k = 0; k < fills.size(); ++k) {
      const double f = filled[k].v[i];
      if (std::isnan(f)) {
        ++holes[k];
        continue;
      }
      sq[k] += (f - truth.v[i]) * (f - truth.v[i]);
      worst[k] = std::max(worst[k], std::abs(f - truth.v[i]));
    }
    if (fills.size() == 2 && !std::isnan(filled[0].v[i]) && !std::isnan(filled[1].v[i])) {
      between += (filled[0].v[i] - filled[1].v[i]) * (filled[0].v[i] - filled[1].v[i]);
      ++both;
    }
  }
  std::printf("%zu void samples\n", count);
  for (size_t k = 0; k < fills.size(); ++k) {
    std::printf("%-8s holes left %zu (%.2f %%), RMSE %.2f m, largest error %.1f m\n",
                names[k].c_str(), holes[k], 100.0 * double(holes[k]) / double(count),
                std::sqrt(sq[k] / double(count - holes[k])), worst[k]);
  }
  if (both)
    std::printf("RMSE %s - %s: %.2f m over %zu samples\n", names[0].c_str(), names[1].c_str(),
                std::sqrt(between / double(both)), both);
}

void seams(const std::string& voids_path, const std::string& filled_path, int tile) {
  const Raster voids = read(voids_path), filled = read(filled_path);
  double across = 0, inside = 0;
  size_t n_across = 0, n_inside = 0;
  const auto pair = [&](int x0, int y0, int x1, int y1, bool edge) {
    if (!std::isnan(voids.at(x0, y0)) || !std::isnan(voids.at(x1, y1))) return;
    const double a = filled.at(x0, y0), b = filled.at(x1, y1);
    if (std::isnan(a) || std::isnan(b)) return;
    (edge ? across : inside) += std::abs(a - b);
    ++(edge ? n_across : n_inside);
  };
  for (int y = 0; y < voids.height; ++y)
    for (int x = 0; x < voids.width; ++x) {
      if (x + 1 < voids.width) pair(x, y, x + 1, y, (x + 1) % tile == 0);
      if (y + 1 < voids.height) pair(x, y, x, y + 1, (y + 1) % tile == 0);
    }
  std::printf(
      "filled neighbours: mean |difference| %.3f m across tile edges (%zu pairs), %.3f m "
      "elsewhere (%zu pairs), ratio %.2f\n",
      across / double(n_across), n_across, inside / double(n_inside), n_inside,
      (across / double(n_across)) / (inside / double(n_inside)));
}

void montage(const std::string& out, const std::vector<std::string>& images) {
  constexpr int kGap = 4;
  std::vector<std::unique_ptr<GDALDataset>> in;
  int width = -kGap, height = 0;
  for (const std::string& path : images) {
    in.emplace_back(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
    if (!in.back() || in.back()->GetRasterCount() < 3)
      throw std::runtime_error("cannot read an RGB image from " + path);
    width += in.back()->GetRasterXSize() + kGap;
    height = std::max(height, in.back()->GetRasterYSize());
  }
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  const std::unique_ptr<GDALDataset> canvas(mem->Create("", width, height, 3, GDT_Byte, nullptr));
  std::vector<unsigned char> white(size_t(width) * size_t(height), 255), pixels;
  for (int b = 1; b <= 3; ++b)
    if (canvas->GetRasterBand(b)->RasterIO(GF_Write, 0, 0, width, height, white.data(), width,
                                           height, GDT_Byte, 0, 0) != CE_None)
      throw std::runtime_error("cannot fill the canvas");
  int x = 0;
  for (const auto& image : in) {
    const int w = image->GetRasterXSize(), h = image->GetRasterYSize();
    pixels.resize(size_t(w) * size_t(h));
    for (int b = 1; b <= 3; ++b)
      if (image->GetRasterBand(b)->RasterIO(GF_Read, 0, 0, w, h, pixels.data(), w, h, GDT_Byte, 0,
                                            0) != CE_None ||
          canvas->GetRasterBand(b)->RasterIO(GF_Write, x, 0, w, h, pixels.data(), w, h, GDT_Byte, 0,
                                             0) != CE_None)
        throw std::runtime_error("cannot copy an image");
    x += w + kGap;
  }
  const bool jpeg = out.size() > 4 && out.substr(out.size() - 4) == ".jpg";
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(jpeg ? "JPEG" : "PNG");
  const char* options[] = {jpeg ? "QUALITY=85" : nullptr, nullptr};
  const std::unique_ptr<GDALDataset> written(driver->CreateCopy(
      out.c_str(), canvas.get(), FALSE, const_cast<char**>(options), nullptr, nullptr));
  if (!written) throw std::runtime_error("cannot write " + out);
}

}  // namespace

int main(int argc, char** argv) try {
  GDALAllRegister();
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 4 && args[0] == "punch") {
    punch(args[1], args[2], std::stoi(args[3]));
  } else if (args.size() >= 4 && args[0] == "compare") {
    compare(args[1], args[2], {args.begin() + 3, args.end()});
  } else if (args.size() == 4 && args[0] == "seams") {
    seams(args[1], args[2], std::stoi(args[3]));
  } else if (args.size() >= 3 && args[0] == "montage") {
    montage(args[1], {args.begin() + 2, args.end()});
  } else {
    std::cerr
        << "usage: void_errors punch IN OUT SIZE | compare TRUTH VOIDS NAME=FILLED... | seams "
           "VOIDS FILLED TILE | montage OUT IN...\n";
    return 2;
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "void_errors: " << e.what() << "\n";
  return 1;
}
