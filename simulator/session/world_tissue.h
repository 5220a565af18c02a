#pragma once
/// The instrument on a deformable body of the World: the tip drags a proxy over the body's
/// surface and presses on it with a spring (DESIGN.md §5); pushing past the wall's thickness
/// (or the scenario's perforation depth) perforates it.

#include <memory>
#include <vector>

#include "simulator/camera/surface_bvh.h"
#include "simulator/session/instrument_tissue.h"
#include "simulator/world/world.h"

namespace viscera::sim {

/// A World body under the instrument.
class WorldTissue final : public InstrumentTissue {
 public:
  /// Attaches the instrument at `tip` to body `body` of `world` with a proxy spring of
  /// `stiffness` N/m. `perforation_depth` m (0: the local rest wall thickness).
  WorldTissue(World& world, int body, double stiffness, const core::Vec3& tip,
              double perforation_depth);

  const std::string& name() const override;
  void move(const InstrumentState& state, double dt) override;
  core::Vec3 force() const override { return world_.instrument_force(); }
  bool in_contact() const override { return world_.instrument_in_contact(); }
  std::optional<TissueEvent> complication() override;
  /// A "tissue-tear" warning for the links or edges of any body that tore in the last step
  /// (TearEvents of the world's tearing and cell-agent terms).
  std::vector<TissueEvent> warnings() override;
  std::string state_hash() const override { return {}; }
  const BodyView* body() const override;

 private:
  double wall_thickness(int triangle);
  double penetration() const;

  World& world_;
  int body_;
  double stiffness_, perforation_depth_;
  core::Vec3 tip_;
  std::unique_ptr<SurfaceBvh> wall_;  ///< the body's surface at rest, for wall thickness
  std::vector<double> thickness_;     ///< per body surface triangle, −1 until measured
  std::size_t reported_tears_ = 0;    ///< TearEvents already reported
};

}  // namespace viscera::sim
