#include "geotiff/gdal_util.h"

namespace maquette {

GDALDataType gdal_type(DType t) {
  switch (t) {
    case DType::U8:
      return GDT_Byte;
    case DType::U16:
      return GDT_UInt16;
    case DType::I16:
      return GDT_Int16;
    case DType::U32:
      return GDT_UInt32;
    case DType::I32:
      return GDT_Int32;
    case DType::F32:
      return GDT_Float32;
    case DType::F64:
      return GDT_Float64;
  }
  __builtin_unreachable();  // DType values are validated when read
}

CPLStringList geotiff_creation_options(bool floating_point) {
  CPLStringList o;
  o.SetNameValue("TILED", "YES");
  o.SetNameValue("BLOCKXSIZE", "256");
  o.SetNameValue("BLOCKYSIZE", "256");
  o.SetNameValue("COMPRESS", "DEFLATE");
  o.SetNameValue("PREDICTOR", floating_point ? "3" : "2");
  o.SetNameValue("BIGTIFF", "IF_SAFER");
  o.SetNameValue("SPARSE_OK", "TRUE");
  return o;
}

}  // namespace maquette
