#include "core/lsystem/turtle.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace viscera::core {
namespace {

struct TurtleState {
  Vec3 position, heading, left, up;
  double width = 1.0;
  double depth = 0.0;
  int last_segment = -1;
  int order = 0;
};

/// Rotates the frame vectors a and b about `axis` by `degrees`, keeping them orthonormal.
void rotate(Vec3& a, Vec3& b, const Vec3& axis, double degrees) {
  const Eigen::AngleAxisd rotation(degrees * std::numbers::pi / 180.0, axis);
  a = (rotation * a).normalized();
  b = (rotation * b).normalized();
}

}  // namespace

std::vector<TurtleSegment> interpret_turtle(const LsystemString& modules,
                                            const TurtleOptions& options) {
  TurtleState state;
  state.position = options.origin;
  state.heading = options.heading.normalized();
  state.left = options.left.normalized();
  state.up = state.heading.cross(state.left).normalized();
  state.width = options.width;
  Rng rng(options.seed);
  std::vector<TurtleState> stack;
  std::vector<TurtleSegment> segments;

  const auto angle_of = [&](const LsystemModule& m) {
    double angle = m.parameters.empty() ? options.angle : m.parameters[0];
    if (options.angle_jitter > 0.0)
      angle += rng.uniform(-options.angle_jitter, options.angle_jitter);
    return angle;
  };

  for (const auto& m : modules) {
    switch (m.symbol) {
      case 'F': {
        const double length = m.parameters.empty() ? options.step : m.parameters[0];
        if (m.parameters.size() > 1) state.width = m.parameters[1];
        const int pieces = std::max(1, options.subdivisions);
        for (int piece = 0; piece < pieces; ++piece) {
          if (options.wiggle > 0.0) {
            rotate(state.heading, state.left, state.up,
                   rng.uniform(-options.wiggle, options.wiggle));
          }
          const double piece_length = length / pieces;
          TurtleSegment s;
          s.start = state.position;
          state.position += piece_length * state.heading;
          if (options.constrain)
            options.constrain(state.position, state.heading, state.left, state.up);
          s.end = state.position;
          s.start_width = state.width;
          state.width *= std::fmax(0.0, 1.0 - options.taper * piece_length);
          s.end_width = state.width;
          s.depth = state.depth;
          s.parent = state.last_segment;
          s.order = state.order;
          state.last_segment = static_cast<int>(segments.size());
          segments.push_back(s);
        }
        break;
      }
      case 'f':
        state.position += (m.parameters.empty() ? options.step : m.parameters[0]) * state.heading;
        if (options.constrain)
          options.constrain(state.position, state.heading, state.left, state.up);
        break;
      case '+':
        rotate(state.heading, state.left, state.up, angle_of(m));
        break;
      case '-':
        rotate(state.heading, state.left, state.up, -angle_of(m));
        break;
      case '&':
        rotate(state.heading, state.up, state.left, angle_of(m));
        break;
      case '^':
        rotate(state.heading, state.up, state.left, -angle_of(m));
        break;
      case '\\':
        rotate(state.left, state.up, state.heading, angle_of(m));
        break;
      case '/':
        rotate(state.left, state.up, state.heading, -angle_of(m));
        break;
      case '|':
        rotate(state.heading, state.left, state.up, 180.0);
        break;
      case '[':
        stack.push_back(state);
        ++state.order;
        break;
      case ']':
        if (stack.empty()) throw InputError("L-system string closes a branch it never opened");
        state = stack.back();
        stack.pop_back();
        break;
      case '!':
        state.width = m.parameters.empty() ? state.width * options.width_factor : m.parameters[0];
        break;
      case '\'':
        state.depth = m.parameters.empty() ? state.depth + options.depth_step : m.parameters[0];
        break;
      default:
        break;
    }
  }
  if (!stack.empty()) throw InputError("L-system string leaves a branch open");
  return segments;
}

}  // namespace viscera::core
