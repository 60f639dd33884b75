#include "model.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/error.h"

namespace maquette::texture {
namespace {

constexpr const char* kFormat = "maquette.texture.model";

[[noreturn]] void fail(const std::string& context, const std::string& path,
                       const std::string& what) {
  throw Error(context + ": " + path + ": " + what);
}

double number(const json& j, const std::string& context, const std::string& path) {
  if (!j.is_number()) fail(context, path, "expected a number, got " + j.dump());
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(context, path, "expected a finite number, got " + j.dump());
  return v;
}

double field(const json& obj, const char* key, double fallback, const std::string& context,
             const std::string& path) {
  return obj.contains(key) ? number(obj.at(key), context, path + "." + key) : fallback;
}

Table parse_table(const json& j, const Quantity& q, const std::string& context,
                  const std::string& path) {
  if (!j.is_object() || j.size() != 1 || !(j.contains("table") || j.contains("hat")))
    fail(context, path,
         "expected {\"table\": [256 numbers]} or {\"hat\": [a, b, c, d]}, got " +
             j.dump().substr(0, 80));
  if (j.contains("hat")) {
    const json& h = j.at("hat");
    if (!h.is_array() || h.size() != 4) fail(context, path + ".hat", "expected 4 numbers");
    std::array<double, 4> abcd{};
    for (int i = 0; i < 4; ++i)
      abcd[i] = number(h[i], context, path + ".hat[" + std::to_string(i) + "]");
    if (!std::is_sorted(abcd.begin(), abcd.end()))
      fail(context, path + ".hat", "expected a <= b <= c <= d, got " + h.dump());
    return hat_table(abcd, q.lo, q.hi);
  }
  const json& t = j.at("table");
  if (!t.is_array() || t.size() != kBins)
    fail(context, path + ".table",
         "expected " + std::to_string(kBins) + " numbers, got " +
             (t.is_array() ? std::to_string(t.size()) : t.dump().substr(0, 40)));
  Table table{};
  for (int i = 0; i < kBins; ++i) {
    const double v = number(t[i], context, path + ".table[" + std::to_string(i) + "]");
    if (v < 0 || v > 1)
      fail(context, path + ".table[" + std::to_string(i) + "]",
           "expected a value in [0, 1], got " + t[i].dump());
    table[i] = float(v);
  }
  return table;
}

std::array<float, 3> parse_colour(const json& j, const std::string& context,
                                  const std::string& path) {
  if (!j.is_array() || j.size() != 3) fail(context, path, "expected [r, g, b], got " + j.dump());
  std::array<float, 3> c{};
  for (int k = 0; k < 3; ++k) {
    c[k] = float(number(j[k], context, path));
    if (c[k] < 0 || c[k] > 255)
      fail(context, path, "components must be in 0..255, got " + j.dump());
  }
  return c;
}

class Parser {
 public:
  Parser(Model& m, std::string context) : m_(m), context_(std::move(context)) {}

  void layer(const json& j, int parent, const std::string& path) {
    if (!j.is_object()) fail(context_, path, "expected a layer object");
    static const std::vector<std::string> known = {"name",  "class",       "colour",
                                                   "bias",  "noise_scale", "roughness_m",
                                                   "noise", "constraints", "children"};
    for (const auto& [key, _] : j.items())
      if (std::find(known.begin(), known.end(), key) == known.end())
        fail(context_, path, "unknown field '" + key + "'");
    Layer l;
    l.parent = parent;
    l.name = j.value("name", "layer" + std::to_string(m_.layers.size()));
    if (j.contains("class")) {
      const json& c = j.at("class");
      if (!c.is_number_integer() || c.get<int64_t>() < 0 || c.get<int64_t>() > 254)
        fail(context_, path + ".class", "expected an integer in 0..254, got " + c.dump());
      l.class_id = c.get<int>();
    }
    if (!j.contains("colour")) fail(context_, path + ".colour", "missing");
    l.colour = parse_colour(j.at("colour"), context_, path + ".colour");
    l.bias = float(field(j, "bias", 1, context_, path));
    l.noise_scale = float(field(j, "noise_scale", 0, context_, path));
    l.roughness_m = float(field(j, "roughness_m", 0, context_, path));
    if (j.contains("noise")) noise(j.at("noise"), l.noise, path + ".noise");
    l.constraints.resize(m_.quantities.size());
    if (j.contains("constraints")) {
      const json& cs = j.at("constraints");
      if (!cs.is_object()) fail(context_, path + ".constraints", "expected an object");
      if (parent < 0 && !cs.empty())
        fail(context_, path + ".constraints", "the root layer has no constraints (paper 4.2)");
      for (const auto& [name, c] : cs.items()) {
        const int q = m_.quantity(name);
        if (q < 0)
          fail(context_, path + ".constraints." + name,
               "not a quantity of the model (declare it in \"quantities\")");
        l.constraints[size_t(q)] =
            parse_table(c, m_.quantities[size_t(q)], context_, path + ".constraints." + name);
      }
    }
    const int self = int(m_.layers.size());
    m_.layers.push_back(std::move(l));
    if (!j.contains("children")) return;
    const json& ch = j.at("children");
    if (!ch.is_array()) fail(context_, path + ".children", "expected an array");
    for (size_t i = 0; i < ch.size(); ++i)
      layer(ch[i], self, path + ".children[" + std::to_string(i) + "]");
  }

