#include "importers/meshing/label_surface.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDiscreteFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>
#include <vtkSmartPointer.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <algorithm>
#include <chrono>

#include "core/error.h"
#include "importers/meshing/label_crop.h"

namespace viscera::importers {
namespace {

/// VTK works in millimetres: the filters' tolerances assume coordinates well above 1e-3.
constexpr double kMillimetresPerMetre = 1000.0;

/// The crop as a 0/1 image in millimetres, its voxel (0,0,0) at the origin.
vtkSmartPointer<vtkImageData> indicator_image(const core::LabelMap& labels, const LabelCrop& crop) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(crop.dims[0], crop.dims[1], crop.dims[2]);
  const core::Vec3 spacing = labels.image.spacing * kMillimetresPerMetre;
  image->SetSpacing(spacing.x(), spacing.y(), spacing.z());
  image->SetOrigin(0.0, 0.0, 0.0);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  std::transform(crop.labels.begin(), crop.labels.end(), out,
                 [](std::uint16_t value) { return value != 0 ? 1 : 0; });
  return image;
}

/// Triangles of `polydata` in the map's world frame (metres), wound so that a positive direction
/// determinant keeps VTK's orientation (repair orients outward afterwards anyway).
core::SurfaceMesh to_world(vtkPolyData& polydata, const core::LabelMap& labels,
                           const LabelCrop& crop) {
  core::SurfaceMesh mesh;
  const core::Vec3 origin = crop_origin(labels, crop);
  const core::Mat3& direction = labels.image.direction;
  vtkPoints* points = polydata.GetPoints();
  const vtkIdType n = points != nullptr ? points->GetNumberOfPoints() : 0;
  mesh.vertices.reserve(static_cast<std::size_t>(n));
  for (vtkIdType p = 0; p < n; ++p) {
    double x[3];
    points->GetPoint(p, x);
    mesh.vertices.push_back(origin +
                            direction * (core::Vec3(x[0], x[1], x[2]) / kMillimetresPerMetre));
  }
  const bool mirror = direction.determinant() < 0.0;
  vtkCellArray* polys = polydata.GetPolys();
  mesh.triangles.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()));
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c) {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    polys->GetCellAtId(c, size, ids);
    if (size != 3) continue;
    core::Triangle t{static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2])};
    if (mirror) std::swap(t[1], t[2]);
    mesh.triangles.push_back(t);
  }
  return mesh;
}

/// Runs `filter` so that a cancellation of `progress` stops it at its next progress report
/// (VTK's AbortExecute), then throws CancelledError.
void update_cancellable(vtkAlgorithm& filter, core::Progress& progress) {
  auto observer = vtkSmartPointer<vtkCallbackCommand>::New();
  observer->SetClientData(&progress);
  observer->SetCallback([](vtkObject* caller, unsigned long, void* client, void*) {
    if (static_cast<core::Progress*>(client)->cancelled())
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
  });
  const unsigned long tag = filter.AddObserver(vtkCommand::ProgressEvent, observer);
  filter.Update();
  filter.RemoveObserver(tag);
  progress.check_cancelled();
}

/// Seconds since `start`, and restarts it.
double lap(std::chrono::steady_clock::time_point& start) {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start).count();
  start = now;
  return seconds;
}

}  // namespace

LabelSurface label_surface(const core::LabelMap& labels, int label,
                           const LabelSurfaceOptions& options, const std::string& what,
                           core::Progress& progress) {
  if (options.smoothing_iterations < 0 || !(options.pass_band > 0.0 && options.pass_band < 2.0)) {
    throw core::UsageError("smoothing needs iterations ≥ 0 and a pass band in (0, 2)");
  }
  progress.begin_stage("label " + std::to_string(label) + " surface", 4);
  LabelSurface result;
  result.label = label;
  auto clock = std::chrono::steady_clock::now();
  // One voxel of background on each side closes surfaces that touch the map's border.
  const LabelCrop crop = crop_labels(labels, label, 1, what);
  const auto image = indicator_image(labels, crop);

  auto contour = vtkSmartPointer<vtkDiscreteFlyingEdges3D>::New();
  contour->SetInputData(image);
  contour->SetValue(0, 1.0);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  update_cancellable(*contour, progress);
  vtkSmartPointer<vtkPolyData> surface = contour->GetOutput();
  result.extracted_triangles = static_cast<std::size_t>(surface->GetNumberOfPolys());
  result.seconds["contour"] = lap(clock);
  progress.step();

  if (options.smoothing_iterations > 0) {
    auto smoother = vtkSmartPointer<vtkWindowedSincPolyDataFilter>::New();
    smoother->SetInputData(surface);
    smoother->SetNumberOfIterations(options.smoothing_iterations);
    smoother->SetPassBand(options.pass_band);
    smoother->BoundarySmoothingOff();
    smoother->FeatureEdgeSmoothingOff();
    smoother->NonManifoldSmoothingOn();
    smoother->NormalizeCoordinatesOn();
    update_cancellable(*smoother, progress);
    surface = smoother->GetOutput();
  }
  result.seconds["smoothing"] = lap(clock);
  progress.step();

  // Quadric decimation does not guard against folds and strong smoothing can fold a thin part:
  // when repair refuses a surface (it intersects itself), decimate again to twice the budget,
  // then keep the smoothed surface whole, and last the unsmoothed contour (marching cubes of a
  // padded binary image, which never intersects itself).
  const vtkSmartPointer<vtkPolyData> smoothed = surface;
  std::size_t budget = options.target_triangles;
  bool smoothing = options.smoothing_iterations > 0;
  for (;;) {
    progress.check_cancelled();
    const bool decimating = smoothing && budget > 0 && budget < result.extracted_triangles;
    surface = smoothing ? smoothed : vtkSmartPointer<vtkPolyData>(contour->GetOutput());
    if (decimating) {
      auto decimate = vtkSmartPointer<vtkQuadricDecimation>::New();
      decimate->SetInputData(smoothed);
      decimate->SetTargetReduction(1.0 - static_cast<double>(budget) /
                                             static_cast<double>(result.extracted_triangles));
      decimate->VolumePreservationOn();
      update_cancellable(*decimate, progress);
      surface = decimate->GetOutput();
    }
    result.seconds["decimation"] += lap(clock);
    result.mesh = to_world(*surface, labels, crop);
    try {
      result.repair = repair_closed_surface(result.mesh, what);
      result.seconds["repair"] += lap(clock);
      break;
    } catch (const core::ValidationError& e) {
      result.seconds["repair"] += lap(clock);
      if (decimating) {
        ++result.decimation_retries;
        budget *= 2;
      } else if (smoothing) {
        smoothing = false;
        result.smoothing_dropped = true;
      } else {
        throw core::ValidationError(e.reason(),
                                    {what, "",
                                     label == 0 ? std::string("surface of all labels")
                                                : "surface of label " + std::to_string(label)});
      }
    }
  }
  progress.step();
  core::compute_vertex_normals(result.mesh);
  result.seconds["repair"] += lap(clock);
  progress.step();
  return result;
}

}  // namespace viscera::importers
