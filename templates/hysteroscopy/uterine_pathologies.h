#pragma once
/// Pathologies of the uterine cavity for the hysteroscopy template (seed 000 §1.1, §12):
/// submucosal (sessile) myomas, intramural myomas, pedunculated myomas, endometrial polyps and
/// adhesions (synechiae). Each is its own closed surface placed at a random point of the cavity
/// wall and seated on it — vertices that would enter the wall are set onto it at a small gap —
/// so it touches the wall without overlapping it; an intramural myoma lies inside the wall
/// instead and becomes a hole in the uterus body. Positions are drawn so that no two
/// pathologies overlap and none covers a tubal orifice or the internal os. Lengths in m.

#include <optional>
#include <string>
#include <vector>

#include "core/random.h"
#include "core/scenario/scenario_parts.h"
#include "templates/geometry/surface_queries.h"
#include "templates/hysteroscopy/uterus_shape.h"

namespace viscera::templates {

/// How many of each kind, and their mean sizes (each pathology's own size is drawn ±25 %).
struct PathologyRequest {
  int submucosal_myomas = 0;
  int intramural_myomas = 0;
  int pedunculated_myomas = 0;
  int polyps = 0;
  int adhesions = 0;
  double myoma_diameter = 0.008;
  double polyp_length = 0.008;
  double adhesion_radius = 0.0008;
  /// Sessile myomas only on the anterior and posterior walls of the corpus (wall normal with
  /// |n_y| > 0.6 and |n_x| < 0.5, y the antero-posterior axis): where a resectoscope from the
  /// cervix lies beside them, parallel to the wall, to shave them, with the cavity open 6 mm
  /// from the myoma towards the cervix, where the sheath lies (the myomectomy patient).
  bool sessile_on_corpus_faces = false;
  double gap = 2e-4;            ///< clearance between a seated pathology and the wall
  double edge_length = 0.0015;  ///< target triangle edge of pathology surfaces
};

/// One placed pathology: its record for Scenario::pathologies and its surface.
struct PlacedPathology {
  core::Pathology record;  ///< id, kind, host "uterus", object id, position (base), size
  core::SurfaceMesh surface;
  bool in_wall = false;   ///< intramural: a hole in the uterus body, not in the cavity
  std::vector<int> base;  ///< surface vertices that rest on the wall (seated) or line the hole
  core::Vec3 axis_start = core::Vec3::Zero(), axis_end = core::Vec3::Zero();  ///< bounding capsule
  /// Unit normal of the wall at the base, into the cavity (the direction a stalk leaves the
  /// wall); zero for an intramural myoma and an adhesion.
  core::Vec3 wall_normal = core::Vec3::Zero();
  double capsule_radius = 0.0;
};

/// Places every requested pathology. `tissue` answers queries on `uterus.surface`. Throws
/// core::InputError ("cannot place …") when a pathology finds no free spot in 200 tries — the
/// variant generator counts that draw as invalid and draws again.
std::vector<PlacedPathology> place_pathologies(const UterusShape& uterus,
                                               const SurfaceQueries& tissue,
                                               const PathologyRequest& request, core::Rng& rng);

/// One pathology of `kind` ("myoma-submucosal", "myoma-intramural", "myoma-pedunculated" or
/// "polyp") of `size` m (myoma diameter, polyp length) shaped and seated exactly as
/// place_pathologies does, at the wall point of `tissue` nearest to `point`; a stalk leans from
/// the wall normal towards `hang` (the internal os in the template, down in the studio). An
/// intramural myoma is a sphere centred half-way through the wall beneath that point (in_wall,
/// base: all its vertices), shrunk to keep 1.5 mm of wall each side but to no less than 0.75 of
/// `size`. The record has kind, position (the wall point; an intramural myoma's centre), size;
/// id, host and object are the caller's. Returns nothing when the shape does not fit there (no
/// room across the cavity or in the wall, or its stalk would leave it). Throws
/// core::UsageError for another kind.
std::optional<PlacedPathology> shape_pathology_at(const SurfaceQueries& tissue,
                                                  const core::Vec3& point, const std::string& kind,
                                                  double size, const core::Vec3& hang,
                                                  const PathologyRequest& request, core::Rng& rng);

}  // namespace viscera::templates
