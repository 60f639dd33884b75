// Polygons of a WKB geometry, as features layers store them (framework/store/store.h Feature::wkb,
// WGS84 lon/lat): Polygon and MultiPolygon, 2D, Z, M or ZM (ISO or EWKB dimension flags).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/geojson.h"

namespace maquette {

// Throws maquette::Error prefixed with `where` (e.g. "op: params.x: feature 3 of 'zones'") for
// another geometry type ("... is a Point, not a polygon") or truncated WKB.
std::vector<PolygonRings> wkb_polygons(std::span<const std::byte> wkb, const std::string& where);

}  // namespace maquette
