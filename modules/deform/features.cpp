// deform.features (region): the DEM deformed to feature strokes (paper 002 §3.2, base level).
//
// A region operator, not a cell operator: a feature's least squares couples every vertex of its
// field of influence, whose width comes from the stroke (its cross_section), so no halo fixed in
// the operator's spec can cover it. The system is defined in global face pixels (unknowns sorted
// by sample, positions from the grid, the tangent plane at the first stroke's first point), so a
// sample's result depends on the strokes and the DEM, not on the tiling of the region; it runs
// once on one rank, so not on threads or ranks either.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "core/error.h"
#include "deform_levels.h"
#include "deform_solve.h"
#include "height_field.h"
#include "mosaic_frame.h"
#include "operators.h"
#include "sample_positions.h"
#include "stroke.h"
#include "stroke_constraints.h"

namespace maquette::deform {
namespace {

// The samples of the neighbouring tiles around the region's mosaic (OperatorSpec::halo): read
// only for the finer samples between the region's outermost sample centres and its edge, so
// that they do not depend on where the region ends; strokes must lie in the region.
constexpr int kHalo = 1;

// The finest "refine": three levels of Loop subdivision, as the three-level edit (each
// level has about 4 times the unknowns of the one before).
constexpr int kMaxLevels = 3;

OperatorSpec features_spec() {
  OperatorSpec s;
  s.name = "deform.features";
  s.description =
      "Deforms the DEM to feature strokes (control curve, elevation, cross section: rivers, "
      "roads, cliffs, ridges) by the weighted least squares of paper 002 §3.2 on its triangulated "
      "height field; heights outside the fields of influence are unchanged";
  s.kind = OperatorKind::Region;
  // "refine": k, the deformed surface k levels of Loop subdivision finer (deform_levels.h).
  s.refinable = true;
  s.max_refine = kMaxLevels;  // more is refused when the pipeline is read
  s.spans_faces = true;       // MosaicFrame places samples across face seams
  s.halo = kHalo;
  s.inputs = {
      single_channel_input("dem", "elevation (m)", Semantics::Continuous),
      {"strokes", "features layer with strokes of tool 'feature'", false, LayerKind::Features, 0}};
  s.outputs = {
      {"dem", "the deformed elevation", DType::F32, 1, Semantics::Continuous, "m", std::nullopt}};
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"energy_weight",
         {{"type", "number"},
          {"minimum", 1e-6},
          {"maximum", 1},
          {"default", 0.01},
          {"description",
           "weight of the Laplace-Beltrami energy rows against the positional constraints "
           "(weight 1): larger is smoother, smaller follows the strokes more closely"}}},
        {"subdivision",
         {{"enum", {"adaptive", "uniform"}},
          {"default", "adaptive"},
          {"description",
           "with the step's refine: Loop subdivision near the features only (adaptive), or of "
           "every sample of the window around them (uniform: the same heights near the "
           "features, the terrain around them smoothed by Loop)"}}}}}};
  return s;
}

// The metres between a sample and its right and lower neighbours, the smaller of the two, at the
// sample nearest `p` (clamped into the mosaic).
double sample_spacing(const MosaicFrame& frame, int size, LonLat p) {
  const auto s = frame.sample(p);
  const int c = s ? std::clamp(int(std::lround((*s)[0])), 0, size - 2) : 0;
  const int r = s ? std::clamp(int(std::lround((*s)[1])), 0, size - 2) : 0;
  const EastNorth2 a = frame.local(frame.sample_lonlat(c, r));
  const EastNorth2 b = frame.local(frame.sample_lonlat(c + 1, r));
  const EastNorth2 d = frame.local(frame.sample_lonlat(c, r + 1));
  return std::min(std::hypot(b[0] - a[0], b[1] - a[1]), std::hypot(d[0] - a[0], d[1] - a[1]));
}

// Fills the horizontal positions of the constraints' vertices and their neighbours.
void place_vertices(const MosaicFrame& frame, const StrokeConstraints& constraints,
                    HeightField& field) {
  std::vector<char> wanted(field.z.size(), 0);
  for (const auto* list : {&constraints.control, &constraints.section})
    for (const HeightConstraint& h : *list)
      for (const size_t v : h.at.vertex) {
        const int c = int(v % size_t(field.width)), r = int(v / size_t(field.width));
        wanted[v] = 1;
        for (const auto& n : kNeighbours) wanted[field.index(c + n[0], r + n[1])] = 1;
      }
  place_samples(frame, wanted, field);
}

