// The operator API. An operator is named "<module>.<verb>", declares its inputs, outputs, halo,
// parameters (a JSON Schema, validated before anything runs) and its kind:
//  - cell:   one cell at a time, from its input tiles (+ halo) to its output tiles;
//  - reduce: map each cell to a partial result, merge partials, finish into an artifact;
//  - region: a whole region at once, as one mosaic split back into cells by the framework;
//  - task:   the program's built-in steps (ingest, export), run once (task_operator.h).
// Operators must be deterministic: same inputs and parameters, same bits, for any thread
// count, order or number of processes.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "content/content.h"
#include "core/cell_id.h"
#include "core/grid.h"
#include "core/tile.h"
#include "runtime/vector_feature.h"
#include "store/store.h"

namespace maquette {

using json = nlohmann::json;

enum class OperatorKind { Cell, Reduce, Region, Task };
std::string_view operator_kind_name(OperatorKind k);

// An input port: a raster layer (tiles with the operator's halo, CellData::inputs) or a features
// layer (CellData::features: the features whose geometry comes within reach_m of the cell).
struct InputSpec {
  std::string name;
  std::string description;
  bool optional = false;
  LayerKind kind = LayerKind::Raster;  // Raster or Features
  double reach_m = 0;                  // features ports: metres around the cell (>= 0)
  // Raster ports: the layers the port takes, checked when the pipeline is planned (a step given
  // another is refused before anything runs, naming the port, the layer and what it is): their
  // semantics (none: either) and channel counts (empty: any). A land-cover port takes
  // Categorical layers of 1 channel, a DEM port Continuous ones of 1.
  std::optional<Semantics> semantics = std::nullopt;
  std::vector<int> channels = {};
};

// A raster port taking layers of one channel of `semantics`: heights (Continuous), land-cover
// classes (Categorical).
InputSpec single_channel_input(std::string name, std::string description, Semantics semantics,
                               bool optional = false);

// An output port. The layer it writes gets dtype/channels/semantics/units/codec from here and its
// level and tile size from the step's first input (or the pipeline's level and tile size), the tile
// size times 2^refine for a step with "refine" (OperatorSpec::refinable).
struct OutputSpec {
  std::string name;
  std::string description;
  DType dtype = DType::F32;
  int channels = 1;
  Semantics semantics = Semantics::Continuous;
  std::string units;
  std::optional<double> nodata;
  // How its tiles are stored (store/codec.h): "normal_oct" for unit normals (float32 x 3), ~4-10x
  // fewer bytes than zstd for at most 0.04 degrees.
  std::string codec = "zstd";
  // The kind of layer it writes: Raster, or 3D content (Mesh, Instances, Volume: CellContent; only
  // name, description and kind apply, the layer is at the step's level).
  LayerKind kind = LayerKind::Raster;
};

// The largest "refine" of any step: a tile of 1 sample refined 12 times is 4096 samples, the
// largest tile (log2_tile_size).
inline constexpr int kMaxRefine = 12;

struct OperatorSpec {
  std::string name;
  std::string description;
  OperatorKind kind = OperatorKind::Cell;
  std::vector<InputSpec> inputs;
  std::vector<OutputSpec> outputs;
  // Pixels of neighbouring tiles each input tile needs on every side. A region operator's mosaics
  // (input and output) are grown by as many samples on every side of its cells' square, and the
  // input's samples within that many of a cell's tile that no cell of the step covers are read
  // from the tiles there (NaN where none); the output is cut back to the cells' tiles.
  int halo = 0;
  // Outputs `refine` levels finer than the inputs (a step's "refine"): a cell operator gets tiles
  // of tile_size << refine (CellContext::refine), a region operator output mosaics as much finer.
  bool refinable = false;
  // The largest "refine" the operator takes: a step asking more is refused when the pipeline is
  // read, naming the step and the value, before anything runs.
  int max_refine = kMaxRefine;
  // A cell operator that writes every sample of every output tile it is given (NaN for nodata
  // included): the runner then hands it uninitialized output tiles instead of NaN-filled ones
  // (Tile::uninitialized), saving their fill. An operator that leaves a sample unwritten must not
  // declare it: that sample would be stored with an indeterminate value.
  bool writes_all_samples = false;
  // A cell operator that also writes cells where its first input has no tile, within that
  // input's footprint (core/data_footprint.h: where its sources have data), e.g. a void filler
  // for voids that swallow whole tiles (the ingest writes no tile without data). The runner then
  // runs it on the region's cells overlapping the footprint too, with an all-NaN input tile (and
  // the neighbours' halo); on the input's tiles only when the input has no footprint.
  bool fills_footprint = false;
  // A region operator whose mosaic may span rHEALPix faces: the runner then pastes the cells of up
  // to three faces into one plane unfolded around an anchor face (Mosaic, core/unfolded_faces.h)
  // instead of refusing cells of several faces. Its operator must place samples through that
  // unfolding (Mosaic::face is the anchor; origin_col/row may lie beyond its edges).
  bool spans_faces = false;
  // JSON Schema (draft 7 subset: type, properties, required, enum, minimum, maximum, default,
  // items, minItems, maxItems, additionalProperties false) of the step's "params" object.
  json params_schema = {{"type", "object"}, {"properties", json::object()}};
  // Checks of a step's params beyond the schema that need neither the store nor a cell: files
  // they name exist, fields that exclude each other, params that need an input port mapped. Run
  // when the pipeline is read (a dry run too), so that a fault is told before any step runs; for
  // params holding artifacts (artifact_refs.h), once they are pasted in, before the step runs.
  // Gets the params (validated, defaults filled in) and the input ports the step maps; throws
  // maquette::Error naming the field and value (the caller prefixes the step). Empty: none.
  std::function<void(const json& params, const std::set<std::string>& mapped_inputs)> check_params;
};

// The raster layers a step's input ports read: (port, layer), in the spec's order.
using InputLayers = std::vector<std::pair<std::string, LayerInfo>>;

// What an operator sees of the cell it works on. `store` is the run's store (on every rank), for
// reading what the step's ports do not carry: artifacts (a stations table, a fitted model), other
// layers, features layers. Operators must only read it: the runner writes every output, and a
// write from an operator would escape the run records, resume and the ranks' agreement.
struct CellContext {
  CellId cell;
  int tile_size = 0;  // of the input tiles (without halo)
  int refine = 0;     // output tiles have tile_size << refine samples (OperatorSpec::refinable)
  const Grid* grid = nullptr;
  const json* params = nullptr;  // validated, defaults filled in
  const Store* store = nullptr;  // read-only (see above)
  // The raster layers the step's input ports read, in the spec's order: what a layer is beyond its
  // tiles, e.g. a DEM's vertical datum (gdal/vertical_datum.h: ellipsoidal_heights(layer) turns
  // its heights into the heights above the ellipsoid that 3D content is placed at).
  const InputLayers* input_layers = nullptr;

