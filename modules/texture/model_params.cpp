#include "model_params.h"

#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "core/error.h"

namespace maquette::texture {
namespace {

json read_model_file(const std::string& path, const std::string& context) {
  std::ifstream in(path);
  if (!in) throw Error(context + ".model_file: cannot open '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  try {
    return json::parse(text.str());
  } catch (const json::parse_error& e) {
    throw Error(context + ".model_file: '" + path + "' is not JSON: " + e.what());
  }
}

void require_one_model(const json& params, const std::string& context) {
  if (params.contains("model") == params.contains("model_file"))
    throw Error(context + ": give exactly one of \"model\" and \"model_file\"");
}

}  // namespace

void check_model_params(const json& params, const std::string& op_name) {
  const std::string context = op_name + ": params";
  require_one_model(params, context);
  if (params.contains("model")) parse_model(params.at("model"), context);
}

std::shared_ptr<const Model> model_from_params(const json& params, const std::string& op_name) {
  const std::string context = op_name + ": params";
  require_one_model(params, context);
  const json doc = params.contains("model")
                       ? params.at("model")
                       : read_model_file(params.at("model_file").get<std::string>(), context);
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const Model>> cache;
  std::string key = doc.dump();
  {
    const std::lock_guard lock(mutex);
    if (const auto it = cache.find(key); it != cache.end()) return it->second;
  }
  auto model = std::make_shared<const Model>(parse_model(doc, context));
  const std::lock_guard lock(mutex);
  if (cache.size() > 16) cache.clear();  // bounded: a process runs few pipelines
  return cache.emplace(std::move(key), model).first->second;
}

}  // namespace maquette::texture
