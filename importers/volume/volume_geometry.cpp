#include "importers/volume/volume_geometry.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkImageReader2.h>
#include <vtkInformation.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkType.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "core/crash_guard.h"
#include "core/error.h"
#include "importers/vtk_error_capture.h"

namespace viscera::importers::detail {
namespace {

/// Copies component `component` of every tuple of `array` into `out` as T.
template <typename T>
void copy_component(vtkDataArray& array, int component, core::ImageVolume& out) {
  const vtkIdType n = array.GetNumberOfTuples();
  auto* target = reinterpret_cast<T*>(out.voxels.data());
  for (vtkIdType t = 0; t < n; ++t)
    target[t] = static_cast<T>(array.GetComponent(t, component));
}

bool integral(double value) {
  return std::isfinite(value) && value == std::round(value);
}

template <typename T>
void rescale_into(const core::ImageVolume& in, double slope, double intercept,
                  core::ImageVolume& out) {
  auto* target = reinterpret_cast<T*>(out.voxels.data());
  const std::size_t n = in.voxel_count();
  for (std::size_t v = 0; v < n; ++v) {
    const double value = slope * in.value(v) + intercept;
    target[v] = static_cast<T>(std::is_integral_v<T> ? std::round(value) : value);
  }
}

}  // namespace

std::uint64_t check_voxel_budget(const std::array<std::int64_t, 3>& dims, std::int64_t components,
                                 std::int64_t bytes_per_component, const VolumeReadOptions& options,
                                 const std::string& file) {
  for (const auto d : dims) {
    if (d <= 0) {
      throw core::InputError("header gives a non-positive size " + std::to_string(dims[0]) + "×" +
                                 std::to_string(dims[1]) + "×" + std::to_string(dims[2]),
                             {file, "", ""});
    }
  }
  // Multiply in long double: a hostile header must not overflow the check itself.
  const long double bytes = static_cast<long double>(dims[0]) * dims[1] * dims[2] *
                            std::max<std::int64_t>(components, 1) *
                            std::max<std::int64_t>(bytes_per_component, 1);
  if (bytes > static_cast<long double>(options.max_bytes)) {
    throw core::InputError(
        "header claims " + std::to_string(dims[0]) + "×" + std::to_string(dims[1]) + "×" +
            std::to_string(dims[2]) + " voxels (" +
            std::to_string(static_cast<unsigned long long>(bytes / (1024.0L * 1024.0L))) +
            " MiB), more than the memory limit of " +
            std::to_string(options.max_bytes / (1024 * 1024)) + " MiB",
        {file, "", ""});
  }
  return static_cast<std::uint64_t>(bytes);
}

std::uint64_t check_reader_budget(vtkImageReader2& reader, const VolumeReadOptions& options,
                                  const std::string& file) {
  if (!core::survives_in_child([&] { reader.UpdateInformation(); })) {
    throw core::InputError(
        "the header is damaged: VTK's reader crashes, hangs or exhausts its memory on it",
        {file, "", ""});
  }
  std::string error;
  {
    VtkErrorCapture capture;
    reader.UpdateInformation();
    error = capture.first_error();
  }
  if (!error.empty()) throw core::InputError("cannot read the header: " + error, {file, "", ""});
  vtkInformation* info = reader.GetOutputInformation(0);
  if (info == nullptr || !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT())) {
    throw core::InputError("cannot read the header", {file, "", ""});
  }
  int extent[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  const std::array<std::int64_t, 3> dims{std::int64_t{extent[1]} - extent[0] + 1,
                                         std::int64_t{extent[3]} - extent[2] + 1,
                                         std::int64_t{extent[5]} - extent[4] + 1};
  const int type = vtkImageData::GetScalarType(info);
  const int components = vtkImageData::GetNumberOfScalarComponents(info);
  int type_size = 0;
  {
    VtkErrorCapture capture;  // VTK warns on the terminal about a type it does not know
    type_size = vtkDataArray::GetDataTypeSize(type);
  }
  if (type_size <= 0)
    throw core::InputError("the header declares a voxel type VTK cannot hold", {file, "", ""});
  return check_voxel_budget(dims, components, type_size, options, file);
}

core::ImageVolume volume_from_vtk_image(vtkImageData& image, const std::string& file,
                                        std::vector<std::string>& notes) {
  vtkDataArray* scalars = image.GetPointData()->GetScalars();
  int dims[3];
  image.GetDimensions(dims);
  if (scalars == nullptr || scalars->GetNumberOfTuples() == 0 || dims[0] <= 0 || dims[1] <= 0 ||
      dims[2] <= 0) {
    throw core::InputError("file holds no voxels", {file, "", ""});
  }
  core::ImageVolume volume;
  volume.dims = {dims[0], dims[1], dims[2]};
  if (static_cast<std::size_t>(scalars->GetNumberOfTuples()) != volume.voxel_count()) {
    throw core::InputError("voxel count does not match the dimensions", {file, "", ""});
  }
  const int components = scalars->GetNumberOfComponents();
  if (components == 3 || components == 4) {
    // Colour voxels (RGB, RGBA) become luminance, Rec. 601: Y = 0.299 R + 0.587 G + 0.114 B.
    volume.scalar_type = core::ScalarType::Float32;
    volume.allocate();
    auto* target = reinterpret_cast<float*>(volume.voxels.data());
    for (vtkIdType t = 0; t < scalars->GetNumberOfTuples(); ++t) {
      target[t] = static_cast<float>(0.299 * scalars->GetComponent(t, 0) +
                                     0.587 * scalars->GetComponent(t, 1) +
                                     0.114 * scalars->GetComponent(t, 2));
    }
    notes.push_back("colour voxels converted to luminance");
    return volume;
  }
  if (components != 1) {
    notes.push_back("first of " + std::to_string(components) + " components read");
  }
  switch (scalars->GetDataType()) {
    case VTK_UNSIGNED_CHAR:
      volume.scalar_type = core::ScalarType::UInt8;
      break;
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_SHORT:
      volume.scalar_type = core::ScalarType::Int16;
      break;
    case VTK_UNSIGNED_SHORT:
      volume.scalar_type = core::ScalarType::UInt16;
      break;
    case VTK_INT:
      volume.scalar_type = core::ScalarType::Int32;
      break;
    case VTK_FLOAT:
      volume.scalar_type = core::ScalarType::Float32;
      break;
    default:
      volume.scalar_type = core::ScalarType::Float64;
      break;  // uint32, 64-bit, double
  }
  volume.allocate();
  const int type = scalars->GetDataType();
  const bool same_type = type == VTK_UNSIGNED_CHAR || type == VTK_SHORT ||
                         type == VTK_UNSIGNED_SHORT || type == VTK_INT || type == VTK_FLOAT ||
                         type == VTK_DOUBLE;
  if (components == 1 && same_type) {
    std::memcpy(volume.voxels.data(), scalars->GetVoidPointer(0), volume.voxels.size());
    return volume;
  }
  switch (volume.scalar_type) {
    case core::ScalarType::UInt8:
      copy_component<std::uint8_t>(*scalars, 0, volume);
      break;
    case core::ScalarType::Int16:
      copy_component<std::int16_t>(*scalars, 0, volume);
      break;
    case core::ScalarType::UInt16:
      copy_component<std::uint16_t>(*scalars, 0, volume);
      break;
    case core::ScalarType::Int32:
      copy_component<std::int32_t>(*scalars, 0, volume);
      break;
    case core::ScalarType::Float32:
      copy_component<float>(*scalars, 0, volume);
      break;
    case core::ScalarType::Float64:
      copy_component<double>(*scalars, 0, volume);
      break;
  }
  return volume;
}

void set_geometry_mm(core::ImageVolume& volume, const core::Mat3& axes, const core::Vec3& origin,
                     bool ras, const std::string& file) {
  core::Mat3 lps_axes = axes;
  core::Vec3 lps_origin = origin;
  if (ras) {
    lps_axes.row(0) *= -1.0;
    lps_axes.row(1) *= -1.0;
    lps_origin.x() *= -1.0;
    lps_origin.y() *= -1.0;
  }
  if (!lps_axes.allFinite() || !lps_origin.allFinite()) {
    throw core::InputError("voxel-to-world transform holds NaN or infinite values", {file, "", ""});
  }
  for (int c = 0; c < 3; ++c) {
    const double length = lps_axes.col(c).norm();
    if (!(length > 0.0)) {
      throw core::InputError("voxel axis " + std::to_string(c) + " has zero length",
                             {file, "", ""});
    }
    volume.spacing[c] = 0.001 * length;
    volume.direction.col(c) = lps_axes.col(c) / length;
  }
  if (std::abs(volume.direction.determinant()) < 1e-6) {
    throw core::InputError("voxel axes are not independent (degenerate orientation)",
                           {file, "", ""});
  }
  volume.origin = 0.001 * lps_origin;
}

void apply_rescale(core::ImageVolume& volume, double slope, double intercept) {
  if (slope == 0.0 || !std::isfinite(slope) || !std::isfinite(intercept) ||
      (slope == 1.0 && intercept == 0.0)) {
    return;
  }
  core::ImageVolume out = volume;
  const bool is_float = volume.scalar_type == core::ScalarType::Float32 ||
                        volume.scalar_type == core::ScalarType::Float64;
  if (!is_float && integral(slope) && integral(intercept)) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t v = 0; v < volume.voxel_count(); ++v) {
      const double value = slope * volume.value(v) + intercept;
      lo = std::min(lo, value);
      hi = std::max(hi, value);
    }
    if (lo >= std::numeric_limits<std::int16_t>::min() &&
        hi <= std::numeric_limits<std::int16_t>::max()) {
      out.scalar_type = core::ScalarType::Int16;
    } else if (lo >= std::numeric_limits<std::int32_t>::min() &&
               hi <= std::numeric_limits<std::int32_t>::max()) {
      out.scalar_type = core::ScalarType::Int32;
    } else {
      out.scalar_type = core::ScalarType::Float64;
    }
  } else {
    out.scalar_type = volume.scalar_type == core::ScalarType::Float64 ? core::ScalarType::Float64
                                                                      : core::ScalarType::Float32;
  }
  out.allocate();
  switch (out.scalar_type) {
    case core::ScalarType::Int16:
      rescale_into<std::int16_t>(volume, slope, intercept, out);
      break;
    case core::ScalarType::Int32:
      rescale_into<std::int32_t>(volume, slope, intercept, out);
      break;
    case core::ScalarType::Float32:
      rescale_into<float>(volume, slope, intercept, out);
      break;
    default:
      rescale_into<double>(volume, slope, intercept, out);
      break;
  }
  volume = std::move(out);
}

void check_finite(const core::ImageVolume& volume, const std::string& file) {
  if (volume.scalar_type != core::ScalarType::Float32 &&
      volume.scalar_type != core::ScalarType::Float64) {
    return;
  }
  for (std::size_t v = 0; v < volume.voxel_count(); ++v) {
    if (!std::isfinite(volume.value(v))) {
      const std::size_t i = v % volume.dims[0];
      const std::size_t j = (v / volume.dims[0]) % volume.dims[1];
      const std::size_t k = v / (static_cast<std::size_t>(volume.dims[0]) * volume.dims[1]);
      throw core::InputError("voxel (" + std::to_string(i) + ", " + std::to_string(j) + ", " +
                                 std::to_string(k) + ") is NaN or infinite",
                             {file, "", ""});
    }
  }
}

}  // namespace viscera::importers::detail
