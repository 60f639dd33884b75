#include "vector/draw_features.h"

#include <ogr_geometry.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "core/error.h"

namespace maquette {
namespace {

using Px = std::array<double, 2>;  // pixel coordinates: column, row (0, 0: top-left corner)
using Rgb = std::array<uint8_t, 3>;

// Magenta in a near-black casing: a hue no terrain tint, snow, water or land imagery has.
constexpr Rgb kCasing = {20, 20, 20};
constexpr Rgb kCore = {255, 0, 200};
constexpr Rgb kBackground = {236, 236, 230};
constexpr double kCasingRadius = 2.2, kCoreRadius = 1.0;  // pixels, half the line widths
constexpr double kDotCasing = 4.0, kDotCore = 2.8;        // point radii, pixels
// Segments are cut into pieces of at most this many pixels before projection, so that a
// straight lon/lat segment follows its curve in a polar picture.
constexpr double kPieceLength = 4;

// Lon/lat to the frame's pixel coordinates.
class Projector {
 public:
  explicit Projector(const PictureFrame& f) : f_(f) {
    centre_lon_ = f.left + f.width * f.x_step / 2;
    if (f.projection == Projection::LonLat) return;
    OGRSpatialReference lonlat, target;
    lonlat.importFromEPSG(4326);
    lonlat.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    target.importFromWkt(f.crs_wkt().c_str());
    target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    ct_.reset(OGRCreateCoordinateTransformation(&lonlat, &target));
    if (!ct_) throw Error("PROJ cannot transform lon/lat to the picture's " + f.crs_name());
  }
  bool curved() const { return ct_ != nullptr; }

  std::optional<Px> operator()(double lon, double lat) const {
    double x = lon, y = lat;
    if (ct_) {
      if (!ct_->Transform(1, &x, &y)) return std::nullopt;
    } else {
      x = centre_lon_ + std::remainder(x - centre_lon_, 360.0);  // the side of the frame
    }
    return Px{(x - f_.left) / f_.x_step, (f_.top - y) / f_.y_step};
  }

 private:
  const PictureFrame& f_;
  double centre_lon_ = 0;
  std::unique_ptr<OGRCoordinateTransformation> ct_;
};

// What is drawn: line pieces and dots, in pixels.
struct Marks {
  std::vector<std::pair<Px, Px>> pieces;
  std::vector<Px> dots;
};

void add_line(const OGRSimpleCurve& line, const Projector& project, Marks& marks) {
  for (int i = 0; i + 1 < line.getNumPoints(); ++i) {
    const double x0 = line.getX(i), y0 = line.getY(i), x1 = line.getX(i + 1), y1 = line.getY(i + 1);
    const auto a = project(x0, y0), b = project(x1, y1);
    if (!a || !b) continue;
    int n = 1;
    if (project.curved())
      n = std::clamp(
          int(std::ceil(std::hypot((*b)[0] - (*a)[0], (*b)[1] - (*a)[1]) / kPieceLength)), 1, 256);
    std::optional<Px> from = a;
    for (int k = 1; k <= n; ++k) {
      const double t = double(k) / n;
      const auto to = k == n ? b : project(x0 + t * (x1 - x0), y0 + t * (y1 - y0));
      if (from && to) marks.pieces.emplace_back(*from, *to);
      from = to;
    }
  }
}

void add_geometry(const OGRGeometry& g, const Projector& project, Marks& marks) {
  switch (wkbFlatten(g.getGeometryType())) {
    case wkbPoint: {
      const auto& p = *g.toPoint();
      if (const auto px = project(p.getX(), p.getY())) marks.dots.push_back(*px);
      return;
    }
    case wkbLineString:
    case wkbLinearRing:
      add_line(*g.toSimpleCurve(), project, marks);
      return;
    case wkbPolygon:
      for (const OGRLinearRing* ring : *g.toPolygon()) add_line(*ring, project, marks);
      return;
    default:
      break;
  }
  if (OGR_GT_IsSubClassOf(g.getGeometryType(), wkbGeometryCollection)) {
    for (const OGRGeometry* part : *g.toGeometryCollection()) add_geometry(*part, project, marks);
  } else if (g.hasCurveGeometry()) {  // circular strings, curve polygons: drawn linearised
    const std::unique_ptr<OGRGeometry> linear(g.getLinearGeometry());
    add_geometry(*linear, project, marks);
  }
}

// Blends `rgb` with coverage `a` over pixel (c, r).
void blend(RgbaImage& image, int c, int r, const Rgb& rgb, double a) {
  uint8_t* p = image.at(c, r);
  const double under = p[3] / 255.0 * (1 - a), alpha = a + under;
  for (size_t k = 0; k < 3; ++k) p[k] = uint8_t(std::lround((rgb[k] * a + p[k] * under) / alpha));
  p[3] = uint8_t(std::lround(255 * alpha));
}

// Paints the pixels within `radius` of segment a-b (a dot when a == b), the edge antialiased.
void stroke(RgbaImage& image, Px a, Px b, double radius, const Rgb& rgb) {
  const int c0 = std::max(0, int(std::floor(std::min(a[0], b[0]) - radius - 1)));
  const int c1 = std::min(image.width - 1, int(std::ceil(std::max(a[0], b[0]) + radius + 1)));
  const int r0 = std::max(0, int(std::floor(std::min(a[1], b[1]) - radius - 1)));
  const int r1 = std::min(image.height - 1, int(std::ceil(std::max(a[1], b[1]) + radius + 1)));
  const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      const double px = c + 0.5 - a[0], py = r + 0.5 - a[1];
      const double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
      const double d = std::hypot(px - t * dx, py - t * dy);
      const double coverage = std::clamp(radius + 0.5 - d, 0.0, 1.0);
      if (coverage > 0) blend(image, c, r, rgb, coverage);
    }
}

}  // namespace

