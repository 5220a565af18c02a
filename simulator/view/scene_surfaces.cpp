#include "simulator/view/scene_surfaces.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
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
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/mesh/surface_embedding.h"
#include "core/package/scenario_package.h"
#include "core/package/zip_archive.h"
#include "simulator/view/cut_face_colours.h"

namespace viscera::view {

std::string read_package_file(const std::filesystem::path& package, const std::string& name) {
  if (std::filesystem::is_directory(package)) {
    std::ifstream in(package / name, std::ios::binary);
    if (!in) throw core::InputError("cannot open", {(package / name).string(), "", ""});
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  }
  return core::read_zip_entry(package, name, {core::kMaxZipEntryBytes, core::kMaxPackageBytes});
}

vtkSmartPointer<vtkImageData> decode_png(const std::string& bytes, const std::string& what) {
  static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || bytes.compare(0, 8, reinterpret_cast<const char*>(kSignature), 8) != 0)
    throw core::InputError("is not a PNG image", {what, "", ""});
  vtkNew<vtkPNGReader> reader;
  reader->SetMemoryBuffer(bytes.data());
  reader->SetMemoryBufferLength(static_cast<vtkIdType>(bytes.size()));
  reader->Update();
  vtkSmartPointer<vtkImageData> image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] <= 0 || dims[1] <= 0 || image->GetNumberOfScalarComponents() < 3)
    throw core::InputError("is not an RGB PNG image", {what, "", ""});
  return image;
}

std::array<double, 3> mean_colour(vtkImageData* image) {
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const vtkIdType n = scalars->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      sum[static_cast<std::size_t>(c)] += scalars->GetComponent(i, c);
  for (double& s : sum)
    s /= static_cast<double>(std::max<vtkIdType>(1, n));
  return sum;
}

struct SceneSurfaces::Surface {
  std::string id;
  vtkSmartPointer<vtkPolyData> mesh;  ///< the skin
  vtkSmartPointer<vtkActor> actor;
  vtkSmartPointer<vtkImageData> texture;
  std::string body;  ///< name of the world body it follows, or ""
  const core::SurfaceEmbedding* embedding = nullptr;
  std::vector<core::Tetrahedron> tets;
  std::vector<core::Triangle> triangles;  ///< skin, then cut faces: both shape the normals
  std::vector<int> weld;  ///< per vertex, the first vertex at the same rest position (UV seams)
  /// Once cut: the surface shown, its cut faces (sharing the skin's points and normals) and
  /// their colours from the organ's solid texture (0…1, per vertex, zero off the cut faces).
  std::shared_ptr<const sim::CutVisibleSurface> cut;
  vtkSmartPointer<vtkPolyData> cut_faces;
  vtkSmartPointer<vtkActor> cut_actor;
  std::vector<std::array<double, 3>> cut_colours;
  std::string texture_preset;  ///< the object's TextureSpec preset ("": none)
  std::uint64_t texture_seed = 0;
  std::shared_ptr<const CutFaceColours> inside;  ///< made at the first cut
  /// The body's node positions and coagulated flags last shown: a body that did not move (an
  /// island asleep) keeps its geometry and colours, and nothing is computed or uploaded again.
  std::vector<core::Vec3> shown_positions;
  std::vector<float> shown_coagulated;
};

