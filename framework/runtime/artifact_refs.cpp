#include "runtime/artifact_refs.h"

#include "core/error.h"
#include "core/json_file.h"

namespace maquette {
namespace {

using json = nlohmann::json;

// Calls fn(path, value) for every artifact reference in `value`, depth first; fn returns the
// value to put in its place.
template <typename Fn>
json map_refs(const json& value, const std::string& path, Fn&& fn) {
  if (is_artifact_ref(value)) return fn(path, value);
  json out = value;
  if (value.is_object())
    for (auto& [key, sub] : out.items()) sub = map_refs(sub, path + "." + key, fn);
  if (value.is_array())
    for (size_t i = 0; i < out.size(); ++i)
      out[i] = map_refs(out[i], path + "[" + std::to_string(i) + "]", fn);
  return out;
}

}  // namespace

bool is_artifact_ref(const json& value) {
  if (!value.is_object() || !value.contains("$artifact") || !value.at("$artifact").is_string() ||
      value.at("$artifact").get<std::string>().empty())
    return false;
  const bool pointer = value.contains("pointer");
  return value.size() == (pointer ? 2u : 1u) && (!pointer || value.at("pointer").is_string());
}

std::vector<std::pair<std::string, std::string>> artifact_refs(const json& params) {
  std::vector<std::pair<std::string, std::string>> refs;
  map_refs(params, "params", [&](const std::string& path, const json& ref) {
    refs.emplace_back(path, ref.at("$artifact").get<std::string>());
    return ref;
  });
  return refs;
}

json paste_artifacts(const json& params, const Store& store, const std::string& context) {
  return map_refs(params, "params", [&](const std::string& path, const json& ref) {
    const std::string name = ref.at("$artifact").get<std::string>();
    const std::optional<Artifact> artifact = store.get_artifact(name);
    if (!artifact) throw Error(context + ": " + path + ": no artifact '" + name + "' in the store");
    const std::string_view text = artifact->text();
    const json doc = parse_json(
        text, context + ": " + path + ": artifact '" + name + "' (" + artifact->media_type + ")");
    if (!ref.contains("pointer")) return doc;
    const std::string pointer = ref.at("pointer");
    try {
      return doc.at(json::json_pointer(pointer));
    } catch (const json::exception& e) {
      throw Error(context + ": " + path + ".pointer: \"" + pointer + "\" in artifact '" + name +
                  "': " + e.what());
    }
  });
}

}  // namespace maquette