void draw_features(RgbaImage& image, const PictureFrame& frame,
                   const std::vector<Feature>& features) {
  const Projector project(frame);
  Marks marks;
  for (const Feature& f : features) {
    OGRGeometry* g = nullptr;
    if (OGRGeometryFactory::createFromWkb(f.wkb.data(), nullptr, &g, f.wkb.size()) != OGRERR_NONE)
      throw Error("feature " + std::to_string(f.fid) + ": stored geometry is not valid WKB");
    const std::unique_ptr<OGRGeometry> owned(g);
    add_geometry(*g, project, marks);
  }
  // Every casing first, so that crossing lines keep their cores.
  for (const auto& [a, b] : marks.pieces) stroke(image, a, b, kCasingRadius, kCasing);
  for (const Px& p : marks.dots) stroke(image, p, p, kDotCasing, kCasing);
  for (const auto& [a, b] : marks.pieces) stroke(image, a, b, kCoreRadius, kCore);
  for (const Px& p : marks.dots) stroke(image, p, p, kDotCore, kCore);
}

PictureRaster blank_picture(const Grid& grid, const RegionSpec& region,
                            const std::vector<Feature>& features, Projection projection,
                            int max_side) {
  PictureRegion picture{region.bbox, region.cells};
  if (!region.bbox && region.cells.empty()) {
    std::array<double, 4> b = features.front().bbox;
    for (const Feature& f : features)
      for (size_t k = 0; k < 4; ++k)
        b[k] = k < 2 ? std::min(b[k], f.bbox[k]) : std::max(b[k], f.bbox[k]);
    const double margin =
        std::max({b[2] - b[0], b[3] - b[1], 1e-4}) / 20;  // so outlines show whole
    picture.bbox =
        std::array<double, 4>{std::max(b[0] - margin, -180.0), std::max(b[1] - margin, -90.0),
                              std::min(b[2] + margin, 180.0), std::min(b[3] + margin, 90.0)};
  }
  int doublings = 0;
  PictureRaster out;
  out.frame = frame_for(grid, picture, projection, 1.0, max_side, doublings);
  out.width = out.frame->width;
  out.height = out.frame->height;
  out.values.assign(size_t(out.width) * size_t(out.height),
                    std::numeric_limits<float>::quiet_NaN());
  return out;
}

void fill_background(RgbaImage& image) {
  for (int r = 0; r < image.height; ++r)
    for (int c = 0; c < image.width; ++c) {
      uint8_t* p = image.at(c, r);
      const double a = p[3] / 255.0;
      for (size_t k = 0; k < 3; ++k)
        p[k] = uint8_t(std::lround(p[k] * a + kBackground[k] * (1 - a)));
      p[3] = 255;
    }
}

}  // namespace maquette