  // The layer read by raster input port `port`; throws maquette::Error when no layer is mapped.
  const LayerInfo& input_layer(const std::string& port) const;

  // Whether this cell owns an object anchored at `anchor` (content/content.h: a mesh object's
  // first vertex, an instance's position): the cell at its level holding the point. Features
  // near several cells are delivered to each; each writes only the objects it owns.
  bool owns(LonLat anchor) const;
};

// What a reduce operator's finish() and a region operator see of their step: as CellContext,
// without a cell.
struct StepContext {
  const Grid* grid = nullptr;
  const json* params = nullptr;               // validated, defaults filled in
  const Store* store = nullptr;               // read-only, as in CellContext
  const InputLayers* input_layers = nullptr;  // as in CellContext

  const LayerInfo& input_layer(const std::string& port) const;
};

// How far beyond its cell an anchor may be found (metres): float32 positions near an edge may
// round across it.
inline constexpr double kAnchorToleranceM = 0.01;

// The 3D content an operator writes for one cell, by content output port (OutputSpec::kind Mesh,
// Instances or Volume), only the ports the step maps. The runner hands each one empty with its
// origin at the cell's centre, height 0 (the operator may move it: any finite origin); a content
// left empty (no object, no instance, no VDB bytes) writes nothing for the cell.
//
// Contract, checked by the runner before anything of the cell is written (a fault fails the cell,
// naming the step, the cell, the port, and the object with its feature id):
// - anchors in the cell: each mesh object's first vertex and each instance's position, taken back
//   to lon/lat from the origin, lie in the cell (CellContext::owns), within kAnchorToleranceM for
//   the rounding of float32 positions near its edge;
// - meshes: finite positions, 3 per vertex, one normal and one uv per vertex or none,
//   indices in range and whole triangles (at least one), materials in range;
// - a finite origin on the globe (lon in [-180, 180], lat in [-90, 90]);
// - instances: content/instances_codec.h's check_instances, finite positions, prototypes
//   "builtin:conifer|broadleaf|shrub" (content/prototypes.h) or a model layer of the store;
// - volumes: a VDB stream the volume plug-in reads (vdb/volume_vdb.h), each grid's anchor (the
//   centre of its active voxels' bounding box, vdb/volume_vdb.h's volume_anchors) in the cell
//   as above (a grid without active voxels has none).
// Meshes are stored as formats/gltf/mesh_glb.h's GLB (positions quantized to at most 1 mm),
// instances losslessly (instances_codec.h), volumes as given.
struct CellContent {
  std::map<std::string, MeshContent> meshes;          // by mesh port
  std::map<std::string, InstancesContent> instances;  // by instances port
  std::map<std::string, VolumeContent> volumes;       // by volume port

