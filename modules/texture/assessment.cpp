#include "assessment.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <vector>

#include "colour.h"

namespace maquette::texture {

namespace {

// Mean RGB and spread (root mean of the channels' variances) of moments [n, sums, squares].
std::pair<std::array<double, 3>, double> mean_and_sd(const nlohmann::json& m) {
  const double n = m[0].get<double>();
  std::array<double, 3> mean{};
  double var = 0;
  for (size_t k = 0; k < 3; ++k) {
    mean[k] = m[1 + k].get<double>() / n;
    var += std::max(0.0, m[4 + k].get<double>() / n - mean[k] * mean[k]) / 3;
  }
  return {mean, std::sqrt(var)};
}

// Per class with pixels in both: the mean colours, their CIEDE2000, the spreads and their ratio.
nlohmann::json class_colours(const nlohmann::json& moments) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [k, sets] : moments.items()) {
    if (!sets.contains("image") || !sets.contains("texture")) continue;
    const auto [im, isd] = mean_and_sd(sets["image"]);
    const auto [tm, tsd] = mean_and_sd(sets["texture"]);
    out[k] = {{"image_mean", im},
              {"texture_mean", tm},
              {"ciede2000",
               ciede2000(srgb_to_lab(im[0], im[1], im[2]), srgb_to_lab(tm[0], tm[1], tm[2]))},
              {"image_sd", isd},
              {"texture_sd", tsd},
              {"sd_ratio", isd > 0 ? nlohmann::json(tsd / isd) : nlohmann::json()}};
    // The same against the class's lit pixels only (texture.assess's colour_min_incidence_cos).
    if (sets.contains("image_lit")) {
      const auto [lm, lsd] = mean_and_sd(sets["image_lit"]);
      out[k]["image_lit_mean"] = lm;
      out[k]["ciede2000_lit"] =
          ciede2000(srgb_to_lab(lm[0], lm[1], lm[2]), srgb_to_lab(tm[0], tm[1], tm[2]));
      out[k]["image_lit_sd"] = lsd;
      out[k]["sd_ratio_lit"] = lsd > 0 ? nlohmann::json(tsd / lsd) : nlohmann::json();
    }
    // The same after the blur (sigma 4 px): the spread at scales of 4 pixels and more, which
    // single-pixel speckle does not reach.
    if (sets.contains("image_blurred") && sets.contains("texture_blurred")) {
      const double ib = mean_and_sd(sets["image_blurred"]).second,
                   tb = mean_and_sd(sets["texture_blurred"]).second;
      out[k]["sd_ratio_blurred"] = ib > 0 ? nlohmann::json(tb / ib) : nlohmann::json();
    }
  }
  return out;
}

// Agreement of a confusion count {"obs,pred": n}: classes, matrix, accuracy, kappa, proportions
// and producer's accuracies.
nlohmann::json agreement(const nlohmann::json& confusion) {
  std::map<std::pair<int, int>, double> count;
  std::set<int> ids;
  double total = 0;
  for (const auto& [key, n] : confusion.items()) {
    const size_t comma = key.find(',');
    const int o = std::stoi(key.substr(0, comma)), p = std::stoi(key.substr(comma + 1));
    count[{o, p}] += n.get<double>();
    ids.insert(o);
    if (p >= 0) ids.insert(p);
    total += n.get<double>();
  }
  const std::vector<int> classes(ids.begin(), ids.end());
  std::map<int, double> row, col;
  double agree = 0;
  nlohmann::json matrix = nlohmann::json::array();
  for (const int o : classes) {
    nlohmann::json line = nlohmann::json::array();
    for (const int p : classes) {
      const double n = count.count({o, p}) ? count.at({o, p}) : 0;
      line.push_back(uint64_t(n));
      row[o] += n, col[p] += n;
      if (o == p) agree += n;
    }
    const double none = count.count({o, -1}) ? count.at({o, -1}) : 0;
    line.push_back(uint64_t(none));
    row[o] += none;
    matrix.push_back(line);
  }
  double expected = 0;
  nlohmann::json proportions = nlohmann::json::object(), producers = nlohmann::json::object();
  for (const int k : classes) {
    expected += row[k] * col[k] / (total * total);
    proportions[std::to_string(k)] = {{"observed", row[k] / total}, {"predicted", col[k] / total}};
    if (row[k] > 0)  // the share of the class's observed pixels predicted as the class
      producers[std::to_string(k)] = (count.count({k, k}) ? count.at({k, k}) : 0) / row[k];
  }
  const double accuracy = agree / total;
  const double kappa = expected < 1 ? (accuracy - expected) / (1 - expected) : 1.0;
  return {{"classes", classes},
          {"confusion", matrix},
          {"pixels", uint64_t(total)},
          {"accuracy", accuracy},
          {"kappa", kappa},
          {"proportions", proportions},
          {"producers_accuracy", producers}};
}

}  // namespace