// Refining reads the DEM kRefineMargin + refine samples around the constrained triangles (the
// subdivision's rings and the energy rows around them). Those samples must lie in the region:
// the window would otherwise be cut at its edge, where Loop's border masks (the border curve's
// B-spline) would replace the interior's, a different surface from uniform subdivision's. And
// they must hold data: nodata there is an error naming the feature, where the solve would
// otherwise meet it as a non-finite system. `control` and `section`: the stroke's constraints.
void check_surroundings(const MosaicFrame& frame, const HeightField& field,
                        std::span<const HeightConstraint> control,
                        std::span<const HeightConstraint> section, int refine,
                        const FeatureStroke& stroke) {
  const int reach = kRefineMargin + refine;
  const std::string feature = "inputs.strokes: feature " + std::to_string(stroke.id);
  const std::string refined =
      ": refined " + std::to_string(refine) + " level(s), it needs the DEM's heights ";
  std::vector<char> seen(field.z.size(), 0);
  for (const auto list : {control, section})
    for (const HeightConstraint& h : list)
      for (const size_t v : h.at.vertex) {
        if (seen[v]) continue;
        seen[v] = 1;
        const int c = int(v % size_t(field.width)), r = int(v / size_t(field.width));
        const auto at = [&] { return lonlat_text(frame.sample_lonlat(c, r)); };
        const int to_edge = std::min({c, r, field.width - 1 - c, field.height - 1 - r});
        if (to_edge < reach)
          throw Error(feature + ": its constraints come within " + std::to_string(to_edge) +
                      " samples of the region's edge at " + at() + refined + std::to_string(reach) +
                      " samples around them, inside the region: draw the region larger around "
                      "the feature");
        for (int y = r - reach; y <= r + reach; ++y)
          for (int x = c - reach; x <= c + reach; ++x) {
            if (!std::isnan(field.z[field.index(x, y)])) continue;
            const auto centre = frame.sample_centre(x, y);
            throw Error(
                feature + ": nodata at " +
                (centre
                     ? lonlat_text(*centre)
                     : "the gap beyond a face corner (no face of the plane there) near " + at()) +
                ", " + std::to_string(reach) + " samples or less from its constraints" + refined +
                "there");
          }
      }
}

// Runs a least squares (deform_solve.h), its errors, which name the feature, put on the strokes'
// port.
template <class Solve>
auto on_strokes_port(const Solve& solve) {
  try {
    return solve();
  } catch (const Error& e) {
    throw Error("inputs.strokes: " + std::string(e.what()));
  }
}

// The deformed surface `refine` levels finer near the features (deform_levels.h): the strokes
// sampled every half a sample of each level solved, from `step_m` at the base level.
RefinedPatch refine_near(const MosaicFrame& frame, HeightField& field,
                         const std::vector<FeatureStroke>& strokes, double step_m,
                         double energy_weight, int refine, Subdivision subdivision) {
  std::vector<StrokeConstraints> by_level(static_cast<size_t>(refine));
  for (int t = 0; t < refine; ++t)
    for (const FeatureStroke& stroke : strokes) {
      StrokeConstraints& all = by_level[size_t(t)];
      const size_t controls = all.control.size(), sections = all.section.size();
      add_stroke_constraints(stroke, frame, field, step_m / double(1 << t), "inputs.strokes", all);
      check_surroundings(frame, field, std::span(all.control).subspan(controls),
                         std::span(all.section).subspan(sections), refine, stroke);
    }
  const SampleWindow window = refinement_window(field, by_level);
  // Nodata samples of the window (in a corner gap of the plane too, which has no position) are
  // farther from the constraints than anything the refined zone reads (check_surroundings):
  // they keep no position, and their finer samples stay nodata.
  std::vector<char> wanted(field.z.size(), 0);
  for (int r = window.row0; r <= window.row1; ++r)
    for (int c = window.col0; c <= window.col1; ++c)
      if (const size_t v = field.index(c, r); !std::isnan(field.z[v])) wanted[v] = 1;
  place_samples(frame, wanted, field);
  return on_strokes_port(
      [&] { return refined_heights(field, window, by_level, energy_weight, subdivision); });
}

// The heights of the input mosaic `dem` (the region and its halo) for the finer samples around
// the refined patch: nodata on the mosaic's outer ring (no tile beyond the region's square, or a
// corner gap) takes the nearest region sample's height, as the region's edge would without a
// halo; other nodata stays (and so do the finer samples of the triangles around it).
HeightField halo_heights(const Tile<float>& dem) {
  HeightField grown;
  grown.width = grown.height = dem.size();
  grown.z.resize(size_t(dem.size()) * size_t(dem.size()));
  const int last = dem.size() - 1 - kHalo;
  for (int r = 0; r < dem.size(); ++r)
    for (int c = 0; c < dem.size(); ++c) {
      const float z = dem.at(c, r);
      grown.z[grown.index(c, r)] =
          std::isnan(z) ? dem.at(std::clamp(c, kHalo, last), std::clamp(r, kHalo, last)) : z;
    }
  return grown;
}

