// synthesis.assess (reduce): issue 18's measures (assess_metrics.h) of a synthesis.transfer's
// colours and source coordinates against its exemplar (the same params) and the target's land
// cover and altitude. Each cell tallies its pixels (coherence reads kCoherenceRadius pixels of
// halo), the tallies are summed, and the report is a JSON artifact and a table on stdout.
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "assess_metrics.h"
#include "core/error.h"
#include "exemplar_params_check.h"
#include "operators.h"
#include "runtime/input_halo.h"
#include "runtime/params_schema.h"
#include "transfer_exemplar.h"
#include "transfer_params.h"

namespace maquette::synthesis {
namespace {

constexpr const char* kOp = "synthesis.assess";

OperatorSpec assess_spec() {
  OperatorSpec s;
  s.name = kOp;
  s.description =
      "Measures a synthesis.transfer (issue 18): label consistency, sources in the exclusion "
      "mask, 5 x 5 patch coherence, distinct sources, most used source, per-label colour "
      "histogram distance, altitude mismatch";
  s.kind = OperatorKind::Reduce;
  InputSpec rgb{"rgb", "the transfer's colours", false};
  rgb.channels = {3};
  InputSpec source{"source",
                   "the transfer's painting pixel (column, row) per output pixel, and its painting "
                   "(0 when absent: one painting)",
                   false};
  source.channels = {2, 3};
  s.inputs = {rgb, source,
              single_channel_input("landcover", "the target land cover the transfer was given",
                                   Semantics::Categorical),
              single_channel_input("dem", "the transfer's altitude guide (with altitude_range)",
                                   Semantics::Continuous, true)};
  s.outputs = {{"report", "the measures (JSON)", DType::U8, 1, Semantics::Continuous, "", {}}};
  s.halo = kCoherenceRadius;
  s.params_schema = {{"type", "object"},
                     {"additionalProperties", false},
                     {"required", {"painting", "landcover_classes"}},
                     {"properties", exemplar_params_schema()}};
  s.params_schema["properties"].update(further_exemplars_schema());
  s.params_schema["properties"]["coherence_step"] =
      integer_param(1, 64, 1,
                    "coherence measured at output pixels whose global column and row are "
                    "multiples of it (a sample; 1: every pixel)");
  s.check_params = [](const json& params, const std::set<std::string>& mapped_inputs) {
    check_exemplar_params(params, kOp, mapped_inputs.count("dem") > 0);
  };
  return s;
}

json to_json(const Tally& t) {
  json uses = json::array(), histograms = json::object();
  for (const auto& [pixel, n] : t.uses) uses.push_back({pixel, n});
  for (const auto& [label, counts] : t.histograms) histograms[std::to_string(label)] = counts;
  json labelled_by = json::object();
  for (const auto& [label, n] : t.labelled_by) labelled_by[std::to_string(label)] = n;
  return {{"pixels", t.pixels},
          {"labelled", t.labelled},
          {"label_matches", t.label_matches},
          {"labelled_by", labelled_by},
          {"excluded", t.excluded},
          {"coherence_sum", t.coherence_sum},
          {"coherence_patches", t.coherence_patches},
          {"altitude_sum", t.altitude_sum},
          {"altitude_pixels", t.altitude_pixels},
          {"uses", uses},
          {"histograms", histograms}};
}

Tally from_json(const json& j) {
  Tally t;
  t.pixels = j.at("pixels");
  t.labelled = j.at("labelled");
  t.label_matches = j.at("label_matches");
  for (const auto& [label, n] : j.at("labelled_by").items())
    t.labelled_by[uint8_t(std::stoi(label))] = n.get<uint64_t>();
  t.excluded = j.at("excluded");
  t.coherence_sum = j.at("coherence_sum");
  t.coherence_patches = j.at("coherence_patches");
  t.altitude_sum = j.at("altitude_sum");
  t.altitude_pixels = j.at("altitude_pixels");
  for (const auto& u : j.at("uses")) t.uses[u.at(0).get<int32_t>()] = u.at(1).get<uint64_t>();
  for (const auto& [label, counts] : j.at("histograms").items())
    t.histograms[uint8_t(std::stoi(label))] = counts.get<std::vector<uint64_t>>();
  return t;
}

// A param's value as a message shows it: its JSON, cut to 60 characters; "absent" for none.
std::string shown(const json& value) {
  if (value.is_null()) return "absent";
  const std::string text = value.dump();
  return text.size() <= 60 ? text : text.substr(0, 57) + "...";
}

// The params in which `params` differ from those of the synthesis.transfer that made `source`
// (its layer's provenance), each as "field: the transfer's value, assess's value": the exemplar's
// (exemplar_key_params), the land-cover table as it reads the target and groups the painting's
// classes (class_table, class_groups: however spelled) and the altitude range. None when they
// agree, or when the layer was made otherwise or by params this version no longer reads.
std::vector<std::string> differing_params(const LayerInfo& source, const json& params) {
  const auto transfer = transfer_params_of(source);
  if (!transfer) return {};
  json made = exemplar_key_params(*transfer), ours = exemplar_key_params(params, kOp);
  made.erase("groups");  // the table's, compared below as the table is read
  ours.erase("groups");
  json keys = made;
  keys.update(ours);
  std::vector<std::string> fields;
  const auto differ = [&](const std::string& key, const json& theirs, const json& mine) {
    fields.push_back(key + ": the transfer's " + shown(theirs) + ", assess's " + shown(mine));
  };
  for (const auto& item : keys.items()) {
    const std::string& key = item.key();
    const json theirs = made.value(key, json()), mine = ours.value(key, json());
    if (theirs != mine) differ(key, theirs, mine);
  }
  const json their_table = transfer->value("landcover_classes", json()),
             my_table = params.value("landcover_classes", json());
  const auto read = [](const json& table) {
    return table.is_null() ? std::pair<std::map<int, uint8_t>, std::map<uint8_t, uint8_t>>{}
                           : std::pair{class_table(table, kOp), class_groups(table, kOp)};
  };
  if (read(their_table) != read(my_table)) differ("landcover_classes", their_table, my_table);
  const json their_range = transfer->value("altitude_range", json()),
             my_range = params.value("altitude_range", json());
  if (their_range != my_range) differ("altitude_range", their_range, my_range);
  return fields;
}

// Throws maquette::Error when `params` differ from the transfer's that made `source` where the
// measures depend on them: measured against another analysis (exemplar_scale 2 here, 4 there) the
// figures were another exemplar's, silently, or its sources fell outside it; read through another
// table, another target's.
void check_same_params(const LayerInfo& source, const json& params) {
  const auto fields = differing_params(source, params);
  if (fields.empty()) return;
  std::string list;
  for (const std::string& f : fields) list += (list.empty() ? "" : "; ") + f;
  throw Error(std::string(kOp) + ": its params differ from those synthesis.transfer made layer '" +
              source.name + "' with (" + list + "): give assess the transfer's params");
}

class Assess : public ReduceOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  json map(const CellContext& ctx, const CellData& data) const override {
    const json& params = *ctx.params;
    check_same_params(ctx.input_layer("source"), params);
    const auto table = class_table(params.at("landcover_classes"), kOp);
    const auto range = altitude_range(params, kOp, data.inputs.count("dem") > 0);
    const auto exemplar = transfer_exemplar(params, kOp);
    const Exemplar e = copied_exemplar(exemplar->pyramid.levels[0]);
    const Tile<float>& rgb = input_with_halo(kOp, ctx, data, "rgb", spec_.halo);
    const Tile<float>& source = input_with_halo(kOp, ctx, data, "source", spec_.halo);
    const Tile<float>& landcover = input_with_halo(kOp, ctx, data, "landcover", spec_.halo);
    const Tile<float>* dem = range ? &input_with_halo(kOp, ctx, data, "dem", spec_.halo) : nullptr;
    const int n = ctx.tile_size, h = spec_.halo, side = n + 2 * h;
    AssessedImage image;
    image.rect = {global_col(ctx.cell, n, -h), global_row(ctx.cell, n, -h), side, side};
    image.rgb.reserve(size_t(side) * size_t(side) * 3);
    for (int r = -h; r < n + h; ++r)
      for (int c = -h; c < n + h; ++c) {
        const float x = source.at(c, r, 0), y = source.at(c, r, 1);
        const float which = source.channels() > 2 ? source.at(c, r, 2) : 0.0f;
        int32_t s = -1;
        if (!std::isnan(x) && !std::isnan(y) && !std::isnan(which)) {
          // A painting index that is no whole number of the list is refused before int().
          const bool listed = which >= 0 && which < float(exemplar->parts.size()) &&
                              which == std::floor(which) && x >= 0 && y >= 0;
          s = listed ? exemplar->pixel_of(int(which), int(x), int(y)) : -1;
          if (s < 0) {
            std::ostringstream what;
            what << kOp << ": inputs.source of cell " << ctx.cell.ToText() << ": (" << x << ", "
                 << y << ") of painting " << which << " lies outside the paintings' exemplar "
                 << "pixels (" << exemplar->parts.size() << " paintings; the first "
                 << exemplar->parts[0].width * exemplar->scale << " x "
                 << exemplar->parts[0].height * exemplar->scale << ")";
            throw Error(what.str());
          }
        }
        image.source.push_back(s);
        // The 8-bit rgb layer's nodata is 0: where a source was written, a missing sample is
        // a channel of value 0, not a hole.
        for (int k = 0; k < 3; ++k) {
          const float v = rgb.at(c, r, k);
          image.rgb.push_back(std::isnan(v) && s >= 0 ? 0.0f : v);
        }
        image.labels.push_back(painting_class(table, landcover.at(c, r)));
        if (dem) image.altitude.push_back(altitude_guide(dem->at(c, r), *range));
      }
    const PixelRect counted{global_col(ctx.cell, n, 0), global_row(ctx.cell, n, 0), n, n};
    const Tally t = tally(e, image, counted, params.at("coherence_step").get<int>());
    if (t.pixels == 0 && t.histograms.empty() && t.coherence_patches == 0) return nullptr;
    return to_json(t);
  }

