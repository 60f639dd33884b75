#include "vector/feature_attributes.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

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

// A JSON array into a list field of `type`; other fields get the array as JSON text.
void set_list(OGRFeature& f, int i, OGRFieldType type, const json& a) {
  if (type == OFTIntegerList) {
    std::vector<int> v;
    for (const json& x : a) v.push_back(x.is_boolean() ? int(x.get<bool>()) : x.get<int>());
    f.SetField(i, int(v.size()), v.data());
  } else if (type == OFTInteger64List) {
    const auto v = a.get<std::vector<GIntBig>>();
    f.SetField(i, int(v.size()), v.data());
  } else if (type == OFTRealList) {
    std::vector<double> v;
    for (const json& x : a)
      v.push_back(x.is_null() ? std::numeric_limits<double>::quiet_NaN() : x.get<double>());
    f.SetField(i, int(v.size()), v.data());
  } else if (type == OFTStringList) {
    CPLStringList v;
    for (const json& x : a)
      v.AddString(x.is_string() ? x.get<std::string>().c_str() : x.dump().c_str());
    f.SetField(i, v.List());
  } else {
    f.SetField(i, a.dump().c_str());
  }
}

// `v` into field i; OGR converts between numbers and text as the field's type asks (dates and
// hex binary from their text).
void set_field(OGRFeature& f, int i, const json& v) {
  if (v.is_null())
    f.SetFieldNull(i);
  else if (v.is_boolean())
    f.SetField(i, int(v.get<bool>()));
  else if (v.is_number_integer())
    f.SetField(i, GIntBig(v.get<int64_t>()));
  else if (v.is_number())
    f.SetField(i, v.get<double>());
  else if (v.is_string())
    f.SetField(i, v.get_ref<const std::string&>().c_str());
  else if (v.is_array())
    set_list(f, i, f.GetFieldDefnRef(i)->GetType(), v);
  else
    f.SetField(i, v.dump().c_str());
}

template <typename T, typename NameOf>
T by_name(const std::string& name, int max, NameOf name_of, const char* what) {
  for (int t = 0; t <= max; ++t)
    if (name == name_of(T(t))) return T(t);
  throw Error("unknown OGR field " + std::string(what) + " '" + name + "'");
}

}  // namespace

json field_definitions(const OGRFeatureDefn& defn) {
  json out = json::array();
  for (int i = 0; i < defn.GetFieldCount(); ++i) {
    const OGRFieldDefn& f = *defn.GetFieldDefn(i);
    out.push_back({{"name", f.GetNameRef()},
                   {"type", OGRFieldDefn::GetFieldTypeName(f.GetType())},
                   {"subtype", OGRFieldDefn::GetFieldSubTypeName(f.GetSubType())}});
  }
  return out;
}

std::unique_ptr<OGRFieldDefn> field_definition(const json& d) {
  auto f = std::make_unique<OGRFieldDefn>(
      d.at("name").get<std::string>().c_str(),
      by_name<OGRFieldType>(d.at("type").get<std::string>(), OFTMaxType,
                            OGRFieldDefn::GetFieldTypeName, "type"));
  f->SetSubType(by_name<OGRFieldSubType>(d.value("subtype", "None"), OFSTMaxSubType,
                                         OGRFieldDefn::GetFieldSubTypeName, "subtype"));
  return f;
}

std::unique_ptr<OGRFieldDefn> inferred_field(const std::string& name, const json& value) {
  const OGRFieldType type = value.is_boolean()          ? OFTInteger
                            : value.is_number_integer() ? OFTInteger64
                            : value.is_number()         ? OFTReal
                                                        : OFTString;
  auto f = std::make_unique<OGRFieldDefn>(name.c_str(), type);
  if (value.is_boolean()) f->SetSubType(OFSTBoolean);
  if (value.is_object() || value.is_array()) f->SetSubType(OFSTJSON);
  return f;
}

void set_feature_attributes(OGRFeature& feature, const json& attributes) {
  for (auto it = attributes.begin(); it != attributes.end(); ++it) {
    const int i = feature.GetFieldIndex(it.key().c_str());
    if (i >= 0) set_field(feature, i, it.value());
  }
}

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
