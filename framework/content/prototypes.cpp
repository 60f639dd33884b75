#include "content/prototypes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "core/error.h"
#include "core/splitmix64.h"

namespace maquette {
namespace {

using P3 = std::array<double, 3>;

P3 add(const P3& a, const P3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P3 cross(const P3& a, const P3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
P3 unit(const P3& a) {
  const double n = std::hypot(a[0], a[1], a[2]);
  return {a[0] / n, a[1] / n, a[2] / n};
}

// A smooth surface: its vertices get the area-weighted mean of their triangles' normals, so
// surfaces meeting at a crease (a cone's rim, a cylinder's cap) keep sharp edges.
struct Surface {
  std::vector<P3> positions;
  std::vector<uint32_t> indices;  // counter-clockwise seen from outside

  uint32_t vertex(const P3& p) {
    positions.push_back(p);
    return uint32_t(positions.size() - 1);
  }
  void triangle(uint32_t a, uint32_t b, uint32_t c) { indices.insert(indices.end(), {a, b, c}); }
};

// A prototype while it is made, in double precision, before it is scaled to 1 m.
struct Model {
  std::array<std::vector<Surface>, 2> parts;  // bark, foliage

  void add(int part, Surface s) { parts[size_t(part)].push_back(std::move(s)); }
};

P3 on_circle(double radius, double angle, double z) {
  return {radius * std::cos(angle), radius * std::sin(angle), z};
}

// A disc of `n` points around (0, 0, z), facing up or down.
Surface disc(double z, double radius, int n, bool up) {
  Surface s;
  const uint32_t centre = s.vertex({0, 0, z});
  for (int i = 0; i < n; ++i) s.vertex(on_circle(radius, 2 * std::numbers::pi * i / n, z));
  for (uint32_t i = 0; i < uint32_t(n); ++i) {
    const uint32_t a = 1 + i, b = 1 + (i + 1) % uint32_t(n);
    up ? s.triangle(centre, a, b) : s.triangle(centre, b, a);
  }
  return s;
}

// A trunk: a closed frustum from (0, 0, 0) to `top`, radii `r0` at its base and `r1` at its top.
void trunk(Model& m, double top, double r0, double r1, int n) {
  Surface side;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    side.vertex(on_circle(r0, a, 0));
    side.vertex(on_circle(r1, a, top));
  }
  for (uint32_t i = 0; i < uint32_t(n); ++i) {
    const uint32_t j = (i + 1) % uint32_t(n);
    side.triangle(2 * i, 2 * j, 2 * j + 1);
    side.triangle(2 * i, 2 * j + 1, 2 * i + 1);
  }
  m.add(0, std::move(side));
  m.add(0, disc(0, r0, n, false));
  m.add(0, disc(top, r1, n, true));
}

// A conifer's tier: a cone from a jagged rim (2n points, branch tips at `radius` hanging below
// `base` by an eighth of the tier's height, notches between them) up to `apex`, closed below by a
// shallow upward cone (the tier's underside, as the branches seen from below). `turn` (radians)
// sets the tips apart from those of the tier below.
void tier(Model& m, double base, double apex, double radius, int n, double turn) {
  const double droop = (apex - base) / 8;
  std::vector<P3> rim;
  for (int i = 0; i < 2 * n; ++i) {
    const bool tip = i % 2 == 0;
    rim.push_back(on_circle(tip ? radius : 0.72 * radius, turn + std::numbers::pi * i / n,
                            tip ? base - droop : base));
  }
  Surface side, under;
  const uint32_t top = side.vertex({0, 0, apex});
  const uint32_t centre = under.vertex({0, 0, base + 0.3 * (apex - base)});
  for (const P3& p : rim) {
    side.vertex(p);
    under.vertex(p);
  }
  const uint32_t k = uint32_t(rim.size());
  for (uint32_t i = 0; i < k; ++i) {
    const uint32_t a = 1 + i, b = 1 + (i + 1) % k;
    side.triangle(top, a, b);
    under.triangle(centre, b, a);
  }
  m.add(1, std::move(side));
  m.add(1, std::move(under));
}

// A unit icosphere subdivided `levels` times (10 * 4^levels + 2 vertices).
Surface icosphere(int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  Surface s;
  for (const P3& p : std::vector<P3>{{-1, t, 0},
                                     {1, t, 0},
                                     {-1, -t, 0},
                                     {1, -t, 0},
                                     {0, -1, t},
                                     {0, 1, t},
                                     {0, -1, -t},
                                     {0, 1, -t},
                                     {t, 0, -1},
                                     {t, 0, 1},
                                     {-t, 0, -1},
                                     {-t, 0, 1}})
    s.vertex(unit(p));
  s.indices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
               4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
               6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto [it, added] = midpoints.try_emplace(key, 0);
      if (added) {
        const P3& p = s.positions[a];
        const P3& q = s.positions[b];
        it->second = s.vertex(unit({p[0] + q[0], p[1] + q[1], p[2] + q[2]}));
      }
      return it->second;
    };
    std::vector<uint32_t> finer;
    for (size_t i = 0; i < s.indices.size(); i += 3) {
      const uint32_t a = s.indices[i], b = s.indices[i + 1], c = s.indices[i + 2];
      const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.insert(finer.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    s.indices = std::move(finer);
  }
  return s;
}

// A deterministic value in [-1, 1] for (seed, i): splitmix64.
double jitter(uint64_t seed, uint64_t i) {
  const uint64_t z = splitmix64_mix(seed * kSplitMix64Gamma + i + 1);
  return double(z >> 11) / double(1ull << 52) - 1;
}

// A lobe of foliage: an icosphere at `centre`, radii `radius` across and `radius * flat` up, each
// vertex moved out or in by up to `lumps` of the radius (seeded), nothing below z = 0.
struct Lobe {
  P3 centre;
  double radius;
};
void lobe(Model& m, const Lobe& l, double flat, double lumps, uint64_t seed) {
  Surface s = icosphere(2);
  for (size_t i = 0; i < s.positions.size(); ++i) {
    const double r = l.radius * (1 + lumps * jitter(seed, i));
    P3& p = s.positions[i];
    p = add(l.centre, {r * p[0], r * p[1], r * flat * p[2]});
    p[2] = std::max(p[2], 0.0);
  }
  m.add(1, std::move(s));
}

MeshObject object(const std::vector<Surface>& surfaces, double height, int material) {
  MeshObject o;
  o.material = material;
  o.provenance.object_id = uint64_t(material);
  for (const Surface& s : surfaces) {
    std::vector<P3> normals(s.positions.size(), P3{0, 0, 0});
    for (size_t i = 0; i < s.indices.size(); i += 3) {
      const P3& a = s.positions[s.indices[i]];
      const P3 n =
          cross(sub(s.positions[s.indices[i + 1]], a), sub(s.positions[s.indices[i + 2]], a));
      for (size_t k = 0; k < 3; ++k) normals[s.indices[i + k]] = add(normals[s.indices[i + k]], n);
    }
    const uint32_t first = uint32_t(o.positions.size() / 3);
    for (size_t i = 0; i < s.positions.size(); ++i) {
      for (double c : s.positions[i]) o.positions.push_back(float(c / height));
      for (double c : unit(normals[i])) o.normals.push_back(float(c));
    }
    for (uint32_t i : s.indices) o.indices.push_back(first + i);
  }
  return o;
}

Material colour(const std::string& name, float r, float g, float b) {
  Material m;
  m.name = name;
  m.base_colour = {r, g, b, 1};
  return m;
}

// Scaled so that its top is at exactly 1 m (its base is at 0).
MeshContent finish(const Model& m, const std::string& name, Material bark, Material foliage) {
  double top = 0;
  for (const auto& part : m.parts)
    for (const Surface& s : part)
      for (const P3& p : s.positions) top = std::max(top, p[2]);
  MeshContent c;
  c.materials = {std::move(bark), std::move(foliage)};
  for (int i = 0; i < 2; ++i) {
    c.objects.push_back(object(m.parts[size_t(i)], top, i));
    c.objects.back().provenance.tool = name;
  }
  return c;
}

MeshContent conifer() {
  Model m;
  trunk(m, 0.3, 0.032, 0.022, 10);
  struct Tier {
    double base, apex, radius;
  };
  const Tier tiers[] = {{0.12, 0.50, 0.27},
                        {0.30, 0.66, 0.22},
                        {0.47, 0.80, 0.17},
                        {0.62, 0.92, 0.12},
                        {0.76, 1.00, 0.07}};
  for (size_t i = 0; i < std::size(tiers); ++i)
    tier(m, tiers[i].base, tiers[i].apex, tiers[i].radius, 11, 0.9 * double(i));
  return finish(m, "builtin:conifer", colour("bark", 0.14f, 0.06f, 0.025f),
                colour("needles", 0.018f, 0.085f, 0.03f));
}

MeshContent broadleaf() {
  Model m;
  trunk(m, 0.56, 0.05, 0.032, 10);
  const Lobe lobes[] = {{{0, 0, 0.68}, 0.26},        {{0.17, 0.05, 0.60}, 0.2},
                        {{-0.12, 0.15, 0.62}, 0.2},  {{-0.1, -0.16, 0.6}, 0.19},
                        {{0.05, -0.02, 0.84}, 0.17}, {{0.12, -0.14, 0.74}, 0.17},
                        {{-0.14, 0, 0.78}, 0.17}};
  for (size_t i = 0; i < std::size(lobes); ++i) lobe(m, lobes[i], 1, 0.1, 101 + i);
  return finish(m, "builtin:broadleaf", colour("bark", 0.1f, 0.07f, 0.045f),
                colour("leaves", 0.06f, 0.22f, 0.03f));
}

MeshContent shrub() {
  Model m;
  trunk(m, 0.15, 0.06, 0.05, 8);
  // The lowest lobes reach below the ground, flattened onto it.
  const Lobe lobes[] = {{{0, 0, 0.36}, 0.40},       {{0.35, 0.1, 0.26}, 0.32},
                        {{-0.3, 0.2, 0.26}, 0.32},  {{-0.1, -0.33, 0.24}, 0.3},
                        {{0.2, -0.28, 0.28}, 0.28}, {{0.1, 0.35, 0.26}, 0.28}};
  for (size_t i = 0; i < std::size(lobes); ++i) lobe(m, lobes[i], 0.8, 0.1, 201 + i);
  return finish(m, "builtin:shrub", colour("bark", 0.1f, 0.07f, 0.045f),
                colour("leaves", 0.13f, 0.2f, 0.035f));
}

}  // namespace

const std::vector<std::string>& builtin_prototype_names() {
  static const std::vector<std::string> names = {"builtin:conifer", "builtin:broadleaf",
                                                 "builtin:shrub"};
  return names;
}

namespace {
[[noreturn]] void unknown_prototype(std::string_view name) {
  std::string known;
  for (const std::string& n : builtin_prototype_names()) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown prototype '" + std::string(name) + "' (built in: " + known + ")");
}
}  // namespace

MeshContent make_builtin_prototype(std::string_view name) {
  if (name == "builtin:conifer") return conifer();
  if (name == "builtin:broadleaf") return broadleaf();
  if (name == "builtin:shrub") return shrub();
  unknown_prototype(name);
}

const MeshContent& builtin_prototype(std::string_view name) {
  static const std::map<std::string, MeshContent, std::less<>> prototypes = [] {
    std::map<std::string, MeshContent, std::less<>> all;
    for (const std::string& n : builtin_prototype_names())
      all.emplace(n, make_builtin_prototype(n));
    return all;
  }();
  const auto it = prototypes.find(name);
  if (it == prototypes.end()) unknown_prototype(name);
  return it->second;
}

}  // namespace maquette