  MeshContent& mesh(const std::string& port);               // throws naming the port
  InstancesContent& instances_of(const std::string& port);  // throws naming the port
  VolumeContent& volume(const std::string& port);           // throws naming the port
  bool wants(const std::string& port) const;
};

// Input tiles as float32 (nodata -> NaN) with the operator's halo; outputs without halo, as
// float32 (NaN -> the output's nodata), converted to the output dtype by the framework. Outputs
// arrive NaN-filled, or uninitialized for an operator that declares writes_all_samples. Features
// ports get the features within their reach_m of the cell (core/geo_distance.h), sorted by id;
// the pointers are valid while the operator runs.
struct CellData {
  std::map<std::string, Tile<float>> inputs;    // by input port name (absent optional: missing)
  std::map<std::string, FeatureList> features;  // by features port name (absent optional: missing)
  std::map<std::string, Tile<float>> outputs;   // by raster output port, only those the step maps
  CellContent content;                          // by content output port (see CellContent)

  const Tile<float>& input(const std::string& port) const;        // throws naming the port
  const FeatureList& features_of(const std::string& port) const;  // throws naming the port
  Tile<float>& output(const std::string& port);                   // throws naming the port
  bool wants(const std::string& output_port) const {
    return outputs.count(output_port) != 0 || content.wants(output_port);
  }
};

class Operator {
 public:
  virtual ~Operator() = default;
  virtual const OperatorSpec& spec() const = 0;
};

class CellOperator : public Operator {
 public:
  virtual void run(const CellContext& ctx, CellData& data) const = 0;
};

class ReduceOperator : public Operator {
 public:
  // Partial result of one cell (may be null for "nothing here").
  virtual json map(const CellContext& ctx, const CellData& data) const = 0;
  // Associative merge; the framework merges partials in cell-id order, so the result does not
  // depend on threads or ranks.
  virtual json merge(const json& a, const json& b) const = 0;
  // The artifact written under the step's output name.
  virtual Artifact finish(const json& merged, const StepContext& ctx) const = 0;
};

// A mosaic: the tiles of a region's cells pasted into one raster on one face. `origin_col/row`
// are the global face pixel coordinates of mosaic pixel (0, 0). For an operator that spans faces
// (OperatorSpec::spans_faces), the raster is the plane unfolded around `face`, the anchor
// (core/unfolded_faces.h): origin_col/row are anchor-frame coordinates, and a neighbour face's
// tiles lie beyond the anchor's edge, turned as the faces meet; samples of no step cell are NaN.
struct Mosaic {
  int face = 0;
  int level = 0;  // pixel level: cell level + log2(tile size)
  int64_t origin_col = 0, origin_row = 0;
  std::map<std::string, Tile<float>> layers;  // square or not: width = height = tile.size()
  // Input mosaics only: by features port, the features within its reach_m of any of the region's
  // cells, sorted by id (valid while the operator runs).
  std::map<std::string, FeatureList> features;
  // Output mosaics only: the content of each of the step's cells (CellContent, prepared by the
  // runner for every cell). A region operator puts each object in the cell that owns its anchor
  // (Grid::cell_from_point at the cells' level).
  std::map<CellId, CellContent> content;
};

class RegionOperator : public Operator {
 public:
  virtual void run(const StepContext& ctx, const Mosaic& input, Mosaic& output) const = 0;
};

using OperatorFactory = std::unique_ptr<Operator> (*)();

}  // namespace maquette
