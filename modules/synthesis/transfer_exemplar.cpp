#include "transfer_exemplar.h"

#include <spdlog/spdlog.h>
#include <tbb/collaborative_call_once.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "exemplar_cache.h"
#include "exemplar_usage.h"
#include "harmonize.h"
#include "light_guide.h"
#include "painting.h"
#include "painting_guides.h"
#include "synthesis.h"
#include "transfer_params.h"

namespace maquette::synthesis {
namespace {

// `read()`, its errors named by `field` (the params' field whose file it reads) too.
template <class Read>
auto reading(const std::string& field, Read&& read) {
  try {
    return read();
  } catch (const Error& e) {
    throw Error(field + ": " + e.what());
  }
}

// A guide of the painting, 0..1 per pixel: "rows" (a panorama's far, high ground is painted near
// its top: 1 on the top row, falling to 0 on the bottom one) or a grey image of its size; errors
// name `field`.
std::vector<float> painting_guide(const std::string& source, const Exemplar& e,
                                  const std::string& what, const std::string& field) {
  std::vector<float> guide(size_t(e.width) * size_t(e.height));
  if (source == "rows") {
    for (int y = 0; y < e.height; ++y)
      std::fill_n(guide.begin() + ptrdiff_t(y) * e.width, e.width,
                  1.0f - float(y) / float(std::max(1, e.height - 1)));
  } else {
    const auto grey =
        reading(field, [&] { return read_mask(source, e.width, e.height, what + " image"); });
    for (size_t i = 0; i < grey.size(); ++i) guide[i] = float(grey[i]) / 255.0f;
  }
  return guide;
}

// One painting with its classes, exclusions and guides from `fields` (the params or one of
// "exemplars"), named `where` in errors; its classes as they are (before any class table).
Exemplar read_exemplar(const nlohmann::json& fields, const std::string& where, int scale) {
  const std::string painting = fields.at("painting").get<std::string>();
  Exemplar e = read_painting(painting);
  // Each of the kLevels levels halves the shrunk painting: its coarsest must keep a pixel.
  const int least = scale << (kLevels - 1);
  if (e.width < least || e.height < least)
    throw Error(where + ".painting: " + painting + " is " + std::to_string(e.width) + " x " +
                std::to_string(e.height) + " pixels, too small for exemplar_scale " +
                std::to_string(scale) + ": " + std::to_string(kLevels) + " levels need at least " +
                std::to_string(least) + " pixels a side");
  // The masks made from the painting's guides (maquette-paint's painting_guides).
  GuidedMasks guided;
  if (fields.contains("painting_guides")) guided = guided_masks(fields, where, e.width, e.height);
  if (!guided.labels.empty()) {
    e.labels = std::move(guided.labels);
    for (size_t i = 0; i < e.labels.size(); ++i) e.excluded[i] |= e.labels[i] == kUnknownLabel;
  } else if (fields.contains("labels")) {
    const std::string labels = fields.at("labels").get<std::string>();
    e.labels =
        reading(where + ".labels", [&] { return read_class_image(labels, e.width, e.height); });
    for (const uint8_t l : e.labels)
      if (l == kUnknownLabel)
        throw Error(where + ".labels: " + labels + ": class " + std::to_string(l) +
                    " is reserved (unknown); classes are 0..254");
  } else {
    e.labels = segment_by_colour(e, fields.at("classes").get<int>());
  }
  if (fields.contains("exclusion")) {
    const auto mask = reading(where + ".exclusion", [&] {
      return read_mask(fields.at("exclusion").get<std::string>(), e.width, e.height,
                       "exclusion mask");
    });
    for (size_t i = 0; i < mask.size(); ++i) e.excluded[i] |= mask[i] != 0;
  }
  const auto excluded_classes = fields.at("exclude_classes").get<std::vector<int>>();
  for (const int c : excluded_classes)
    for (size_t i = 0; i < e.labels.size(); ++i) e.excluded[i] |= e.labels[i] == c;
  if (std::find(e.excluded.begin(), e.excluded.end(), 0) == e.excluded.end())
    throw Error(where + ": every pixel of " + painting +
                " is excluded (by its transparency, exclusion or exclude_classes " +
                nlohmann::json(excluded_classes).dump() + "): nothing is left to copy");
  if (!guided.altitude.empty())
    e.altitude = std::move(guided.altitude);
  else if (fields.contains("painting_altitude"))
    e.altitude = painting_guide(fields.at("painting_altitude").get<std::string>(), e, "altitude",
                                where + ".painting_altitude");
  if (!guided.distance.empty())
    e.distance = std::move(guided.distance);
  else if (fields.contains("painting_distance"))
    e.distance = painting_guide(fields.at("painting_distance").get<std::string>(), e, "distance",
                                where + ".painting_distance");
  return e;
}

// The further paintings of "exemplars", read, relabelled into the first's classes (those their
// tables do not name excluded) and shrunk; errors name `op` (transfer_exemplar).
std::vector<Exemplar> further_exemplars(const nlohmann::json& params, const std::string& op,
                                        int scale) {
  std::vector<Exemplar> out;
  if (!params.contains("exemplars")) return out;
  check_altitude_of_every_painting(params, op);
  const nlohmann::json& list = params.at("exemplars");
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string where = op + ".exemplars[" + std::to_string(i) + "]";
    const nlohmann::json& fields = list.at(i);
    Exemplar e = read_exemplar(fields, where, scale);
    const nlohmann::json& table = fields.at("landcover_classes");
    const auto labels = further_classes(params.at("landcover_classes"), table, op, where);
    const auto groups = class_groups(table, where);
    std::set<uint8_t> copied;  // the table's sets (by their smallest class) with pixels to copy
    for (size_t p = 0; p < e.labels.size(); ++p) {
      const auto it = labels.find(e.labels[p]);
      if (it == labels.end()) {
        e.excluded[p] = 1;
        continue;
      }
      if (!e.excluded[p]) copied.insert(groups.at(e.labels[p]));
      e.labels[p] = it->second;
    }
    // A class without pixels would leave this painting unused for its land cover, unsaid.
    for (const auto& [target, c] : class_table(table, where))
      if (!copied.count(c))
        throw Error(where + ".landcover_classes." + std::to_string(target) + ": painting class " +
                    std::to_string(c) + " has no pixel to copy in " +
                    fields.at("painting").get<std::string>() + " (not in it, or excluded)");
    out.push_back(shrink_exemplar(e, scale));
  }
  return out;
}

// The files the analysis reads for `fields` (the params or one of "exemplars", whose fields
// `prefix` names): the guides' keywords ("rows", "lightness", "guides" with painting_guides) are
// no files.
void add_inputs(const nlohmann::json& fields, const std::string& prefix,
                std::vector<InputFile>& files) {
  struct Field {
    std::string name;
    const char* what;
    const char* keyword;  // the value that names no file, or null
  };
  for (const auto& [field, what, keyword] :
       {Field{"painting", "the painting", nullptr},
        {"labels", "the class image", nullptr},
        {"exclusion", "the exclusion mask", nullptr},
        {"painting_altitude", "the painting's altitude image", "rows"},
        {"painting_distance", "the painting's distance image", "rows"},
        {"painting_light", "the painting's light image", "lightness"},
        {"painting_guides", "the painting's guides", nullptr}})
    if (fields.contains(field) && !(keyword && fields.at(field) == keyword) &&
        !from_guides(fields, field))
      files.push_back(
          {std::string(what) + " (" + prefix + field + ")", fields.at(field).get<std::string>()});
}

// The paintings of `params` by file, for messages: "painting P" or "paintings P, Q".
std::string painting_names(const nlohmann::json& params) {
  std::string names = params.at("painting").get<std::string>();
  if (params.contains("exemplars"))
    for (const auto& further : params.at("exemplars"))
      names += ", " + further.at("painting").get<std::string>();
  return (params.contains("exemplars") ? "paintings " : "painting ") + names;
}

// The analysis (cached by exemplar_cache.h under a key holding the build: a change here or in
// what it calls misses the older files); errors name `op` (transfer_exemplar).
std::shared_ptr<const TransferExemplar> build(const nlohmann::json& params, const std::string& op) {
  const int scale = params.at("exemplar_scale").get<int>();
  Exemplar e = read_exemplar(params, op, scale);
  // The class table's sets of classes taken as one (exclusions are by the painting's classes).
  if (params.contains("landcover_classes"))
    for (const auto& [from, to] : class_groups(params.at("landcover_classes"), op))
      std::replace(e.labels.begin(), e.labels.end(), from, to);
  // maquette-paint's light guide (one painting), after the table's sets: its quantiles are
  // within the classes the synthesis matches.
  if (params.contains("painting_light")) {
    const std::string light = params.at("painting_light").get<std::string>();
    e.light = painting_light(e, light == "lightness"
                                    ? painting_lightness(e)
                                    : painting_guide(light, e, "light", op + ".painting_light"));
  }
  std::vector<Exemplar> parts{shrink_exemplar(e, scale)};
  for (Exemplar& further : further_exemplars(params, op, scale))
    parts.push_back(std::move(further));
  if (params.contains("harmonize"))
    harmonize(parts,
              parse_harmonization(params.at("harmonize").get<std::string>(), op + ".harmonize"));
  auto out = std::make_shared<TransferExemplar>();
  out->scale = scale;
  Exemplar combined = combine_exemplars(std::move(parts), out->parts);
  // The synthesis packs an exemplar pixel's column and row as x | y << 16 in 32 bits.
  if (combined.width > 65535 || combined.height > 32767)
    throw Error(op + ": the exemplar is " + std::to_string(combined.width) + " x " +
                std::to_string(combined.height) +
                " pixels (the paintings side by side, after exemplar_scale): at most 65535 x "
                "32767; raise exemplar_scale or give fewer paintings");
  // Minutes for a large painting (6000 x 4000 at exemplar_scale 2: 306 s of CPU), said before.
  spdlog::info(
      "{}: analysing {}: {} x {} exemplar pixels at exemplar_scale {} (once per set of "
      "inputs; the exemplar cache keeps it)",
      op, painting_names(params), combined.width, combined.height, scale);
  const auto start = std::chrono::steady_clock::now();
  try {
    out->pyramid = analyse_exemplar(combined, kLevels, params.at("k").get<int>(), out->parts);
  } catch (const Error& e) {
    throw Error(op + ": " + painting_names(params) + ": " + e.what());
  }
  // Measured with the default weights: the same exemplar serves every step's weights.
  measure_usage(out->pyramid, SynthesisParams{});
  spdlog::info("{}: {} analysed in {:.1f} s", op, painting_names(params),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return out;
}

// Refuses a class the table gives a target value that has no pixel to copy (absent from the
// paintings, excluded, or lost to the exemplar's blocks): the synthesis would take any class's
// pixels there instead (synthesis.cpp, start_pool), without a word.
void check_table_classes(const TransferExemplar& t, const nlohmann::json& params,
                         const std::string& op) {
  for (const auto& [target, c] : class_table(params.at("landcover_classes"), op))
    check_class_has_pixels(t, c, op + ".landcover_classes." + std::to_string(target));
}

}  // namespace

void check_class_has_pixels(const TransferExemplar& t, int painting_class,
                            const std::string& field) {
  const ExemplarLevel& finest = t.pyramid.levels[0];
  if (painting_class >= 0 && painting_class < kUnknownLabel &&
      !finest.by_label[size_t(painting_class)].empty())
    return;
  std::string present;
  for (int l = 0; l < kUnknownLabel; ++l)
    if (!finest.by_label[size_t(l)].empty())
      present += (present.empty() ? "" : ", ") + std::to_string(l);
  throw Error(field + ": painting class " + std::to_string(painting_class) +
              " has no pixel to copy (not in the painting, or excluded); the classes that have: " +
              present);
}

SourcePixel TransferExemplar::source_of(int32_t s) const {
  const int width = pyramid.levels[0].width, x = s % width, y = s / width;
  int p = 0;
  while (p + 1 < int(parts.size()) && x >= parts[size_t(p) + 1].x0) ++p;
  return {p, (x - parts[size_t(p)].x0) * scale, y * scale};
}

int32_t TransferExemplar::pixel_of(int exemplar, int col, int row) const {
  if (exemplar < 0 || exemplar >= int(parts.size()) || col < 0 || row < 0) return -1;
  const Placement& at = parts[size_t(exemplar)];
  const int x = col / scale, y = row / scale;
  if (x >= at.width || y >= at.height) return -1;
  return pyramid.levels[0].index(at.x0 + x, y);
}

void check_altitude_of_every_painting(const nlohmann::json& params, const std::string& op) {
  if (!params.contains("exemplars")) return;
  const nlohmann::json& list = params.at("exemplars");
  for (size_t i = 0; i < list.size(); ++i)
    if (list.at(i).contains("painting_altitude") != params.contains("painting_altitude"))
      throw Error(op + ".exemplars[" + std::to_string(i) + "].painting_altitude: " +
                  (params.contains("painting_altitude")
                       ? "missing, but the first painting has one"
                       : "given, but the first painting has none") +
                  ": give every painting an altitude or none");
}

nlohmann::json exemplar_key_params(const nlohmann::json& params, const std::string& op) {
  nlohmann::json key = nlohmann::json::object();
  for (const char* field : {"painting", "labels", "classes", "exclusion", "exclude_classes",
                            "painting_altitude", "painting_distance", "painting_light",
                            "painting_guides", "exemplar_scale", "k", "exemplars", "harmonize"})
    if (params.contains(field)) key[field] = params.at(field);
  if (const nlohmann::json guided = guided_masks_key(params); !guided.empty())
    key["guided"] = guided;
  // The first painting's labels depend on the table's groups only; a further painting's on the
  // table itself (each of its classes takes the first's class for the same target value).
  if (params.contains("landcover_classes"))
    key["groups"] = params.contains("exemplars")
                        ? params.at("landcover_classes")
                        : nlohmann::json(class_groups(params.at("landcover_classes"), op));
  return key;
}

std::vector<InputFile> exemplar_inputs(const nlohmann::json& params) {
  std::vector<InputFile> files;
  add_inputs(params, "", files);
  if (params.contains("exemplars"))
    for (size_t i = 0; i < params.at("exemplars").size(); ++i)
      add_inputs(params.at("exemplars").at(i), "exemplars[" + std::to_string(i) + "].", files);
  return files;
}

std::vector<std::string> exemplar_input_files(const nlohmann::json& params) {
  std::vector<std::string> files;
  for (const InputFile& input : exemplar_inputs(params)) files.push_back(input.path);
  return files;
}

std::shared_ptr<const TransferExemplar> transfer_exemplar(const nlohmann::json& params,
                                                          const std::string& op) {
  const nlohmann::json key = exemplar_key_params(params, op);
  struct Slot {
    tbb::collaborative_once_flag once;
    std::shared_ptr<const TransferExemplar> exemplar;
  };
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<Slot>> cache;
  Slot* slot = nullptr;
  {
    const std::lock_guard lock(mutex);
    auto& entry = cache[key.dump()];
    if (!entry) entry = std::make_unique<Slot>();
    slot = entry.get();
  }
  // One analysis per exemplar and process, read from the persistent cache (exemplar_cache.h) when
  // it holds it: the cells that need it meanwhile work on it (its parallel k nearest search)
  // instead of waiting; a failed one is tried again by the next cell.
  tbb::collaborative_call_once(slot->once, [&] {
    const auto directory = exemplar_cache_dir();
    const auto disk_key =
        directory ? exemplar_cache_key(key, exemplar_input_files(params)) : std::nullopt;
    const auto analyse = [&] { return build(params, op); };
    slot->exemplar = disk_key ? cached_exemplar(*directory, *disk_key, analyse) : analyse();
  });
  // Not in the analysis: the table's classes are not all in the key (exemplar_key_params).
  if (params.contains("landcover_classes")) check_table_classes(*slot->exemplar, params, op);
  return slot->exemplar;
}

}  // namespace maquette::synthesis
