#pragma once
/// What the trainee reads on top of the endoscopic image: the force bars with their warnings
/// (seed 002 §5.2: coloured bars per force component, a warning as the tissue's limit nears),
/// the session-info panel (seed 002 §6: elapsed time, forces, endoscope tip coordinates) and
/// the key bindings of the manual controls.

#include <vtkSmartPointer.h>

#include <string>

#include "core/math_types.h"

class vtkActor2D;
class vtkPolyData;
class vtkRenderer;
class vtkTextActor;

namespace viscera::view {

/// What the overlay shows at one frame.
struct OverlayState {
  double elapsed = 0.0;                   ///< s since the session started
  double time_limit = 0.0;                ///< s
  core::Vec3 force = core::Vec3::Zero();  ///< N on the instrument
  double force_warning = 0.0;             ///< N, 0: no warning level
  core::Vec3 tip = core::Vec3::Zero();    ///< m
  double optics_angle = 0.0;              ///< °
  std::string step;                       ///< procedure step under way, or ""
  double surface_seen = 0.0;              ///< fraction 0…1
  double inflow = 0.0, outflow = 0.0;     ///< valve openings 0…1
  std::string ended;                      ///< end reason once the session is over, or ""
  std::string tool;  ///< laparoscopic tool in the working port, "" without tools
  bool jaws_closed = false;
  bool irrigating = false;  ///< the suction–irrigation cannula's irrigation valve is open
  double lens_fog = 0.0;    ///< 0…1, the steam on the lens
  double pool_ml = 0.0;     ///< ml of fluid pooled at the lowest point of the scene
  double pool_blood_fraction = 0.0;  ///< 0…1
  std::string left_tool;  ///< the second port's tool (the left hand), "" while it is empty
  bool left_jaws_closed = false;
};

/// How close the force is to the warning level: "" below 80 %, "approaching" up to the level,
/// "excessive" above it (seed 002 §5.2). Always "" without a warning level.
std::string force_alert(double force, double warning);

/// The 2D actors of the overlay, in their own renderer layer.
class SessionOverlay {
 public:
  /// `bindings` is the text of the key bindings (empty: none shown).
  explicit SessionOverlay(const std::string& bindings);
  ~SessionOverlay();

  void add_to(vtkRenderer* renderer) const;
  void update(const OverlayState& state);

  /// Fraction 0…1 each bar fills for the current state (Fx, Fy, Fz, |F|), for tests.
  const std::array<double, 4>& bar_fill() const { return fill_; }
  std::string info_text() const;
  std::string warning_text() const;

 private:
  /// Sets the info text for `state` (force magnitude `magnitude` N, the tool line `tool`).
  void lay_out_info(const OverlayState& state, double magnitude, const std::string& tool);
  vtkSmartPointer<vtkTextActor> info_, bindings_, warning_, legend_;
  vtkSmartPointer<vtkPolyData> bars_;
  vtkSmartPointer<vtkActor2D> bar_actor_;
  std::array<double, 4> fill_{0.0, 0.0, 0.0, 0.0};
  /// The info text is laid out again (FreeType, 5 % of a laparoscopy window's CPU when it was
  /// every frame) when kTextInterval s of session time have passed since the last layout, the
  /// time went back, or its step, end or tool lines changed; the force bars follow every frame.
  static constexpr double kTextInterval = 0.1;
  double laid_out_at_ = -1.0;
  std::string laid_out_lines_;
};

}  // namespace viscera::view