nlohmann::json assessment(const nlohmann::json& merged) {
  nlohmann::json report = agreement(merged.at("confusion"));
  if (merged.contains("confusion_unfiltered")) {
    const nlohmann::json raw = agreement(merged.at("confusion_unfiltered"));
    report["unfiltered"] = {{"confusion", raw["confusion"]},
                            {"accuracy", raw["accuracy"]},
                            {"kappa", raw["kappa"]},
                            {"producers_accuracy", raw["producers_accuracy"]}};
  }
  const double de_n = merged.at("de_n").get<double>();
  report["class_colours"] = class_colours(merged.value("moments", nlohmann::json::object()));
  report["ciede2000_mean"] =
      de_n > 0 ? nlohmann::json(merged.at("de_sum").get<double>() / de_n) : nlohmann::json();
  return report;
}

std::string assessment_table(const nlohmann::json& r) {
  std::string s = "texture.assess: observed (rows) x predicted (columns)\n  class";
  char buf[64];
  for (const int k : r.at("classes")) std::snprintf(buf, sizeof buf, " %9d", k), s += buf;
  s += "      none   observed%  predicted%  producer's\n";
  const auto& classes = r.at("classes");
  for (size_t i = 0; i < classes.size(); ++i) {
    std::snprintf(buf, sizeof buf, "  %5d", classes[i].get<int>());
    s += buf;
    for (const auto& n : r.at("confusion")[i])
      std::snprintf(buf, sizeof buf, " %9llu", (unsigned long long)n.get<uint64_t>()), s += buf;
    const auto& p = r.at("proportions")[std::to_string(classes[i].get<int>())];
    const std::string id = std::to_string(classes[i].get<int>());
    std::snprintf(buf, sizeof buf, "   %8.2f  %10.2f  %10.3f\n", 100 * p["observed"].get<double>(),
                  100 * p["predicted"].get<double>(),
                  r["producers_accuracy"].value(id, nlohmann::json(0.0)).get<double>());
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "  accuracy %.4f  kappa %.4f", r["accuracy"].get<double>(),
                r["kappa"].get<double>());
  s += buf;
  if (!r["ciede2000_mean"].is_null())
    std::snprintf(buf, sizeof buf, "  CIEDE2000 (blurred) %.2f", r["ciede2000_mean"].get<double>()),
        s += buf;
  s += "\n";
  if (r.contains("unfiltered")) {
    const auto& u = r["unfiltered"];
    std::snprintf(buf, sizeof buf, "  unfiltered (as rendered): accuracy %.4f  kappa %.4f",
                  u["accuracy"].get<double>(), u["kappa"].get<double>());
    s += buf;
    s += "  producer's";
    for (const auto& [k, a] : u["producers_accuracy"].items())
      std::snprintf(buf, sizeof buf, " %s %.3f", k.c_str(), a.get<double>()), s += buf;
    s += "\n";
  }
  if (r["class_colours"].empty()) return s;
  s += "  class  image RGB        texture RGB      CIEDE2000  image sd  texture sd  ratio  "
       "blurred\n";
  for (const auto& [k, c] : r["class_colours"].items()) {
    const auto& a = c["image_mean"];
    const auto& b = c["texture_mean"];
    std::snprintf(buf, sizeof buf, "  %5s  %4.0f %4.0f %4.0f   %4.0f %4.0f %4.0f", k.c_str(),
                  a[0].get<double>(), a[1].get<double>(), a[2].get<double>(), b[0].get<double>(),
                  b[1].get<double>(), b[2].get<double>());
    s += buf;
    // (&c = c: clang 14, the fuzz build's compiler, cannot capture a structured binding)
    const auto ratio = [&c = c](const char* key) {
      return c.contains(key) && !c[key].is_null() ? c[key].get<double>() : 0.0;
    };
    std::snprintf(buf, sizeof buf, "   %9.2f  %8.1f  %10.1f  %5.2f  %7.2f\n",
                  c["ciede2000"].get<double>(), c["image_sd"].get<double>(),
                  c["texture_sd"].get<double>(), ratio("sd_ratio"), ratio("sd_ratio_blurred"));
    s += buf;
    if (c.contains("image_lit_mean")) {
      const auto& l = c["image_lit_mean"];
      std::snprintf(buf, sizeof buf, "    lit  %4.0f %4.0f %4.0f   %14s", l[0].get<double>(),
                    l[1].get<double>(), l[2].get<double>(), "");
      s += buf;
      std::snprintf(buf, sizeof buf, "   %9.2f  %8.1f  %10s  %5.2f\n",
                    c["ciede2000_lit"].get<double>(), c["image_lit_sd"].get<double>(), "",
                    ratio("sd_ratio_lit"));
      s += buf;
    }
  }
  return s;
}

}  // namespace maquette::texture
