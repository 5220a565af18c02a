#pragma once
/// The second instrument port's tool in the endoscopic view (issue 19 §3): the left hand's
/// instrument seen by the laparoscope — a 5 mm shaft from outside the view up to the jaws'
/// hinge and, for tools with jaws, two jaws opening along the tool's up (closed: together).
/// Satin steel under the head light. Hidden while the port is empty. The working port's tool is
/// drawn the same way while the laparoscope is held apart; otherwise it runs along the optics,
/// out of their view.

#include <vtkSmartPointer.h>

#include "simulator/session/instrument_state.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace viscera::view {

/// The geometry of a tool in a port, in world coordinates (m): `shaft_length` m of a
/// `shaft_radius` m, 12-sided shaft ending at the hinge `jaw_length` m behind the tip, then the
/// jaws (none for the blunt probe, the suction cannula and the hook, whose shaft runs to the
/// tip). Open jaws stand `jaw_opening` m apart at their tips.
struct PortInstrumentShape {
  double shaft_radius = 0.0025;
  double shaft_length = 0.15;
  double jaw_length = 0.012;
  double jaw_opening = 0.008;
  double jaw_thickness = 0.0012;
};

/// The triangles of `port`'s tool (nothing when the port is empty).
vtkSmartPointer<vtkPolyData> port_instrument_mesh(const sim::SecondPort& port,
                                                  const PortInstrumentShape& shape = {});

class PortInstrument {
 public:
  /// Adds the (hidden) instrument to `scene`.
  explicit PortInstrument(vtkRenderer* scene);
  ~PortInstrument();
  PortInstrument(const PortInstrument&) = delete;
  PortInstrument& operator=(const PortInstrument&) = delete;

  /// Draws the tool of `port`, or hides it when the port is empty.
  void update(const sim::SecondPort& port);
  bool visible() const;

 private:
  vtkSmartPointer<vtkActor> actor_;
  sim::SecondPort shown_;  ///< the port whose triangles the mapper holds (none at first)
};

}  // namespace viscera::view