namespace {

/// Per vertex, the first vertex with bit-identical coordinates and the same `side` (when
/// given): texture atlases split vertices along seams, and their normals must still agree or the
/// seams show as creases; a cut face's corner is not welded to the skin's, so the cut's rim
/// stays sharp.
std::vector<int> weld_map(const std::vector<core::Vec3>& points,
                          const std::vector<double>* side = nullptr) {
  std::map<std::array<double, 4>, int> first;
  std::vector<int> weld(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double s = side != nullptr ? (*side)[i] : 0.0;
    const auto [it, inserted] =
        first.try_emplace({points[i].x(), points[i].y(), points[i].z(), s}, static_cast<int>(i));
    weld[i] = it->second;
  }
  return weld;
}

/// The wet-mucosa look of every surface: mostly diffuse under the head light with a tight
/// specular highlight.
void set_tissue_lighting(vtkProperty* property) {
  property->SetAmbient(0.08);
  property->SetDiffuse(0.9);
  property->SetSpecular(0.25);
  property->SetSpecularPower(30.0);
}

/// Fills `colours` (RGB bytes) from `base` × the coagulated tint at each vertex's share
/// (`share[v].x()`, 0…1; null share: none).
void fill_colours(vtkUnsignedCharArray* colours, const std::vector<std::array<double, 3>>& base,
                  const std::vector<core::Vec3>* share, const std::array<double, 3>& tint) {
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(static_cast<vtkIdType>(base.size()));
  for (std::size_t v = 0; v < base.size(); ++v) {
    const double s = share != nullptr ? std::clamp((*share)[v].x(), 0.0, 1.0) : 0.0;
    for (std::size_t c = 0; c < 3; ++c) {
      const double factor = 1.0 + s * (tint[c] - 1.0);
      colours->SetComponent(static_cast<vtkIdType>(v), static_cast<int>(c),
                            std::round(255.0 * base[v][c] * factor));
    }
  }
  colours->Modified();
}

/// Writes positions and area-weighted unit normals (shared across welded vertices) into `mesh`.
void set_geometry(vtkPolyData* mesh, const std::vector<core::Vec3>& points,
                  const std::vector<core::Triangle>& triangles, const std::vector<int>& weld) {
  vtkPoints* positions = mesh->GetPoints();
  positions->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    positions->SetPoint(static_cast<vtkIdType>(i), points[i].data());
  positions->Modified();
  std::vector<core::Vec3> normals(points.size(), core::Vec3::Zero());
  for (const core::Triangle& t : triangles) {
    const core::Vec3 n =
        (points[static_cast<std::size_t>(t[1])] - points[static_cast<std::size_t>(t[0])])
            .cross(points[static_cast<std::size_t>(t[2])] - points[static_cast<std::size_t>(t[0])]);
    for (int v : t)
      normals[static_cast<std::size_t>(weld[static_cast<std::size_t>(v)])] += n;
  }
  for (std::size_t i = 0; i < normals.size(); ++i)
    normals[i] = normals[static_cast<std::size_t>(weld[i])];
  auto* array = vtkFloatArray::SafeDownCast(mesh->GetPointData()->GetNormals());
  array->SetNumberOfTuples(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const double length = normals[i].norm();
    const core::Vec3 n = length > 0.0 ? core::Vec3(normals[i] / length) : core::Vec3::UnitZ();
    array->SetTuple3(static_cast<vtkIdType>(i), n.x(), n.y(), n.z());
  }
  // Only the point and normal arrays changed: VTK re-uploads just those two vertex buffers
  // (the index buffer and texture coordinates keep their upload, their times being older).
  array->Modified();
}

vtkSmartPointer<vtkPolyData> make_mesh(const std::vector<core::Vec3>& points,
                                       const std::vector<core::Triangle>& triangles,
                                       const std::vector<core::Vec2>& uvs,
                                       const std::vector<int>& weld) {
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> positions;
  positions->SetDataTypeToFloat();  // uploaded as is: no double-to-float pass per frame
  mesh->SetPoints(positions);
  vtkNew<vtkCellArray> polys;
  for (const core::Triangle& t : triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  mesh->SetPolys(polys);
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetName("Normals");
  mesh->GetPointData()->SetNormals(normals);
  if (uvs.size() == points.size()) {
    vtkNew<vtkFloatArray> tcoords;
    tcoords->SetNumberOfComponents(2);
    tcoords->SetName("TextureCoordinates");
    tcoords->SetNumberOfTuples(static_cast<vtkIdType>(uvs.size()));
    for (std::size_t i = 0; i < uvs.size(); ++i)
      tcoords->SetTuple2(static_cast<vtkIdType>(i), uvs[i].x(), uvs[i].y());
    mesh->GetPointData()->SetTCoords(tcoords);
  }
  set_geometry(mesh, points, triangles, weld);
  return mesh;
}

}  // namespace

SceneSurfaces::SceneSurfaces(const core::Scenario& scenario, const std::filesystem::path& package) {
  for (const core::SceneObject& object : scenario.objects) {
    if (object.role == core::ObjectRole::Instrument) continue;
    const bool simulated = object.body_kind == core::BodyKind::TetMesh ||
                           object.body_kind == core::BodyKind::MassSpring;
    Surface surface;
    surface.id = object.id;
    if (!object.surface.triangles.empty()) {
      surface.triangles = object.surface.triangles;
      surface.weld = weld_map(object.surface.vertices);
      surface.mesh = make_mesh(object.surface.vertices, object.surface.triangles,
                               object.surface.uvs, surface.weld);
      if (simulated && !object.embedding.empty() &&
          object.embedding.tet.size() == object.surface.vertices.size()) {
        surface.body = object.id;
        surface.embedding = &object.embedding;
        surface.tets = object.body.tets;
      }
    } else {
      continue;  // nothing visible: a body without a surface is shown through its organ
    }
    if (const auto it = scenario.textures.find(object.texture); it != scenario.textures.end()) {
      if (const auto map = it->second.maps.find("albedo"); map != it->second.maps.end()) {
        const std::string what = (package / map->second).string();
        surface.texture = decode_png(read_package_file(package, map->second), what);
      }
    }
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(surface.mesh);
    mapper->ScalarVisibilityOff();
    surface.actor = vtkSmartPointer<vtkActor>::New();
    surface.actor->SetMapper(mapper);
    vtkProperty* property = surface.actor->GetProperty();
    set_tissue_lighting(property);
    property->SetColor(0.85, 0.55, 0.5);
    if (const auto it = scenario.textures.find(object.texture); it != scenario.textures.end()) {
      surface.texture_preset = it->second.preset;
      surface.texture_seed = it->second.seed;
    }
    if (!surface.body.empty()) {
      // The inside a cut lays open: empty and hidden until the first cut.
      surface.cut_faces = vtkSmartPointer<vtkPolyData>::New();
      vtkNew<vtkPolyDataMapper> cut_mapper;
      cut_mapper->SetInputData(surface.cut_faces);
      cut_mapper->SetColorModeToDirectScalars();
      cut_mapper->SetScalarModeToUsePointData();
      surface.cut_actor = vtkSmartPointer<vtkActor>::New();
      surface.cut_actor->SetMapper(cut_mapper);
      set_tissue_lighting(surface.cut_actor->GetProperty());
      surface.cut_actor->VisibilityOff();
    }
    if (surface.texture) {
      if (surface.mesh->GetPointData()->GetTCoords() != nullptr) {
        vtkNew<vtkTexture> texture;
        texture->SetInputData(surface.texture);
        texture->InterpolateOn();
        texture->RepeatOn();
        texture->MipmapOff();
        surface.actor->SetTexture(texture);
        property->SetColor(1.0, 1.0, 1.0);
      } else {
        const auto mean = mean_colour(surface.texture);
        property->SetColor(mean[0] / 255.0, mean[1] / 255.0, mean[2] / 255.0);
      }
    }
    surfaces_.push_back(std::move(surface));
  }
}

SceneSurfaces::~SceneSurfaces() = default;

void SceneSurfaces::add_to(vtkRenderer* renderer) const {
  for (const Surface& surface : surfaces_) {
    renderer->AddActor(surface.actor);
    if (surface.cut_actor) renderer->AddActor(surface.cut_actor);
  }
}

void SceneSurfaces::update(const std::vector<sim::BodyPositions>& bodies) {
  for (Surface& surface : surfaces_) {
    if (surface.body.empty()) continue;
    for (const sim::BodyPositions& body : bodies) {
      if (body.name != surface.body) continue;
      const bool recut = body.cut_surface && body.cut_surface != surface.cut;
      if (recut) show_cut(surface, body.cut_surface);
      if (recut || body.positions != surface.shown_positions) {
        set_geometry(surface.mesh,
                     core::embedded_positions(*surface.embedding, surface.tets, body.positions),
                     surface.triangles, surface.weld);
        surface.shown_positions = body.positions;
      }
      if (recut || body.coagulated != surface.shown_coagulated) {
        tint_coagulated(surface, body.coagulated);
        surface.shown_coagulated = body.coagulated;
      }
    }
  }
}

void SceneSurfaces::tint_coagulated(Surface& surface, const std::vector<float>& coagulated) {
  vtkMapper* mapper = surface.actor->GetMapper();
  if (coagulated.empty()) {
    if (mapper->GetScalarVisibility() != 0) {
      mapper->ScalarVisibilityOff();
      surface.mesh->GetPointData()->RemoveArray("Coagulated");
      if (surface.cut) {
        fill_colours(
            vtkUnsignedCharArray::SafeDownCast(surface.cut_faces->GetPointData()->GetScalars()),
            surface.cut_colours, nullptr, kCoagulatedTint);
      }
    }
    return;
  }
  // The nodes' flags interpolated like positions: x carries each vertex's coagulated share.
  std::vector<core::Vec3> flags(coagulated.size(), core::Vec3::Zero());
  for (std::size_t n = 0; n < coagulated.size(); ++n)
    flags[n].x() = static_cast<double>(coagulated[n]);
  const std::vector<core::Vec3> share =
      core::embedded_positions(*surface.embedding, surface.tets, flags);
  // Textured surfaces: the texture is modulated by the vertex colour; plain ones: the colour is
  // the surface's own, darkened.
  double base[3] = {1.0, 1.0, 1.0};
  if (!surface.actor->GetTexture()) surface.actor->GetProperty()->GetColor(base);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Coagulated");
  fill_colours(colours,
               std::vector<std::array<double, 3>>(share.size(), {base[0], base[1], base[2]}),
               &share, kCoagulatedTint);
  surface.mesh->GetPointData()->SetScalars(colours);
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUsePointData();
  mapper->ScalarVisibilityOn();
  if (surface.cut) {
    fill_colours(
        vtkUnsignedCharArray::SafeDownCast(surface.cut_faces->GetPointData()->GetScalars()),
        surface.cut_colours, &share, kCoagulatedTint);
  }
}

void SceneSurfaces::show_cut(Surface& surface, std::shared_ptr<const sim::CutVisibleSurface> cut) {
  const core::SurfaceMesh& mesh = cut->mesh;
  const std::vector<double> none(mesh.vertices.size(), 0.0);
  const auto flag_it = mesh.vertex_attributes.find("cut_face");
  const std::vector<double>& flag =
      flag_it != mesh.vertex_attributes.end() && flag_it->second.size() == mesh.vertices.size()
          ? flag_it->second
          : none;
  std::vector<core::Triangle> skin, inside;
  for (const core::Triangle& t : mesh.triangles) {
    const bool opened = flag[static_cast<std::size_t>(t[0])] > 0.5 &&
                        flag[static_cast<std::size_t>(t[1])] > 0.5 &&
                        flag[static_cast<std::size_t>(t[2])] > 0.5;
    (opened ? inside : skin).push_back(t);
  }
  surface.weld = weld_map(mesh.vertices, &flag);
  surface.mesh = make_mesh(mesh.vertices, skin, mesh.uvs, surface.weld);
  vtkPolyDataMapper::SafeDownCast(surface.actor->GetMapper())->SetInputData(surface.mesh);
  surface.actor->GetMapper()->ScalarVisibilityOff();  // tint_coagulated sets it again

  // The cut faces share the skin's points and normals; their colours are the solid texture at
  // their material points.
  surface.cut_faces->Initialize();
  surface.cut_faces->SetPoints(surface.mesh->GetPoints());
  surface.cut_faces->GetPointData()->SetNormals(surface.mesh->GetPointData()->GetNormals());
  vtkNew<vtkCellArray> polys;
  for (const core::Triangle& t : inside) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  surface.cut_faces->SetPolys(polys);
  surface.cut_colours.assign(mesh.vertices.size(), {0.0, 0.0, 0.0});
  std::vector<core::Vec3> material;
  std::vector<std::size_t> opened;
  const auto& mx = mesh.vertex_attributes.find("material_x");
  const auto& my = mesh.vertex_attributes.find("material_y");
  const auto& mz = mesh.vertex_attributes.find("material_z");
  const bool has_material = mx != mesh.vertex_attributes.end() &&
                            my != mesh.vertex_attributes.end() &&
                            mz != mesh.vertex_attributes.end();
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (flag[v] <= 0.5) continue;
    opened.push_back(v);
    material.push_back(has_material ? core::Vec3(mx->second[v], my->second[v], mz->second[v])
                                    : mesh.vertices[v]);
  }
  if (!surface.inside && !surface.texture_preset.empty())
    surface.inside =
        std::make_shared<const CutFaceColours>(surface.texture_preset, surface.texture_seed);
  double plain[3];
  surface.actor->GetProperty()->GetColor(plain);  // untextured surfaces: their own colour
  const auto colours = surface.inside ? surface.inside->at(material)
                                      : std::vector<std::array<double, 3>>(
                                            material.size(), {plain[0], plain[1], plain[2]});
  for (std::size_t i = 0; i < opened.size(); ++i)
    surface.cut_colours[opened[i]] = colours[i];
  vtkNew<vtkUnsignedCharArray> scalars;
  scalars->SetName("CutFaceColour");
  fill_colours(scalars, surface.cut_colours, nullptr, kCoagulatedTint);
  surface.cut_faces->GetPointData()->SetScalars(scalars);
  surface.cut_actor->SetVisibility(inside.empty() ? 0 : 1);

  surface.triangles = std::move(skin);
  surface.triangles.insert(surface.triangles.end(), inside.begin(), inside.end());
  surface.cut = std::move(cut);
  surface.embedding = &surface.cut->embedding;
  surface.tets = surface.cut->tets;
}

vtkImageData* SceneSurfaces::texture_of(const std::string& id) const {
  for (const Surface& surface : surfaces_)
    if (surface.id == id) return surface.texture;
  return nullptr;
}

vtkPolyData* SceneSurfaces::cut_faces_of(const std::string& id) const {
  for (const Surface& surface : surfaces_)
    if (surface.id == id) return surface.cut_faces;
  return nullptr;
}

}  // namespace viscera::view
