#include "assessment.h"

#include <cstdio>
#include <map>
#include <set>
#include <vector>

namespace maquette::texture {

nlohmann::json assessment(const nlohmann::json& merged) {
  std::map<std::pair<int, int>, double> count;
  std::set<int> ids;
  double total = 0;
  for (const auto& [key, n] : merged.at("confusion").items()) {
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
  nlohmann::json proportions = nlohmann::json::object();
  for (const int k : classes) {
    expected += row[k] * col[k] / (total * total);
    proportions[std::to_string(k)] = {{"observed", row[k] / total}, {"predicted", col[k] / total}};
  }
  const double accuracy = agree / total;
  const double kappa = expected < 1 ? (accuracy - expected) / (1 - expected) : 1.0;
  const double de_n = merged.at("de_n").get<double>();
  return {{"classes", classes},
          {"confusion", matrix},
          {"pixels", uint64_t(total)},
          {"accuracy", accuracy},
          {"kappa", kappa},
          {"proportions", proportions},
          {"ciede2000_mean",
           de_n > 0 ? nlohmann::json(merged.at("de_sum").get<double>() / de_n) : nlohmann::json()}};
}

std::string assessment_table(const nlohmann::json& r) {
  std::string s = "texture.assess: observed (rows) x predicted (columns)\n  class";
  char buf[64];
  for (const int k : r.at("classes")) std::snprintf(buf, sizeof buf, " %9d", k), s += buf;
  s += "      none   observed%  predicted%\n";
  const auto& classes = r.at("classes");
  for (size_t i = 0; i < classes.size(); ++i) {
    std::snprintf(buf, sizeof buf, "  %5d", classes[i].get<int>());
    s += buf;
    for (const auto& n : r.at("confusion")[i])
      std::snprintf(buf, sizeof buf, " %9llu", (unsigned long long)n.get<uint64_t>()), s += buf;
    const auto& p = r.at("proportions")[std::to_string(classes[i].get<int>())];
    std::snprintf(buf, sizeof buf, "   %8.2f  %10.2f\n", 100 * p["observed"].get<double>(),
                  100 * p["predicted"].get<double>());
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "  accuracy %.4f  kappa %.4f", r["accuracy"].get<double>(),
                r["kappa"].get<double>());
  s += buf;
  if (!r["ciede2000_mean"].is_null())
    std::snprintf(buf, sizeof buf, "  CIEDE2000 (blurred) %.2f", r["ciede2000_mean"].get<double>()),
        s += buf;
  return s + "\n";
}

}  // namespace maquette::texture
