#include "content_fixture.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace maquette::test {

std::string encoded_image(const std::string& driver, int w, int h) {
  GDALAllRegister();
  GDALDataset* mem =
      GetGDALDriverManager()->GetDriverByName("MEM")->Create("", w, h, 3, GDT_Byte, nullptr);
  std::vector<uint8_t> band(size_t(w) * h);
  for (int b = 1; b <= 3; ++b) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        band[size_t(y) * w + x] = uint8_t((x * 7 + y * 3 * b + b * 60) % 256);
    EXPECT_EQ(
        mem->GetRasterBand(b)->RasterIO(GF_Write, 0, 0, w, h, band.data(), w, h, GDT_Byte, 0, 0),
        CE_None);
  }
  const std::string path = "/vsimem/content_fixture_image";
  GDALDataset* out = GetGDALDriverManager()
                         ->GetDriverByName(driver.c_str())
                         ->CreateCopy(path.c_str(), mem, false, nullptr, nullptr, nullptr);
  GDALClose(out);
  GDALClose(mem);
  vsi_l_offset size = 0;
  GByte* bytes = VSIGetMemFileBuffer(path.c_str(), &size, false);
  std::string image(reinterpret_cast<const char*>(bytes), size);
  VSIUnlink(path.c_str());
  return image;
}

MeshObject box(std::array<float, 3> corner, std::array<float, 3> size) {
  MeshObject o;
  // Per face: the axis of its normal, its sign; the two other axes in counter-clockwise order.
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const uint32_t base = uint32_t(o.positions.size() / 3);
      const float corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (const auto& c : corners) {
        std::array<float, 3> p;
        p[axis] = corner[axis] + (sign > 0 ? size[axis] : 0);
        p[u] = corner[u] + c[0] * size[u];
        p[v] = corner[v] + c[1] * size[v];
        o.positions.insert(o.positions.end(), p.begin(), p.end());
        std::array<float, 3> n{0, 0, 0};
        n[axis] = float(sign);
        o.normals.insert(o.normals.end(), n.begin(), n.end());
        o.uvs.insert(o.uvs.end(), {0.13f + 0.7f * c[0], 0.87f - 0.7f * c[1]});
      }
      // (u, v, axis) is right-handed: corners 0 1 2 3 turn counter-clockwise seen from +axis.
      if (sign > 0)
        o.indices.insert(o.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
      else
        o.indices.insert(o.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
    }
  return o;
}

MeshObject sphere(std::array<float, 3> centre, float radius, int slices, int stacks) {
  MeshObject o;
  for (int i = 0; i <= stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const double phi = std::numbers::pi * i / stacks, theta = 2 * std::numbers::pi * j / slices;
      const double n[3] = {std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta),
                           std::cos(phi)};
      for (int a = 0; a < 3; ++a) {
        o.positions.push_back(float(centre[a] + radius * n[a]));
        o.normals.push_back(float(n[a]));
      }
    }
  const auto at = [&](int i, int j) { return uint32_t(i * slices + (j % slices)); };
  for (int i = 0; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      // Seen from outside, (i, j) -> (i + 1, j) -> (i + 1, j + 1) turns counter-clockwise.
      if (i > 0) o.indices.insert(o.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i < stacks - 1)
        o.indices.insert(o.indices.end(), {at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)});
    }
  return o;
}

namespace {

std::array<double, 3> vec(const std::vector<float>& v, size_t i) {
  return {v[i * 3], v[i * 3 + 1], v[i * 3 + 2]};
}

// The largest difference of a coordinate (quantization is per coordinate).
double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

double angle(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::acos(
      std::clamp(dot / std::hypot(a[0], a[1], a[2]) / std::hypot(b[0], b[1], b[2]), -1.0, 1.0));
}

}  // namespace

MeshDifference compare_meshes(const MeshObject& a, const MeshObject& b) {
  MeshDifference d;
  EXPECT_EQ(a.indices.size(), b.indices.size());
  EXPECT_EQ(a.normals.empty(), b.normals.empty());
  EXPECT_EQ(a.uvs.empty(), b.uvs.empty());
  for (size_t t = 0; t < b.indices.size(); t += 3) {
    double best = INFINITY;
    size_t best_t = 0;
    int best_r = 0;
    for (size_t s = 0; s < a.indices.size(); s += 3)
      for (int r = 0; r < 3; ++r) {
        double worst = 0;
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, distance(vec(a.positions, a.indices[s + (c + r) % 3]),
                                           vec(b.positions, b.indices[t + c])));
        if (worst < best) best = worst, best_t = s, best_r = r;
      }
    EXPECT_LT(best, 0.1) << "triangle " << t / 3 << " has no counterpart";
    d.position = std::max(d.position, best);
    for (int c = 0; c < 3; ++c) {
      const uint32_t va = a.indices[best_t + (c + best_r) % 3], vb = b.indices[t + c];
      if (!a.normals.empty() && !b.normals.empty())
        d.normal = std::max(d.normal, angle(vec(a.normals, va), vec(b.normals, vb)));
      if (!a.uvs.empty() && !b.uvs.empty())
        for (int k = 0; k < 2; ++k)
          d.uv = std::max(d.uv, double(std::abs(a.uvs[va * 2 + k] - b.uvs[vb * 2 + k])));
    }
  }
  return d;
}

}  // namespace maquette::test
