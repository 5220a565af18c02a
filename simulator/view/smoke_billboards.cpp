#include "simulator/view/smoke_billboards.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace viscera::view {

namespace {

/// A hash of a lattice point to [0, 1), wrapping with `period`.
double lattice(int x, int y, int period) {
  auto h = static_cast<std::uint32_t>(((x % period + period) % period) * 73856093U) ^
           static_cast<std::uint32_t>(((y % period + period) % period) * 19349663U);
  h ^= h >> 13U;
  h *= 0x5bd1e995U;
  h ^= h >> 15U;
  return (h & 0xFFFFFFU) / static_cast<double>(0x1000000U);
}

/// Value noise with smooth interpolation, period `period` lattice cells.
double value_noise(double x, double y, int period) {
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  const double sx = fx * fx * (3.0 - 2.0 * fx), sy = fy * fy * (3.0 - 2.0 * fy);
  const double a = lattice(x0, y0, period), b = lattice(x0 + 1, y0, period);
  const double c = lattice(x0, y0 + 1, period), d = lattice(x0 + 1, y0 + 1, period);
  return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
}

}  // namespace

vtkSmartPointer<vtkImageData> smoke_texture(int size) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      // Turbulence: Σ |2n − 1| / 2^o over four octaves (Perlin's turbulence with value noise).
      double turbulence = 0.0, norm = 0.0;
      for (int o = 0; o < 4; ++o) {
        const int period = 4 << o;
        const double scale = static_cast<double>(period) / size;
        turbulence += std::abs(2.0 * value_noise(i * scale, j * scale, period) - 1.0) / (1 << o);
        norm += 1.0 / (1 << o);
      }
      turbulence /= norm;
      // Transparent towards the circle's rim (seed 001 §4.2).
      const double u = (i + 0.5) / size - 0.5, v = (j + 0.5) / size - 0.5;
      const double falloff = std::clamp(1.0 - 2.0 * std::hypot(u, v), 0.0, 1.0);
      auto* texel = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
      texel[0] = texel[1] = texel[2] = 255;
      texel[3] = static_cast<unsigned char>(
          std::lround(255.0 * std::clamp(falloff * falloff * (0.35 + 0.9 * turbulence), 0.0, 1.0)));
    }
  return image;
}

SmokeBillboards::SmokeBillboards(vtkRenderer* scene) {
  quads_ = vtkSmartPointer<vtkPolyData>::New();
  quads_->SetPoints(vtkSmartPointer<vtkPoints>::New());
  quads_->SetPolys(vtkSmartPointer<vtkCellArray>::New());
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(quads_);
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUsePointData();
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(smoke_texture(kTextureSize));
  texture->InterpolateOn();
  texture->RepeatOff();
  texture->EdgeClampOn();
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
  actor_->SetTexture(texture);
  vtkProperty* look = actor_->GetProperty();
  look->LightingOff();  // smoke scatters the head light back: self-lit
  look->SetBackfaceCulling(false);
  actor_->ForceTranslucentOn();
  actor_->SetVisibility(false);
  scene->AddActor(actor_);
}

SmokeBillboards::~SmokeBillboards() = default;

void SmokeBillboards::update(const std::vector<sim::SmokeBillboard>& puffs, const core::Vec3& right,
                             const core::Vec3& up) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(4 * puffs.size()));
  auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(static_cast<vtkIdType>(4 * puffs.size()));
  tcoords->SetName("TCoords");
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetNumberOfComponents(4);
  colours->SetNumberOfTuples(static_cast<vtkIdType>(4 * puffs.size()));
  colours->SetName("Colours");
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const double corner_u[4] = {-1, 1, 1, -1}, corner_v[4] = {-1, -1, 1, 1};
  for (std::size_t k = 0; k < puffs.size(); ++k) {
    const sim::SmokeBillboard& p = puffs[k];
    // One of the texture's eight symmetries per puff (transposed, mirrored), so neighbouring
    // puffs do not repeat one pattern while the rim stays transparent.
    const int symmetry = p.index % 8;
    const auto alpha =
        static_cast<unsigned char>(std::lround(255.0 * std::clamp(p.opacity, 0.0, 1.0)));
    vtkIdType ids[4];
    for (int c = 0; c < 4; ++c) {
      const auto id = static_cast<vtkIdType>(4 * k + static_cast<std::size_t>(c));
      const core::Vec3 x = p.centre + p.radius * (corner_u[c] * right + corner_v[c] * up);
      points->SetPoint(id, x.data());
      double u = 0.5 * (corner_u[c] + 1.0), v = 0.5 * (corner_v[c] + 1.0);
      if (symmetry & 1) std::swap(u, v);
      if (symmetry & 2) u = 1.0 - u;
      if (symmetry & 4) v = 1.0 - v;
      tcoords->SetTuple2(id, u, v);
      colours->SetTuple4(id, 222, 220, 214, alpha);
      ids[c] = id;
    }
    polys->InsertNextCell(4, ids);
  }
  quads_->SetPoints(points);
  quads_->SetPolys(polys);
  quads_->GetPointData()->SetTCoords(tcoords);
  quads_->GetPointData()->SetScalars(colours);
  quads_->Modified();
  size_ = puffs.size();
  actor_->SetVisibility(!puffs.empty());
}

}  // namespace viscera::view
