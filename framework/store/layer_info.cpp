// Layer definitions: enum names, validation, comparison.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/json_file.h"
#include "core/samples.h"
#include "store/codec.h"
#include "store/store_impl.h"

namespace maquette {
namespace {

constexpr std::string_view kKindNames[] = {"raster",   "mesh",      "volume", "features",
                                           "artifact", "instances", "model"};
constexpr std::string_view kSemanticsNames[] = {"continuous", "categorical"};

std::string nodata_text(const std::optional<double>& v) {
  if (!v) return "none";
  std::ostringstream s;
  s.precision(17);
  s << *v;
  return s.str();
}

}  // namespace

std::string_view layer_kind_name(LayerKind k) { return kKindNames[size_t(k)]; }

LayerKind parse_layer_kind(std::string_view name) {
  for (size_t i = 0; i < std::size(kKindNames); ++i)
    if (kKindNames[i] == name) return LayerKind(i);
  throw Error("unknown layer kind '" + std::string(name) +
              "' (expected raster, mesh, instances, volume, model, features or artifact)");
}

std::optional<ContentKind> layer_content_kind(LayerKind k) {
  switch (k) {
    case LayerKind::Mesh:
      return ContentKind::Mesh;
    case LayerKind::Instances:
      return ContentKind::Instances;
    case LayerKind::Volume:
      return ContentKind::Volume;
    default:
      return std::nullopt;
  }
}

std::string_view semantics_name(Semantics s) { return kSemanticsNames[size_t(s)]; }

Semantics parse_semantics(std::string_view name) {
  for (size_t i = 0; i < std::size(kSemanticsNames); ++i)
    if (kSemanticsNames[i] == name) return Semantics(i);
  throw Error("unknown semantics '" + std::string(name) + "' (expected continuous or categorical)");
}

LayerInfo normalized_layer(const LayerInfo& info) {
  const std::string where = "layer '" + info.name + "': ";
  if (info.name.empty()) throw Error("a layer needs a name");
  // A name told apart from another only by blanks or unseen characters (" ", "dem ") reads as
  // another layer's in every message and listing.
  const auto unseen = [](unsigned char c) { return c < 0x20 || c == 0x7f; };
  if (std::isspace((unsigned char)info.name.front()) ||
      std::isspace((unsigned char)info.name.back()) ||
      std::any_of(info.name.begin(), info.name.end(), unseen))
    throw Error("layer name '" + excerpt(info.name) +
                "': no blank at either end and no control character");
  if (info.level < 0 || info.level > CellId::kMaxLevel)
    throw Error(where + "level " + std::to_string(info.level) + " not in [0, 29]");
  if (holds_content(info.kind)) {
    // Blobs of content name their own format (content_blob.h): no raster field applies. A
    // model is in no cell: its layer is at level 0.
    LayerInfo out;
    out.name = info.name;
    out.kind = info.kind;
    out.level = info.kind == LayerKind::Model ? 0 : info.level;
    out.dtype = DType::U8;
    out.tile_size = 1;
    out.codec = kContentCodec;
    out.provenance = info.provenance;
    return out;
  }
  if (info.channels < 1 || info.channels > 1024)
    throw Error(where + "channels " + std::to_string(info.channels) + " not in [1, 1024]");
  try {
    log2_tile_size(info.tile_size);
    check_codec_holds(parse_codec(info.codec), info.dtype, info.channels);
  } catch (const Error& e) {
    throw Error(where + e.what());
  }

  LayerInfo out = info;
  if (!out.nodata) return out;
  const double v = *out.nodata;
  const bool representable = visit_dtype(out.dtype, [&]<typename T>(std::type_identity<T>) {
    if constexpr (std::is_floating_point_v<T>)
      return std::isnan(v) || std::isinf(v) || std::abs(v) <= double(std::numeric_limits<T>::max());
    else
      return !std::isnan(v) && double(cast_sample<T>(v)) == v;
  });
  if (!representable)
    throw Error(where + "nodata " + nodata_text(out.nodata) + " is not a " +
                std::string(dtype_name(out.dtype)) + " value");
  // NaN is always missing in float tiles, and SQLite cannot store it: keep "no nodata".
  if (std::isnan(v)) out.nodata.reset();
  return out;
}

std::string layer_difference(const LayerInfo& a, const LayerInfo& b) {
  auto differ = [](std::string_view field, auto x, auto y) {
    std::ostringstream s;
    s << field << ' ' << x << " vs " << y;
    return s.str();
  };
  if (a.kind != b.kind) return differ("kind", layer_kind_name(a.kind), layer_kind_name(b.kind));
  if (a.dtype != b.dtype) return differ("dtype", dtype_name(a.dtype), dtype_name(b.dtype));
  if (a.channels != b.channels) return differ("channels", a.channels, b.channels);
  if (a.tile_size != b.tile_size) return differ("tile size", a.tile_size, b.tile_size);
  if (a.level != b.level) return differ("level", a.level, b.level);
  if (a.nodata != b.nodata) return differ("nodata", nodata_text(a.nodata), nodata_text(b.nodata));
  if (a.semantics != b.semantics)
    return differ("semantics", semantics_name(a.semantics), semantics_name(b.semantics));
  if (a.units != b.units) return differ("units", "'" + a.units + "'", "'" + b.units + "'");
  return {};
}

}  // namespace maquette
