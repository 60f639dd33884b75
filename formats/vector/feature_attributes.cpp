#include "vector/feature_attributes.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "core/json_file.h"

namespace maquette {
namespace {

using json = nlohmann::json;

json real(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string hex(const GByte* data, int size) {
  std::string out;
  char byte[3];
  for (int i = 0; i < size; ++i) {
    std::snprintf(byte, sizeof byte, "%02x", data[i]);
    out += byte;
  }
  return out;
}

// The field's date and time as ISO 8601: "2024-05-01", "12:30:00", "2024-05-01T12:30:00.5Z".
std::string iso8601(const OGRFeature& f, int i, OGRFieldType type) {
  int y, mo, d, h, mi, tz;
  float s;
  f.GetFieldAsDateTime(i, &y, &mo, &d, &h, &mi, &s, &tz);
  char date[48], time[48];
  std::snprintf(date, sizeof date, "%04d-%02d-%02d", y, mo, d);
  std::snprintf(time, sizeof time, "%02d:%02d:%06.3f", h, mi, double(s));
  if (type == OFTDate) return date;
  if (type == OFTTime) return time;
  // OGR's tz flag: 0 unknown, 1 local time, 100 UTC, 100 +- n: offset of n quarter hours.
  std::string zone;
  if (tz == 100) {
    zone = "Z";
  } else if (tz > 1) {
    char offset[32];
    const int q = std::abs(tz - 100);
    std::snprintf(offset, sizeof offset, "%c%02d:%02d", tz > 100 ? '+' : '-', q / 4, q % 4 * 15);
    zone = offset;
  }
  return std::string(date) + "T" + time + zone;
}

json field_value(const OGRFeature& f, int i, const OGRFieldDefn& defn) {
  const OGRFieldType type = defn.GetType();
  const bool boolean = defn.GetSubType() == OFSTBoolean;
  int n = 0;
  switch (type) {
    case OFTInteger:
      return boolean ? json(f.GetFieldAsInteger(i) != 0) : json(f.GetFieldAsInteger(i));
    case OFTInteger64:
      return boolean ? json(f.GetFieldAsInteger64(i) != 0) : json(f.GetFieldAsInteger64(i));
    case OFTReal:
      return real(f.GetFieldAsDouble(i));
    case OFTString: {
      const char* text = f.GetFieldAsString(i);
      if (defn.GetSubType() == OFSTJSON) {
        try {
          return parse_json(text, "");  // nesting bounded, as every JSON the program reads
        } catch (const Error&) {        // not JSON (or too deep): kept as text
        }
      }
      return text;
    }
    case OFTDate:
    case OFTTime:
    case OFTDateTime:
      return iso8601(f, i, type);
    case OFTIntegerList: {
      const int* v = f.GetFieldAsIntegerList(i, &n);
      json a = json::array();
      for (int k = 0; k < n; ++k) a.push_back(boolean ? json(v[k] != 0) : json(v[k]));
      return a;
    }
    case OFTInteger64List: {
      const GIntBig* v = f.GetFieldAsInteger64List(i, &n);
      return json(std::vector<int64_t>(v, v + n));
    }
    case OFTRealList: {
      const double* v = f.GetFieldAsDoubleList(i, &n);
      json a = json::array();
      for (int k = 0; k < n; ++k) a.push_back(real(v[k]));
      return a;
    }
    case OFTStringList: {
      json a = json::array();
      if (char** v = f.GetFieldAsStringList(i))
        for (; *v; ++v) a.push_back(*v);
      return a;
    }
    case OFTBinary: {
      const GByte* v = f.GetFieldAsBinary(i, &n);
      return hex(v, n);
    }
    default:
      return f.GetFieldAsString(i);
  }
}

}  // namespace

json feature_attributes(const OGRFeature& feature) {
  json out = json::object();
  for (int i = 0; i < feature.GetFieldCount(); ++i) {
    const OGRFieldDefn& defn = *feature.GetFieldDefnRef(i);
    out[defn.GetNameRef()] =
        feature.IsFieldSetAndNotNull(i) ? field_value(feature, i, defn) : json(nullptr);
  }
  return out;
}

}  // namespace maquette
