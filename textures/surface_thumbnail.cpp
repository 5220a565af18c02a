#include "textures/surface_thumbnail.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace viscera::textures {
namespace {

constexpr std::uint8_t kBackground[3] = {40, 44, 52};
constexpr double kTissue[3] = {222.0, 140.0, 140.0};

}  // namespace

Image8 render_surface_thumbnail(const core::SurfaceMesh& surface, int size) {
  if (size < 16 || size > 1024)
    throw core::UsageError("a thumbnail is 16 to 1024 pixels wide, not " + std::to_string(size));
  if (surface.vertices.empty() || surface.triangles.empty())
    throw core::UsageError("cannot draw a thumbnail of an empty surface");
  core::Vec3 low = surface.vertices.front(), high = low;
  for (const auto& v : surface.vertices) {
    if (!v.allFinite()) throw core::UsageError("cannot draw a thumbnail of a non-finite surface");
    low = low.cwiseMin(v);
    high = high.cwiseMax(v);
  }
  const core::Vec3 centre = 0.5 * (low + high);
  double radius = 0.0;
  for (const auto& v : surface.vertices)
    radius = std::max(radius, (v - centre).norm());
  if (!(radius > 0.0)) radius = 1.0;

  // Camera frame: looking along −view, z up on the image where possible.
  const core::Vec3 view = core::Vec3(1.0, -1.5, 1.0).normalized();  // towards the viewer
  const core::Vec3 right = core::Vec3::UnitZ().cross(view).normalized();
  const core::Vec3 up = view.cross(right);
  const double scale = 0.45 * size / radius;  // the bounding sphere spans 90 % of the width
  const double half = 0.5 * size;

  Image8 image(size, size, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = kBackground[i % 3];
  std::vector<double> depth(static_cast<std::size_t>(size) * size,
                            -std::numeric_limits<double>::infinity());
  std::vector<core::Vec3> screen;  // x, y in pixels (y down), z towards the viewer
  screen.reserve(surface.vertices.size());
  for (const auto& v : surface.vertices) {
    const core::Vec3 d = v - centre;
    screen.emplace_back(half + scale * d.dot(right), half - scale * d.dot(up), d.dot(view));
  }
  for (const auto& t : surface.triangles) {
    const core::Vec3& a = screen[static_cast<std::size_t>(t[0])];
    const core::Vec3& b = screen[static_cast<std::size_t>(t[1])];
    const core::Vec3& c = screen[static_cast<std::size_t>(t[2])];
    const core::Vec3 normal = (surface.vertices[static_cast<std::size_t>(t[1])] -
                               surface.vertices[static_cast<std::size_t>(t[0])])
                                  .cross(surface.vertices[static_cast<std::size_t>(t[2])] -
                                         surface.vertices[static_cast<std::size_t>(t[0])]);
    const double length = normal.norm();
    if (!(length > 0.0)) continue;
    // A headlight on both sides, plus ambient light.
    const double shade = 0.25 + 0.75 * std::abs(normal.dot(view)) / length;
    const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (std::abs(area) < 1e-12) continue;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int x1 = std::min(size - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int y1 = std::min(size - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        // Barycentric weights from edge functions; the sign of `area` covers both windings.
        const double w0 = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) / area;
        const double w1 = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) / area;
        const double w2 = 1.0 - w0 - w1;
        if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
        const double z = w0 * a.z() + w1 * b.z() + w2 * c.z();
        double& stored = depth[static_cast<std::size_t>(y) * size + x];
        if (z <= stored) continue;
        stored = z;
        std::uint8_t* pixel = image.row(y) + 3 * x;
        for (int k = 0; k < 3; ++k)
          pixel[k] = static_cast<std::uint8_t>(std::lround(std::min(255.0, kTissue[k] * shade)));
      }
    }
  }
  return image;
}

