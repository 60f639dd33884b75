// Artifacts: named JSON or binary blobs (fitted models, statistics, run reports).
#include "store/store_impl.h"

namespace maquette {

Artifact Artifact::FromText(std::string name, std::string_view text, nlohmann::json metadata) {
  const auto* bytes = reinterpret_cast<const std::byte*>(text.data());
  return {std::move(name), "application/json", {bytes, bytes + text.size()}, std::move(metadata)};
}

void Store::put_artifact(const Artifact& artifact) {
  Batch batch(*this);
  batch.put_artifact(artifact);
  batch.commit();
}

std::optional<Artifact> Store::get_artifact(const std::string& name) const {
  auto conn = impl_->readers.borrow();
  auto q = conn->query("SELECT media_type, data, metadata FROM artifacts WHERE name = ?");
  if (!q.bind_text(1, name).step()) return std::nullopt;
  const auto data = q.blob(1);
  return Artifact{name, q.text(0), {data.begin(), data.end()}, nlohmann::json::parse(q.text(2))};
}

std::vector<std::string> Store::artifact_names() const {
  auto conn = impl_->readers.borrow();
  auto q = conn->query("SELECT name FROM artifacts ORDER BY name");
  std::vector<std::string> names;
  while (q.step()) names.push_back(q.text(0));
  return names;
}

}  // namespace maquette
