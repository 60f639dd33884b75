// Model layers: one model per layer, a mesh content blob in the model's own frame, kept in the
// `content` table at level 0 and cell id 0 (no valid cell has that id, so no reader of cells
// takes it for a cell's content; stats and drop_layer count and remove it with the layer's other
// rows).

#include "content/content_blob.h"
#include "content/glb_chunks.h"
#include "store/store_impl.h"

namespace maquette {
namespace {

constexpr int64_t kModelCell = 0;

std::string model_where(const std::string& name, const std::string& store_path) {
  return "model '" + name + "' in " + store_path;
}

void check_model_layer(const LayerEntry& e, const std::string& store_path) {
  if (e.info.kind != LayerKind::Model)
    throw Error("layer '" + e.info.name + "' in " + store_path + " is of kind " +
                std::string(layer_kind_name(e.info.kind)) + ", not a model");
}

// Throws naming `where` unless the blob is a sound mesh envelope at the zero origin.
void check_model_blob(std::string_view blob, const std::string& where) {
  const ContentEnvelope envelope = read_content_envelope(blob, where);
  if (envelope.kind != ContentKind::Mesh)
    throw Error("corrupt model blob (" + where + "): it holds " +
                std::string(content_kind_name(envelope.kind)) + " content, not a mesh");
  if (!(envelope.origin == EnuOrigin{}))
    throw Error("corrupt model blob (" + where +
                "): its origin is not zero (a model is in its own frame)");
}

// The materials of a model's GLB (its JSON chunk's "materials").
int64_t glb_materials(std::string_view glb, const std::string& where) {
  const nlohmann::json gltf =
      split_glb(glb, "corrupt model blob (" + where + "), its payload").gltf;
  const auto materials = gltf.find("materials");
  return materials != gltf.end() && materials->is_array() ? int64_t(materials->size()) : 0;
}

}  // namespace

ModelWrite model_write(const std::optional<LayerEntry>& existing, const std::string& store_path,
                       const std::string& name, std::string_view blob,
                       const nlohmann::json& provenance) {
  if (name.empty()) throw Error("a model needs a name");
  if (existing) check_model_layer(*existing, store_path);
  check_model_blob(blob, model_where(name, store_path));
  return {name, std::string(blob), provenance};
}

void write_model(sqlite::Connection& c, const std::string& store_path, const ModelWrite& w) {
  int64_t id = 0;
  if (const auto old = load_layer(c, w.name)) {
    check_model_layer(*old, store_path);
    update_provenance(c, *old, w.provenance);
    id = old->id;
  } else {
    LayerInfo info;
    info.name = w.name;
    info.kind = LayerKind::Model;
    info.provenance = w.provenance;
    id = insert_layer(c, normalized_layer(info));
  }
  write_content_blob(c, id, 0, kModelCell, w.blob);
  c.query("UPDATE layers SET updated = strftime('%Y-%m-%dT%H:%M:%fZ') WHERE id = ?")
      .bind_int(1, id)
      .run();
}

std::optional<std::string> Store::get_model(const std::string& name) const {
  const auto e = impl_->find(name);
  if (!e) return std::nullopt;
  check_model_layer(*e, impl_->path);
  auto conn = impl_->readers.borrow();
  auto blob = read_content_blob(*conn, e->id, 0, kModelCell);
  if (blob) check_model_blob(*blob, model_where(name, impl_->path));
  return blob;
}

ModelStats Store::model_stats(const std::string& name) const {
  const auto blob = get_model(name);
  const std::string where = model_where(name, impl_->path);
  if (!blob) throw Error("no " + where);
  ModelStats s;
  s.content = read_content_envelope(*blob, where).stats;
  s.materials = glb_materials(content_payload(*blob), where);
  s.bytes = int64_t(blob->size());
  return s;
}

}  // namespace maquette