// The finer output mosaic (the region and its halo): the patch (in the region's finer samples)
// where it is, elsewhere `grown` (halo_heights) linearly interpolated at the finer pixel centres.
// Rows in parallel, each sample on its own (height_at_clamped, its coordinates clamped once per
// column and row).
void write_finer(const HeightField& grown, const RefinedPatch& patch, int refine,
                 Tile<float>& out) {
  const double scale = 1 << refine;
  const int shift = kHalo << refine;
  std::vector<double> cols(size_t(out.size())), rows(size_t(out.size()));
  for (int k = 0; k < out.size(); ++k) {
    cols[size_t(k)] = clamped_col(grown, (k + 0.5) / scale - 0.5);
    rows[size_t(k)] = clamped_row(grown, (k + 0.5) / scale - 0.5);
  }
  tbb::parallel_for(0, out.size(), [&](int r) {
    for (int c = 0; c < out.size(); ++c) {
      const int j = c - shift - patch.col0, i = r - shift - patch.row0;
      out.at(c, r) = float(j >= 0 && i >= 0 && j < patch.columns && i < patch.rows
                               ? patch.z[size_t(i) * size_t(patch.columns) + size_t(j)]
                               : height_at(grown, locate(grown, cols[size_t(c)], rows[size_t(r)])));
    }
  });
}

class Features : public RegionOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = features_spec();
    return s;
  }

  void run(const StepContext& ctx, const Mosaic& input, Mosaic& output) const override {
    const Tile<float>& dem = input.layers.at("dem");
    Tile<float>& out = output.layers.at("dem");
    const double energy_weight = ctx.params->at("energy_weight").get<double>();
    // The region: the mosaic less the runner's halo of kHalo samples on every side.
    const int size = dem.size() - 2 * kHalo;
    // The step's refine: the runner makes the output mosaic 2^refine times finer.
    const int refine = output.level - input.level;
    if (refine < 0 || refine > kMaxLevels || size < 2 || out.size() != dem.size() << refine)
      throw Error("deform.features: output mosaic of " + std::to_string(out.size()) +
                  " samples a side at level " + std::to_string(output.level) + " for an input of " +
                  std::to_string(dem.size()) + " at level " + std::to_string(input.level) +
                  " (refine 0 to " + std::to_string(kMaxLevels) + " levels)");
    const std::vector<FeatureStroke> strokes =
        feature_strokes(input.features.at("strokes"), "strokes");
    if (refine == 0) out = dem;
    if (strokes.empty() && refine == 0) return;
    if (strokes.empty()) {
      write_finer(halo_heights(dem), {}, refine, out);
      return;
    }

    HeightField field;
    field.width = field.height = size;
    field.z.resize(size_t(size) * size_t(size));
    for (int r = 0; r < size; ++r)
      for (int c = 0; c < size; ++c) field.z[field.index(c, r)] = dem.at(c + kHalo, r + kHalo);
    field.east.assign(field.z.size(), NAN);
    field.north.assign(field.z.size(), NAN);

    const LonLat reference = strokes.front().curve.front();
    const MosaicFrame frame(*ctx.grid, input.face, input.level, input.origin_col + kHalo,
                            input.origin_row + kHalo, reference);
    // Half a sample: every triangle the curve or a cross section crosses holds a constraint.
    const double step_m = 0.5 * sample_spacing(frame, size, reference);
    if (refine > 0) {
      const Subdivision subdivision =
          ctx.params->at("subdivision") == "uniform" ? Subdivision::Uniform : Subdivision::Adaptive;
      write_finer(halo_heights(dem),
                  refine_near(frame, field, strokes, step_m, energy_weight, refine, subdivision),
                  refine, out);
      return;
    }
    StrokeConstraints constraints;
    for (const FeatureStroke& stroke : strokes)
      add_stroke_constraints(stroke, frame, field, step_m, "inputs.strokes", constraints);
    place_vertices(frame, constraints, field);
    on_strokes_port([&] {
      deform_heights(field, constraints.control, constraints.section, constraints.bands,
                     energy_weight);
    });

    for (int r = 0; r < size; ++r)
      for (int c = 0; c < size; ++c) {
        const double z = field.z[field.index(c, r)];
        if (!std::isnan(z) && z != double(dem.at(c + kHalo, r + kHalo)))
          out.at(c + kHalo, r + kHalo) = float(z);
      }
  }
};

}  // namespace

std::unique_ptr<Operator> make_features() { return std::make_unique<Features>(); }

}  // namespace maquette::deform
