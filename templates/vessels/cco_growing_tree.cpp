#include "templates/vessels/cco_growing_tree.h"

#include <cmath>
#include <numbers>

namespace viscera::templates::cco {

GrowingTree::GrowingTree(const CcoOptions& o, double terminal_flow)
    : viscous_factor_(8.0 * o.viscosity / std::numbers::pi),
      gamma_(o.murray_exponent),
      terminal_flow_(terminal_flow),
      pressure_drop_(o.perfusion_pressure - o.terminal_pressure) {}

Summary GrowingTree::leaf(double length, int terminals) const {
  return {viscous_factor_ * length, length, terminals};
}

Summary GrowingTree::combine(double length, const Summary& l, const Summary& r, double& beta_l,
                             double& beta_r) const {
  const double rho = std::pow((l.terminals * l.resistance) / (r.terminals * r.resistance), 0.25);
  beta_l = std::pow(1.0 + std::pow(rho, -gamma_), -1.0 / gamma_);
  beta_r = std::pow(1.0 + std::pow(rho, gamma_), -1.0 / gamma_);
  Summary s;
  s.resistance = viscous_factor_ * length +
                 1.0 / (std::pow(beta_l, 4) / l.resistance + std::pow(beta_r, 4) / r.resistance);
  s.volume_factor = length + beta_l * beta_l * l.volume_factor + beta_r * beta_r * r.volume_factor;
  s.terminals = l.terminals + r.terminals;
  return s;
}

double GrowingTree::root_radius(const Summary& s) const {
  return std::pow(s.resistance * terminal_flow_ * s.terminals / pressure_drop_, 0.25);
}

void GrowingTree::refresh(int i) {
  Node& n = nodes[i];
  const double length = (n.distal - n.proximal).norm();
  if (n.left < 0) {
    n.summary = leaf(length);
  } else {
    n.summary =
        combine(length, nodes[n.left].summary, nodes[n.right].summary, n.beta_left, n.beta_right);
  }
}

void GrowingTree::refresh_upwards(int i) {
  for (; i >= 0; i = nodes[i].parent)
    refresh(i);
}

GrowingTree::Trial GrowingTree::try_insertion(int j, const Vec3& b, const Vec3& x) const {
  const Node& J = nodes[j];
  // The continuation b–D keeps J's subtree; only its own length changes.
  const double old_length = (J.distal - J.proximal).norm();
  const double continuation = (J.distal - b).norm();
  Summary c = J.summary;
  c.resistance += viscous_factor_ * (continuation - old_length);
  c.volume_factor += continuation - old_length;
  double beta_c = 0.0, beta_t = 0.0;
  Summary s = combine((b - J.proximal).norm(), c, leaf((x - b).norm()), beta_c, beta_t);
  double product = beta_t;  // new terminal radius / root radius
  int child = j;
  for (int p = J.parent; p >= 0; child = p, p = nodes[p].parent) {
    const Node& P = nodes[p];
    const double length = (P.distal - P.proximal).norm();
    double bl = 0.0, br = 0.0;
    if (P.left == child) {
      s = combine(length, s, nodes[P.right].summary, bl, br);
      product *= bl;
    } else {
      s = combine(length, nodes[P.left].summary, s, bl, br);
      product *= br;
    }
  }
  const double r0 = root_radius(s);
  return {std::numbers::pi * r0 * r0 * s.volume_factor, r0 * product};
}

int GrowingTree::insert(int j, const Vec3& b, const Vec3& x, int birth) {
  const int c = static_cast<int>(nodes.size());
  const int t = c + 1;
  Node continuation = nodes[j];
  continuation.proximal = b;
  continuation.parent = j;
  Node terminal;
  terminal.proximal = b;
  terminal.distal = x;
  terminal.parent = j;
  terminal.birth = birth;
  nodes.push_back(continuation);
  nodes.push_back(terminal);
  if (nodes[c].left >= 0) {
    nodes[nodes[c].left].parent = c;
    nodes[nodes[c].right].parent = c;
  }
  nodes[j].distal = b;
  nodes[j].left = c;
  nodes[j].right = t;
  refresh(c);
  refresh(t);
  refresh_upwards(j);
  return t;
}

void GrowingTree::remove_terminal(int t) {
  const int j = nodes[t].parent;
  const int c = nodes[j].left == t ? nodes[j].right : nodes[j].left;
  Node& J = nodes[j];
  J.distal = nodes[c].distal;
  J.left = nodes[c].left;
  J.right = nodes[c].right;
  if (J.left >= 0) {
    nodes[J.left].parent = j;
    nodes[J.right].parent = j;
  }
  nodes[c].alive = false;
  nodes[t].alive = false;
  refresh_upwards(j);
}

std::vector<double> GrowingTree::radii() const {
  std::vector<double> r(nodes.size(), 0.0);
  std::vector<int> stack = {root};
  r[root] = root_radius(nodes[root].summary);
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    const Node& n = nodes[i];
    if (n.left < 0) continue;
    r[n.left] = r[i] * n.beta_left;
    r[n.right] = r[i] * n.beta_right;
    stack.push_back(n.left);
    stack.push_back(n.right);
  }
  return r;
}

}  // namespace viscera::templates::cco