 private:
  void noise(const json& j, NoiseParams& n, const std::string& path) {
    if (!j.is_object()) fail(context_, path, "expected an object");
    if (j.contains("seed")) {
      if (!j.at("seed").is_number_integer()) fail(context_, path + ".seed", "expected an integer");
      n.seed = j.at("seed").get<uint64_t>();
    }
    n.octaves = int(field(j, "octaves", n.octaves, context_, path));
    if (n.octaves < 1 || n.octaves > 12)
      fail(context_, path + ".octaves", "expected 1..12, got " + std::to_string(n.octaves));
    n.wavelength_m = field(j, "wavelength_m", n.wavelength_m, context_, path);
    if (!(n.wavelength_m > 0))
      fail(context_, path + ".wavelength_m", "expected > 0, got " + j.at("wavelength_m").dump());
    n.persistence = field(j, "persistence", n.persistence, context_, path);
  }

  Model& m_;
  std::string context_;
};

}  // namespace

bool is_categorical(const std::string& quantity) { return quantity == kCategoricalQuantity; }

int Model::quantity(const std::string& name) const {
  for (size_t i = 0; i < quantities.size(); ++i)
    if (quantities[i].name == name) return int(i);
  return -1;
}

Table hat_table(const std::array<double, 4>& abcd, double lo, double hi) {
  const auto [a, b, c, d] = abcd;
  Table t{};
  for (int i = 0; i < kBins; ++i) {
    const double x = lo + (hi - lo) * (i + 0.5) / kBins;
    // The clamped minimum of a rising and a falling line (a vertical edge when a == b).
    const double up = b > a ? (x - a) / (b - a) : (x >= a ? 1.0 : 0.0);
    const double down = d > c ? (d - x) / (d - c) : (x < d ? 1.0 : 0.0);
    t[size_t(i)] = float(std::clamp(std::min(up, down), 0.0, 1.0));
  }
  return t;
}

Model parse_model(const json& doc, const std::string& context) {
  const std::string m = "model";
  if (!doc.is_object()) fail(context, m, "expected a JSON object");
  if (doc.value("format", "") != kFormat)
    fail(context, m + ".format",
         "expected \"" + std::string(kFormat) + "\", got " +
             (doc.contains("format") ? doc.at("format").dump() : "nothing"));
  if (!doc.contains("version") || doc.at("version") != kModelVersion)
    fail(context, m + ".version",
         "unsupported version " + (doc.contains("version") ? doc.at("version").dump() : "(none)") +
             " (this build reads version " + std::to_string(kModelVersion) + ")");
  Model model;
  const json& qs = doc.value("quantities", json::array());
  if (!qs.is_array()) fail(context, m + ".quantities", "expected an array");
  for (size_t i = 0; i < qs.size(); ++i) {
    const std::string p = m + ".quantities[" + std::to_string(i) + "]";
    const json& q = qs[i];
    if (!q.is_object() || !q.contains("name") || !q.at("name").is_string())
      fail(context, p, "expected {\"name\": ..., \"range\": [lo, hi]}");
    if (!q.contains("range") || !q.at("range").is_array() || q.at("range").size() != 2)
      fail(context, p + ".range", "expected [lo, hi]");
    Quantity quantity{q.at("name").get<std::string>(), number(q["range"][0], context, p + ".range"),
                      number(q["range"][1], context, p + ".range")};
    if (!(quantity.hi > quantity.lo))
      fail(context, p + ".range", "expected lo < hi, got " + q.at("range").dump());
    if (is_categorical(quantity.name) &&
        (quantity.lo != kCategoricalLo || quantity.hi != kCategoricalHi))
      fail(context, p + ".range",
           "the categorical quantity '" + quantity.name +
               "' has the range [-0.5, 255.5] (a bin per code), got " + q.at("range").dump());
    if (model.quantity(quantity.name) >= 0)
      fail(context, p + ".name", "quantity '" + quantity.name + "' declared twice");
    model.quantities.push_back(quantity);
  }
  if (!doc.contains("root")) fail(context, m + ".root", "missing (the root layer)");
  Parser(model, context).layer(doc.at("root"), -1, m + ".root");
  if (model.layers.size() > 255)
    fail(context, m + ".root",
         "more than 255 layers (" + std::to_string(model.layers.size()) + ")");
  return model;
}

json model_to_json(const Model& model) {
  json qs = json::array();
  for (const Quantity& q : model.quantities)
    qs.push_back({{"name", q.name}, {"range", {q.lo, q.hi}}});
  std::function<json(int)> layer = [&](int i) {
    const Layer& l = model.layers[size_t(i)];
    json j = {{"name", l.name},
              {"colour", l.colour},
              {"bias", l.bias},
              {"noise_scale", l.noise_scale},
              {"roughness_m", l.roughness_m},
              {"noise",
               {{"seed", l.noise.seed},
                {"octaves", l.noise.octaves},
                {"wavelength_m", l.noise.wavelength_m},
                {"persistence", l.noise.persistence}}}};
    if (l.class_id >= 0) j["class"] = l.class_id;
    json cs = json::object();
    for (size_t q = 0; q < l.constraints.size(); ++q)
      if (l.constraints[q]) cs[model.quantities[q].name] = {{"table", *l.constraints[q]}};
    if (!cs.empty()) j["constraints"] = cs;
    json children = json::array();
    for (size_t c = 0; c < model.layers.size(); ++c)
      if (model.layers[c].parent == i) children.push_back(layer(int(c)));
    if (!children.empty()) j["children"] = children;
    return j;
  };
  return {{"format", kFormat}, {"version", kModelVersion}, {"quantities", qs}, {"root", layer(0)}};
}

int layer_class(const Model& model, int layer) {
  for (int i = layer; i >= 0; i = model.layers[size_t(i)].parent)
    if (model.layers[size_t(i)].class_id >= 0) return model.layers[size_t(i)].class_id;
  return -1;
}

}  // namespace maquette::texture