Image8 image_thumbnail(const Image8& image, int size) {
  if (size < 16 || size > 1024)
    throw core::UsageError("a thumbnail is 16 to 1024 pixels wide, not " + std::to_string(size));
  if (image.empty() || image.width <= 0 || image.height <= 0)
    throw core::UsageError("cannot make a thumbnail of an empty image");
  const double scale = static_cast<double>(size) / std::max(image.width, image.height);
  const int width = std::max(1, static_cast<int>(std::lround(image.width * scale)));
  const int height = std::max(1, static_cast<int>(std::lround(image.height * scale)));
  const cv::Mat source(image.height, image.width, image.channels == 1 ? CV_8UC1 : CV_8UC3,
                       const_cast<std::uint8_t*>(image.pixels.data()));
  cv::Mat scaled;
  cv::resize(source, scaled, cv::Size(width, height), 0.0, 0.0, cv::INTER_AREA);
  if (image.channels == 1) cv::cvtColor(scaled, scaled, cv::COLOR_GRAY2RGB);
  Image8 result(width, height, 3);
  for (int y = 0; y < height; ++y)
    std::copy_n(scaled.ptr<std::uint8_t>(y), 3 * width, result.row(y));
  return result;
}

Image8 render_stress_strain_thumbnail(const core::StressStrainCurve& curve, int size) {
  if (size < 16 || size > 1024)
    throw core::UsageError("a thumbnail is 16 to 1024 pixels wide, not " + std::to_string(size));
  if (curve.cubic.size() != 4) throw core::UsageError("the stress-strain curve has no cubic fit");
  const auto sigma = [&](double e) {
    return curve.cubic[1] * e + curve.cubic[2] * e * std::abs(e) + curve.cubic[3] * e * e * e;
  };
  double max_strain = 0.0, max_stress = 0.0;
  for (const double e : curve.strain)
    max_strain = std::max(max_strain, std::abs(e));
  if (!(max_strain > 0.0)) max_strain = 0.3;
  for (const double s : curve.stress)
    max_stress = std::max(max_stress, s);
  const int margin = size / 10, span = size - 2 * margin;
  for (int i = 0; i <= span; ++i)
    max_stress = std::max(max_stress, sigma(max_strain * i / span));
  if (!(max_stress > 0.0) || !std::isfinite(max_stress)) max_stress = 1.0;
  const auto column = [&](double e) { return margin + e / max_strain * span; };
  const auto row = [&](double s) { return size - 1 - margin - s / max_stress * span; };

  Image8 image(size, size, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = kBackground[i % 3];
  const auto put = [&](int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    if (x < 0 || y < 0 || x >= size || y >= size) return;
    std::uint8_t* p = image.row(y) + 3 * x;
    p[0] = r;
    p[1] = g;
    p[2] = b;
  };
  for (int i = 0; i <= span; ++i) {  // axes through the origin
    put(margin + i, size - 1 - margin, 140, 140, 150);
    put(margin, size - 1 - margin - i, 140, 140, 150);
  }
  // The cubic, one pixel column at a time, joined vertically so steep parts stay connected.
  int previous = static_cast<int>(std::lround(row(0.0)));
  for (int i = 0; i <= span; ++i) {
    const int y = static_cast<int>(std::lround(
        std::clamp(row(sigma(max_strain * i / span)), -1.0, static_cast<double>(size))));
    for (int v = std::min(previous, y); v <= std::max(previous, y); ++v)
      put(margin + i, v, static_cast<std::uint8_t>(kTissue[0]),
          static_cast<std::uint8_t>(kTissue[1]), static_cast<std::uint8_t>(kTissue[2]));
    previous = y;
  }
  for (std::size_t k = 0; k < curve.strain.size() && k < curve.stress.size(); ++k) {
    if (curve.strain[k] < 0.0 || curve.stress[k] < 0.0) continue;  // the plot shows tension
    const int x = static_cast<int>(std::lround(column(curve.strain[k])));
    const int y = static_cast<int>(std::lround(row(curve.stress[k])));
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        put(x + dx, y + dy, 235, 235, 235);
  }
  return image;
}

}  // namespace viscera::textures
