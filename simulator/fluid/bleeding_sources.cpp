#include "simulator/fluid/bleeding_sources.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "core/scenario/vessel_paths.h"

namespace viscera::sim::fluid {
namespace {

/// Ooze below this fraction of its opening rate counts as clotted.
constexpr double kClottedFraction = 0.01;

}  // namespace

BleedingSources::BleedingSources(BleedingPhysiology physiology)
    : physiology_(std::move(physiology)) {}

int BleedingSources::add_cut(int body, std::span<const core::VesselTree> trees,
                             std::span<const core::Vec3> nodes,
                             std::span<const core::Triangle> triangles, double time) {
  int added = 0;
  for (const core::VesselTree& tree : trees) {
    for (OpenedVessel& vessel : find_opened_vessels(tree, nodes, triangles, physiology_)) {
      BleedingSource source;
      source.vessel_tree = tree.id;
      source.segment = vessel.segment;
      source.along = vessel.along;
      source.path = std::move(vessel.path);
      source.radius = vessel.radius;
      source.level = vessel.level;
      source.body = body;
      source.nodes = triangles[static_cast<std::size_t>(vessel.triangle)];
      source.barycentric = vessel.barycentric;
      source.opened_at = time;
      source.conductance = vessel.conductance;
      source.pressure = vessel.pressure;
      sources_.push_back(std::move(source));
      ++added;
    }
  }
  const double area = 0.5 * triangles_area(nodes, triangles);
  if (area > 0.0) {
    BleedingSource ooze;
    ooze.capillary = true;
    ooze.area = area;
    ooze.body = body;
    double largest = -1.0;
    for (const core::Triangle& t : triangles) {
      const double a = triangles_area(nodes, std::span<const core::Triangle>(&t, 1));
      if (a > largest) {
        largest = a;
        ooze.nodes = t;
      }
    }
    ooze.opened_at = time;
    ooze.conductance = physiology_.capillary_conductance * area;
    ooze.pressure = physiology_.capillary_pressure;
    sources_.push_back(std::move(ooze));
  }
  return added;
}

std::vector<VesselOpening> BleedingSources::openings(double time) {
  std::vector<VesselOpening> openings;
  openings.reserve(sources_.size());
  for (BleedingSource& source : sources_) {
    double conductance = source.conductance;
    if (source.capillary && source.stop == BleedingStop::Bleeding) {
      const double decay = std::exp(-(time - source.opened_at) / physiology_.ooze_time_constant);
      if (decay < kClottedFraction) stop(source, BleedingStop::Clotted, time);
      conductance *= decay;
    }
    if (source.stop != BleedingStop::Bleeding) conductance = 0.0;
    double pressure = source.pressure;
    if (source.pulse_period > 0.0)
      pressure *= 1.0 + source.pulse_amplitude *
                            std::cos(2.0 * std::numbers::pi * (time - source.pulse_delay) /
                                     source.pulse_period);
    openings.push_back({conductance, pressure});
  }
  return openings;
}

void BleedingSources::record_step(std::span<const double> volumes) {
  for (std::size_t i = 0; i < volumes.size() && i < sources_.size(); ++i) {
    if (volumes[i] >= 0.0)
      sources_[i].bled += volumes[i];
    else
      sources_[i].intravasated -= volumes[i];
  }
}

int BleedingSources::coagulate(const core::Vec3& tip, double radius,
                               std::span<const core::Vec3> sites, double time) {
  int stopped = 0;
  for (std::size_t i = 0; i < sources_.size() && i < sites.size(); ++i) {
    if (sources_[i].stop == BleedingStop::Bleeding && (sites[i] - tip).norm() <= radius) {
      stop(sources_[i], BleedingStop::Coagulated, time);
      ++stopped;
    }
  }
  return stopped;
}

int BleedingSources::clip_where(const std::string& vessel_tree, double time,
                                const std::function<bool(const BleedingSource&)>& clipped) {
  int stopped = 0;
  for (BleedingSource& source : sources_) {
    if (source.capillary || source.stop != BleedingStop::Bleeding ||
        source.vessel_tree != vessel_tree || !clipped(source))
      continue;
    stop(source, BleedingStop::Clipped, time);
    ++stopped;
  }
  return stopped;
}

int BleedingSources::clip(const std::string& vessel_tree, int segment, double time) {
  return clip_where(vessel_tree, time, [&](const BleedingSource& source) {
    return std::find(source.path.begin(), source.path.end(), segment) != source.path.end();
  });
}

void BleedingSources::set_pulse(std::size_t index, double period, double delay, double amplitude) {
  BleedingSource& source = sources_.at(index);
  source.pulse_period = period;
  source.pulse_delay = delay;
  source.pulse_amplitude = amplitude;
}

int BleedingSources::clip_at(int body, const core::VesselTree& tree, const core::Vec3& rest_point,
                             double reach, double time) {
  return clip_where(tree.id, time, [&](const BleedingSource& source) {
    if (source.body != body) return false;
    return std::any_of(source.path.begin(), source.path.end(), [&](int segment) {
      const core::VesselSegmentPoint clip =
          core::nearest_point_on_segment(tree, segment, rest_point);
      // On the opened segment, only a clip proximal to the opening lies upstream of it.
      return clip.wall_distance <= reach &&
             (segment != source.segment || clip.along < source.along);
    });
  });
}

void BleedingSources::stop(BleedingSource& source, BleedingStop why, double time) {
  source.stop = why;
  source.stopped_at = time;
}

core::Vec3 site_position(const BleedingSource& source, std::span<const core::Vec3> positions) {
  return source.barycentric.x() * positions[static_cast<std::size_t>(source.nodes[0])] +
         source.barycentric.y() * positions[static_cast<std::size_t>(source.nodes[1])] +
         source.barycentric.z() * positions[static_cast<std::size_t>(source.nodes[2])];
}

}  // namespace viscera::sim::fluid