  json merge(const json& a, const json& b) const override {
    if (a.is_null()) return b;
    if (b.is_null()) return a;
    Tally t = from_json(a);
    t.merge(from_json(b));
    return to_json(t);
  }

  Artifact finish(const json& merged, const StepContext& ctx) const override {
    if (merged.is_null() || merged.at("pixels").get<uint64_t>() == 0)
      throw Error(std::string(kOp) +
                  ": no output pixel with a source in the region (inputs.source)");
    const Tally t = from_json(merged);
    const Exemplar e = copied_exemplar(transfer_exemplar(*ctx.params, kOp)->pyramid.levels[0]);
    const Metrics m = metrics(e, t);
    json distances = json::object();
    for (const auto& [label, d] : m.histogram_distance) distances[std::to_string(label)] = d;
    json report = {{"pixels", m.pixels},
                   {"label_consistency", m.label_consistency},
                   {"excluded_pixels", m.excluded_pixels},
                   {"coherence", m.coherence},
                   {"coherence_patches", t.coherence_patches},
                   {"distinct_source_fraction", m.distinct_source_fraction},
                   {"distinct_source_bound", m.distinct_source_bound},
                   {"distinct_source_label_bound", m.distinct_source_label_bound},
                   {"usable_exemplar_pixels", m.allowed_pixels},
                   {"max_source_share", m.max_source_share},
                   {"histogram_distance", distances},
                   {"worst_histogram_distance", m.worst_histogram_distance}};
    // Without an altitude guide there is no mismatch: a 0 would read as a perfect match.
    if (t.altitude_pixels > 0) report["altitude_mismatch"] = m.altitude_mismatch;
    std::ostringstream table;
    for (const auto& [key, value] : report.items())
      if (!value.is_object()) table << key << '\t' << value.dump() << '\n';
    for (const auto& [label, d] : distances.items())
      table << "histogram_distance[" << label << "]\t" << d.dump() << '\n';
    std::cout << table.str() << std::flush;
    return Artifact::FromText("report", report.dump(1),
                              {{"label_consistency", m.label_consistency},
                               {"coherence", m.coherence},
                               {"distinct_source_fraction", m.distinct_source_fraction}});
  }

 private:
  OperatorSpec spec_ = assess_spec();
};

}  // namespace

std::unique_ptr<Operator> make_assess() { return std::make_unique<Assess>(); }

}  // namespace maquette::synthesis
