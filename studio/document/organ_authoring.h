#pragma once
/// What the studio's organ panels compute before they push a command (issue 9 §5; seed 001
/// §3.3): a texture baked onto one object, a vessel tree grown in one organ, a pathology shaped
/// and seated where the user clicked on an organ wall. Each calls the same library functions as
/// the CLI (`viscera bake`, `viscera vessels`, the hysteroscopy template's pathologies), takes
/// the scenario by const reference and returns the parts to add, so it runs on a worker thread
/// while the document stays untouched; the commands in organ_commands.h add the results.

#include <cstdint>
#include <optional>
#include <string>

#include "core/progress.h"
#include "core/scenario/scenario.h"
#include "studio/document/scenario_document.h"
#include "studio/document/wall_remesh.h"

namespace viscera::studio {

/// A procedural texture for one object (as `viscera bake --preset P --object O`).
struct TextureRequest {
  std::string preset = "endometrium";  ///< data/textures/presets.json
  std::uint64_t seed = 1;
  int width = 512, height = 512;  ///< pixels of the baked maps
};

/// The object with its UVs (an LSCM atlas when its own were unusable), its texture spec with
/// the maps listed, and the map files (package path → PNG bytes).
struct TexturedObject {
  core::TextureSpec spec;
  core::SceneObject object;
  PackageFiles files;
};

/// Bakes `request` onto object `object_id` alone through textures::bake_textures_into. The
/// spec's id is "<object>-<preset>" like the CLI's. Throws core::UsageError for an unknown
/// object or preset; CancelledError through `progress`.
TexturedObject bake_object_texture(const core::Scenario& scenario, const std::string& object_id,
                                   const TextureRequest& request,
                                   core::Progress& progress = core::Progress::none());

/// How `viscera vessels --method` grows a tree.
enum class VesselMethod { Cco, Lsystem };

/// A vessel tree for one organ. Lengths in m, flow in m³/s.
struct VesselRequest {
  VesselMethod method = VesselMethod::Cco;
  int terminals = 60;            ///< CCO terminal segments
  int generations = 5;           ///< L-system generations
  double root_radius = 1.5e-3;   ///< L-system root radius (CCO radii follow from hydraulics)
  double murray_exponent = 3.0;  ///< CCO bifurcation law r₀^γ = r₁^γ + r₂^γ
  double flow = 2.5e-6;          ///< root flow
  std::uint64_t seed = 1;
};

/// Grows a tree inside object `object_id`'s surface (templates::SurfaceMeshDomain) by CCO or the
/// built-in L-system grammar, with the CLI's turtle set-up. Its id is "<object>-vessels" (or
/// "-2", … when taken), its host the object. Throws core::UsageError for an unknown object or
/// bad parameters, core::InputError when the organ leaves no room; CancelledError.
core::VesselTree grow_organ_vessels(const core::Scenario& scenario, const std::string& object_id,
                                    const VesselRequest& request,
                                    core::Progress& progress = core::Progress::none());

/// Kinds a click can place on an organ wall (templates::shape_pathology_at). Polyps, submucosal
/// and pedunculated myomas grow into the cavity; a subserosal myoma bulges out of the serosa;
/// an intramural myoma lies inside the wall beneath the click.
inline constexpr const char* kWallPathologyKinds[] = {
    "polyp", "myoma-submucosal", "myoma-pedunculated", "myoma-intramural", "myoma-subserosal"};

/// Which side of a hollow organ's wall a pathology of `kind` belongs on: "cavity" for
/// intracavitary kinds (polyp, myoma-submucosal, myoma-pedunculated), "serosa" for
/// myoma-subserosal, "wall" (inside it, beneath the click) for myoma-intramural. Throws
/// core::UsageError for any other kind.
std::string wall_side_of(const std::string& kind);

/// The point of `surface`'s `side` ("cavity": triangles whose vertices the "cavity" vertex
/// attribute marks 1, as the hysteroscopy template marks the cavity wall; "serosa": marked 0)
/// nearest to `point`, m. Nothing when the surface has no such marks (a solid organ: the wall
/// where the user clicked is the only wall).
std::optional<core::Vec3> snap_to_wall_side(const core::SurfaceMesh& surface,
                                            const core::Vec3& point, const std::string& side);

/// A pathology as the scenario holds it: its object (a gmsh tet body, attached at its base),
/// the material to add when the scenario lacks it, its record and its connection to the host;
/// for an intramural myoma also the host re-meshed with a hole for it (wall_remesh.h).
struct PathologyParts {
  core::SceneObject object;
  std::optional<core::Material> material;
  core::Pathology record;
  core::Connection connection;
  std::optional<RemeshedHost> host;
};

/// Shapes a pathology of `kind` and `size` m at the wall point of object `host_id` nearest to
/// `point` (m) on the side of the wall where that kind grows (snap_to_wall_side; a click on
/// the outside of the uterus seats a polyp on the cavity wall beneath), on the host's welded
/// surface (a baked, seam-split surface works), as the hysteroscopy template does, fills it with
/// tets and connects its base to the host's nearest knots. An intramural myoma is a sphere in
/// the wall beneath `point`: the host is re-meshed around it (remesh_around_holes) and the
/// myoma joined to the knots lining its hole. Stalks lean towards the scenario's
/// "cervix-internal-os" landmark, else down (−z). Material "myoma" or "endometrium" (the
/// scenario's, else the shipped tissue). Throws core::UsageError for an unknown host or kind,
/// core::InputError when the shape finds no room there in 20 draws of `seed`'s generator.
PathologyParts build_pathology_at(const core::Scenario& scenario, const std::string& host_id,
                                  const core::Vec3& point, const std::string& kind, double size,
                                  std::uint64_t seed = 1,
                                  core::Progress& progress = core::Progress::none());

}  // namespace viscera::studio
