#include "gdal/image_file.h"

#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>

#include <atomic>
#include <mutex>

#include "core/error.h"
#include "core/output_file.h"
#include "gdal/gdal_drivers.h"
#include "gdal/gdal_env.h"

namespace maquette {

namespace {

// write_image to any GDAL path (`path`: the one errors name).
void create_image(std::span<const uint8_t> pixels, int width, int height, int bands,
                  const ImageFormat& format, const std::string& gdal_path,
                  const std::string& path) {
  init_gdal();
  register_all_gdal_drivers();
  const std::string why = "cannot write " + path;
  if (pixels.size() != size_t(width) * size_t(height) * size_t(bands))
    throw Error(why + ": " + std::to_string(pixels.size()) + " bytes for " + std::to_string(width) +
                " x " + std::to_string(height) + " x " + std::to_string(bands));
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  GDALDriver* out_driver = GetGDALDriverManager()->GetDriverByName(format.driver.c_str());
  if (!mem || !out_driver) throw Error(why + ": GDAL has no MEM or " + format.driver + " driver");
  const GDALDatasetUniquePtr image(mem->Create("", width, height, bands, GDT_Byte, nullptr));
  // RasterIO reads from the buffer when writing; GDAL's signature takes it non-const.
  if (!image || image->RasterIO(GF_Write, 0, 0, width, height, const_cast<uint8_t*>(pixels.data()),
                                width, height, GDT_Byte, bands, nullptr, bands,
                                GSpacing(bands) * width, 1, nullptr) != CE_None)
    throw Error(why + ": " + gdal_last_error("GDAL failed"));
  {
    // GDAL's JPEG driver builds its creation option list on the first request, unguarded: a
    // thread validating options against it while another builds it parses half a list (an
    // error the trap below reports). Built once, under a lock, before any CreateCopy.
    static std::mutex first_request;
    const std::lock_guard lock(first_request);
    out_driver->GetMetadataItem(GDAL_DMD_CREATIONOPTIONLIST);
  }
  CPLStringList options;
  for (const std::string& o : format.options) options.AddString(o.c_str());
  GdalErrorTrap trap;
  GDALDatasetUniquePtr out(out_driver->CreateCopy(gdal_path.c_str(), image.get(), FALSE,
                                                  options.List(), nullptr, nullptr));
  if (!out) throw Error(why + ": " + gdal_last_error("the " + format.driver + " driver failed"));
  out.reset();  // closes the file
  trap.check(why);
}

}  // namespace

void write_image(std::span<const uint8_t> pixels, int width, int height, int bands,
                 const ImageFormat& format, const std::string& path) {
  if (path.starts_with("/vsi"))
    return create_image(pixels, width, height, bands, format, path, path);
  OutputFile out(path, {".aux.xml"});
  write_image(pixels, width, height, bands, format, out);
  out.commit();
}

void write_image(std::span<const uint8_t> pixels, int width, int height, int bands,
                 const ImageFormat& format, const OutputFile& out) {
  create_image(pixels, width, height, bands, format, out.temp_path(), out.path());
}

std::vector<uint8_t> encode_image(std::span<const uint8_t> pixels, int width, int height, int bands,
                                  const ImageFormat& format) {
  static std::atomic<uint64_t> serial = 0;  // one /vsimem/ file per call, threads alike
  const std::string path = "/vsimem/maquette_image_" + std::to_string(serial++);
  try {
    write_image(pixels, width, height, bands, format, path);
  } catch (...) {
    VSIUnlink(path.c_str());
    throw;
  }
  vsi_l_offset size = 0;
  GByte* bytes = VSIGetMemFileBuffer(path.c_str(), &size, TRUE);  // takes the buffer, unlinks
  if (!bytes) throw Error("cannot encode an image: GDAL wrote no " + format.driver + " bytes");
  std::vector<uint8_t> out(bytes, bytes + size);
  VSIFree(bytes);
  return out;
}

}  // namespace maquette
