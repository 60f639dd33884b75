#include "runtime/params_schema.h"

#include <cmath>
#include <cstdint>

#include "core/error.h"
#include "core/json_file.h"
#include "runtime/artifact_refs.h"

namespace maquette {
namespace {

using json = nlohmann::json;

class Validator {
 public:
  explicit Validator(const std::string& context) : context_(context) {}

  json check(const json& schema, const json& value, const std::string& path) const {
    // Checked once the runner has pasted the artifact in (artifact_refs.h).
    if (is_artifact_ref(value)) return value;
    json out = value;
    if (schema.contains("type")) check_type(schema.at("type").get<std::string>(), out, path);
    if (schema.contains("enum")) check_enum(schema.at("enum"), out, path);
    if (out.is_number()) check_range(schema, out, path);
    if (out.is_object()) check_object(schema, out, path);
    if (out.is_array()) check_length(schema, out, path);
    if (out.is_array() && schema.contains("items")) {
      for (size_t i = 0; i < out.size(); ++i)
        out[i] = check(schema.at("items"), out[i], path + "[" + std::to_string(i) + "]");
    }
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw Error(context_ + ": " + path + ": " + what);
  }

  void check_length(const json& schema, const json& value, const std::string& path) const {
    const auto items = [](size_t n) { return std::to_string(n) + (n == 1 ? " item" : " items"); };
    if (schema.contains("minItems") && value.size() < schema.at("minItems").get<size_t>())
      fail(path, "expected at least " + items(schema.at("minItems").get<size_t>()) + ", got " +
                     excerpt(value));
    if (schema.contains("maxItems") && value.size() > schema.at("maxItems").get<size_t>())
      fail(path, "expected at most " + items(schema.at("maxItems").get<size_t>()) + ", got " +
                     excerpt(value));
  }

  // Draft 7: "integer" also accepts a number with a zero fractional part (2.0), stored as 2.
  void check_type(const std::string& type, json& value, const std::string& path) const {
    bool ok = false;
    if (type == "object")
      ok = value.is_object();
    else if (type == "number")
      ok = value.is_number();
    else if (type == "string")
      ok = value.is_string();
    else if (type == "boolean")
      ok = value.is_boolean();
    else if (type == "array")
      ok = value.is_array();
    else if (type == "integer") {
      ok = value.is_number_integer() || (value.is_number_float() && is_whole(value));
      if (ok && !fits_int64(value))
        fail(path, excerpt(value) + " is outside the 64-bit integer range");
      if (ok && value.is_number_float()) value = int64_t(value.get<double>());
    } else {
      fail(path, "the operator's schema has an unsupported type '" + type + "'");
    }
    if (!ok) fail(path, "expected " + article(type) + ", got " + excerpt(value));
  }

  static bool is_whole(const json& value) {
    const double d = value.get<double>();
    return std::isfinite(d) && d == std::trunc(d);
  }

  // Casting a double outside [-2^63, 2^63) to int64_t is undefined: check before.
  static bool fits_int64(const json& value) {
    if (value.is_number_unsigned()) return value.get<uint64_t>() <= uint64_t(INT64_MAX);
    if (value.is_number_integer()) return true;
    const double d = value.get<double>();
    return d >= -0x1p63 && d < 0x1p63;
  }

  static std::string article(const std::string& type) {
    return (type == "object" || type == "integer" || type == "array" ? "an " : "a ") + type;
  }

  void check_enum(const json& allowed, const json& value, const std::string& path) const {
    for (const auto& a : allowed)
      if (a == value) return;
    fail(path, excerpt(value) + " is not one of " + allowed.dump());
  }

  void check_range(const json& schema, const json& value, const std::string& path) const {
    const double v = value.get<double>();
    if (schema.contains("minimum") && v < schema.at("minimum").get<double>())
      fail(path, excerpt(value) + " is below the minimum " + schema.at("minimum").dump());
    if (schema.contains("maximum") && v > schema.at("maximum").get<double>())
      fail(path, excerpt(value) + " is above the maximum " + schema.at("maximum").dump());
  }

  void check_object(const json& schema, json& value, const std::string& path) const {
    const json empty = json::object();
    const json& props = schema.contains("properties") ? schema.at("properties") : empty;
    if (schema.contains("additionalProperties") && schema.at("additionalProperties") == false) {
      for (const auto& [key, _] : value.items())
        if (!props.contains(key)) fail(path, "unknown field '" + excerpt(key) + "'");
    }
    if (schema.contains("required")) {
      for (const auto& key : schema.at("required"))
        if (!value.contains(key.get<std::string>()))
          fail(path, "missing required field '" + key.get<std::string>() + "'");
    }
    for (const auto& [key, sub] : props.items()) {
      if (value.contains(key))
        value[key] = check(sub, value.at(key), path + "." + key);
      else if (sub.contains("default"))
        value[key] = sub.at("default");
    }
  }

  const std::string& context_;
};

}  // namespace

json validate_params(const json& schema, const json& params, const std::string& context) {
  return Validator(context).check(schema, params.is_null() ? json::object() : params, "params");
}

json number_param(double min, double max, double def, const std::string& description) {
  return {{"type", "number"},
          {"minimum", min},
          {"maximum", max},
          {"default", def},
          {"description", description}};
}

json string_param(const std::string& def, const std::string& description) {
  return {{"type", "string"}, {"default", def}, {"description", description}};
}

namespace {

constexpr const char* kNamesKey = "names";
const char* const kNamedKinds[] = {"artifact", "layer", "output file"};  // by NamedKind

}  // namespace

json named_param(NamedKind kind, const std::optional<std::string>& def,
                 const std::string& description) {
  json p = {{"type", "string"}, {kNamesKey, kNamedKinds[int(kind)]}, {"description", description}};
  if (def) p["default"] = *def;
  return p;
}

std::optional<NamedKind> named_kind(const json& param_schema) {
  if (!param_schema.is_object() || !param_schema.contains(kNamesKey)) return std::nullopt;
  for (int k = 0; k < int(std::size(kNamedKinds)); ++k)
    if (param_schema.at(kNamesKey) == kNamedKinds[k]) return NamedKind(k);
  return std::nullopt;
}

json integer_param(int64_t min, int64_t max, int64_t def, const std::string& description) {
  return {{"type", "integer"},
          {"minimum", min},
          {"maximum", max},
          {"default", def},
          {"description", description}};
}

}  // namespace maquette
