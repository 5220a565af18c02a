#pragma once
/// The package's visible surfaces as VTK actors: one textured actor per scene object with a
/// surface (seed 000 §7: the organ surfaces carry the package's albedo textures), following
/// the simulated bodies as they deform (each surface vertex rides on its embedding tet, or is
/// the body's own surface node). A cut body's surface is replaced by the one its cuts made
/// (BodyPositions::cut_surface): the skin keeps its texture, and the faces the cut laid open
/// are a second actor over the same points, coloured from the organ's solid texture
/// (CutFaceColours).

#include <vtkSmartPointer.h>

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "simulator/runtime/session_snapshot.h"

class vtkActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;

namespace viscera::view {

/// The bytes of a file inside a package folder or .vscz; throws core::InputError naming it.
std::string read_package_file(const std::filesystem::path& package, const std::string& name);

/// Decodes a PNG held in memory; throws core::InputError naming `what` when it is not one.
vtkSmartPointer<vtkImageData> decode_png(const std::string& bytes, const std::string& what);

/// Mean RGB (0…255) of an image's first three components.
std::array<double, 3> mean_colour(vtkImageData* image);

/// Actors of every object that has a surface (instruments excepted).
class SceneSurfaces {
 public:
  /// Builds the actors and loads each object's albedo texture from `package`. Throws
  /// core::InputError when a texture file cannot be read or decoded.
  SceneSurfaces(const core::Scenario& scenario, const std::filesystem::path& package);
  ~SceneSurfaces();

  /// Adds every actor to `renderer`.
  void add_to(vtkRenderer* renderer) const;
  /// Moves the surfaces to a session snapshot's bodies (objects without a body stay put), shows
  /// the surfaces of bodies cut since the last update, and colours coagulated tissue darkens
  /// towards a dry brown (BodyPositions::coagulated, blended over each surface vertex's embedding
  /// tet): the texture times kCoagulatedTint where every node is coagulated. Desiccated tissue is
  /// pale tan to brown; modulating the texture can only darken it, so the tint is the brown end.
  void update(const std::vector<sim::BodyPositions>& bodies);
  /// RGB factor on the tissue's colour where it is fully coagulated.
  static constexpr std::array<double, 3> kCoagulatedTint{0.62, 0.50, 0.40};

  /// The albedo texture of object `id`, or null.
  vtkImageData* texture_of(const std::string& id) const;
  /// The cut faces of object `id` (empty until a cut), their points the surface's.
  vtkPolyData* cut_faces_of(const std::string& id) const;

 private:
  struct Surface;
  /// Colours `surface`'s vertices by the coagulated share of their tet (none: no colours).
  static void tint_coagulated(Surface& surface, const std::vector<float>& coagulated);
  /// Shows `cut` as `surface`'s topology from now on: skin and cut-face triangles, the weld,
  /// the embedding and the cut faces' colours.
  static void show_cut(Surface& surface, std::shared_ptr<const sim::CutVisibleSurface> cut);
  std::vector<Surface> surfaces_;
};

}  // namespace viscera::view
