#include "example_pipeline.h"

#include <fstream>
#include <stdexcept>

namespace maquette::test {

using nlohmann::json;

json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  return json::parse(in);
}

json example_pipeline(const std::string& name) {
  const std::string shared = "../../shared";
  json p = read_json(kExamples + "/" + name + ".json");
  for (json& step : p["steps"])
    if (step["op"] == "ingest")
      for (json& source : step["params"]["sources"]) {
        const std::string path = source.get<std::string>();
        source = path.starts_with(shared) ? kShared + path.substr(shared.size())
                                          : kExamples + "/" + path;
      }
  return p;
}

}  // namespace maquette::test
