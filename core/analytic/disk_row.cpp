#include "disk_row.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "normal_contact_episodes.hpp"
#include "planarbench/contact_pairs.hpp"

namespace pb::internal {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
// at most this many impacts (a row of N disks struck once has N - 1 before
// the first catches up; a chatter of impacts is no case for this closed form)
constexpr int kMaxImpacts = 10000;
}  // namespace

std::string DiskRow::why_not(const Case& c) {
  try {
    const DiskRow r(c);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

DiskRow::DiskRow(const Case& c) {
  auto refuse = [](const std::string& why) { throw std::invalid_argument(why); };
  const GeneratedBodies* row = nullptr;
  for (const GeneratedBodies& g : c.generated) {
    if (g.kind == SceneKind::row) row = row == nullptr ? &g : nullptr;
  }
  if (row == nullptr) refuse("not one [[generate]] row");
  if (!c.joints.empty()) refuse("a row of disks has no joints");
  if (c.gravity_mps2.norm() != 0.0) refuse("the row's closed form has no gravity");
  int moving = 0;
  for (const Body& b : c.bodies) moving += b.fixed ? 0 : 1;
  if (moving != row->count) refuse("bodies besides the row's move: the closed form is the row alone");
  for (int k = 0; k < row->count; ++k) {
    const Body& b = c.bodies[static_cast<std::size_t>(row->body(k))];
    const auto* circle = std::get_if<Circle>(&b.shape);
    if (circle == nullptr) refuse(fmt::format("body '{}' is a {}: the row's closed form is of disks", b.name, shape_type_name(b.shape)));
    disks_.push_back(row->body(k));
    mass_kg_.push_back(b.mass_kg);
    radius_m_.push_back(circle->radius_m);
  }
  origin_m_ = c.bodies[static_cast<std::size_t>(disks_.front())].position_m;
  if (disks_.size() > 1) {
    const Vec2 d = c.bodies[static_cast<std::size_t>(disks_[1])].position_m - origin_m_;
    direction_ = d.normalized();
  }
  // one Kelvin-Voigt law between every pair of neighbours, no friction
  const ContactPairs rules(c);
  for (std::size_t k = 0; k + 1 < disks_.size(); ++k) {
    const ContactLaw* law = rules.law_between(disks_[k], disks_[k + 1]);
    const auto* kv = law != nullptr ? std::get_if<KelvinVoigt>(law) : nullptr;
    if (kv == nullptr || kv->damping_depth_m != 0.0) refuse("neighbours need one plain Kelvin-Voigt law");
    if (k > 0 && (kv->stiffness_n_per_m != stiffness_n_per_m_ || kv->damping_ns_per_m != damping_ns_per_m_)) {
      refuse("neighbours need one plain Kelvin-Voigt law");
    }
    stiffness_n_per_m_ = kv->stiffness_n_per_m;
    damping_ns_per_m_ = kv->damping_ns_per_m;
  }
  // along the row: centres on the line, velocities along it
  Stretch st;
  for (std::size_t k = 0; k < disks_.size(); ++k) {
    const Body& b = c.bodies[static_cast<std::size_t>(disks_[k])];
    const Vec2 r = b.position_m - origin_m_;
    const Vec2 across(-direction_.y(), direction_.x());
    const double scale = 1.0 + r.norm();
    if (std::abs(r.dot(across)) > 1e-12 * scale || std::abs(b.velocity_mps.dot(across)) > 0.0) {
      refuse(fmt::format("body '{}' is off the row's line or moves across it", b.name));
    }
    st.s0_m.push_back(r.dot(direction_));
    st.v0_mps.push_back(b.velocity_mps.dot(direction_));
  }
  for (const Body& body : c.bodies) {
    BodyState s;
    s.position_m = body.position_m;
    s.angle_rad = body.angle_rad;
    s.velocity_mps = body.velocity_mps;
    s.angular_velocity_radps = body.angular_velocity_radps;
    initial_.push_back(s);
  }
  // free flight and impacts in turn, to the end of the run
  const double end_s = c.duration_s;
  const std::size_t n = disks_.size();
  st.t0_s = 0.0;
  std::vector<double> s(n), v(n);
  for (int impacts = 0;; ++impacts) {
    if (impacts > kMaxImpacts) refuse("more than 10000 impacts: not a row this closed form resolves");
    // the next neighbours to touch in free flight
    double hit = kInf;
    int pair = -1;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double gap = st.s0_m[k + 1] - st.s0_m[k] - radius_m_[k] - radius_m_[k + 1];
      const double closing = st.v0_mps[k] - st.v0_mps[k + 1];
      if (impacts == 0 && gap < 0.0) refuse("neighbours overlap at t = 0: the row starts apart");
      if (closing > 0.0 && st.t0_s + gap / closing < hit) {
        hit = st.t0_s + gap / closing;
        pair = static_cast<int>(k);
      }
    }
    st.t1_s = std::min(hit, end_s);
    st.pair = -1;
    stretches_.push_back(st);
    if (!(hit < end_s)) break;
    // the impact: the gap from 0, closing at the relative speed
    Stretch im;
    im.t0_s = hit;
    along_row(st, hit, im.s0_m, im.v0_mps);
    im.pair = pair;
    const auto k = static_cast<std::size_t>(pair);
    NormalContactParams p;
    p.mass_kg = mass_kg_[k] * mass_kg_[k + 1] / (mass_kg_[k] + mass_kg_[k + 1]);
    p.stiffness_n_per_m = stiffness_n_per_m_;
    p.damping_ns_per_m = damping_ns_per_m_;
    p.normal_gravity_mps2 = 0.0;
    p.gap0_m = 0.0;
    p.gap_rate0_mps = im.v0_mps[k + 1] - im.v0_mps[k];
    im.motion = std::make_shared<NormalContactMotion>(p);
    // to the offset: the gap back to 0 (or the run's end)
    double offset = kInf;
    for (double horizon = 1e-3; !(offset < kInf) && hit + horizon < 2.0 * end_s + 1.0; horizon *= 2.0) {
      im.motion->extend_to(horizon);
      const auto& phases = im.motion->phases();
      for (std::size_t i = 1; i < phases.size(); ++i) {
        if (phases[i].kind == NormalPhaseKind::separated) {
          offset = phases[i].start_s;
          break;
        }
      }
    }
    im.t1_s = std::min(hit + offset, end_s);
    im.motion->extend_to(im.t1_s - hit);
    // binary: no other neighbours touch before this impact has ended
    along_row(im, im.t1_s, s, v);
    for (std::size_t j = 0; j + 1 < n; ++j) {
      if (j == k) continue;
      if (s[j + 1] - s[j] - radius_m_[j] - radius_m_[j + 1] < 0.0) {
        refuse(fmt::format("the impact of disks {} and {} at t = {:.6g} s overlaps one of disks {} "
                           "and {}: no binary closed form",
                           k + 1, k + 2, hit, j + 1, j + 2));
      }
    }
    stretches_.push_back(im);
    if (!(hit + offset < end_s)) break;
    st = Stretch{};
    st.t0_s = im.t1_s;
    st.s0_m = s;
    st.v0_mps = v;
  }
}

void DiskRow::along_row(const Stretch& st, double t_s, std::vector<double>& s_m,
                        std::vector<double>& v_mps) const {
  const double tau = t_s - st.t0_s;
  s_m.resize(st.s0_m.size());
  v_mps.resize(st.s0_m.size());
  for (std::size_t k = 0; k < st.s0_m.size(); ++k) {
    s_m[k] = st.s0_m[k] + st.v0_mps[k] * tau;
    v_mps[k] = st.v0_mps[k];
  }
  if (st.pair < 0) return;
  // the struck pair: its centre of mass uniform, the gap from the oscillator
  const auto k = static_cast<std::size_t>(st.pair);
  const double ma = mass_kg_[k], mb = mass_kg_[k + 1], m = ma + mb;
  const double xc = (ma * st.s0_m[k] + mb * st.s0_m[k + 1]) / m;
  const double vc = (ma * st.v0_mps[k] + mb * st.v0_mps[k + 1]) / m;
  const NormalState ns = st.motion->state_at(tau);
  const double r = ns.gap_m + radius_m_[k] + radius_m_[k + 1];  // m, between the centres
  s_m[k] = xc + vc * tau - (mb / m) * r;
  s_m[k + 1] = xc + vc * tau + (ma / m) * r;
  v_mps[k] = vc - (mb / m) * ns.gap_rate_mps;
  v_mps[k + 1] = vc + (ma / m) * ns.gap_rate_mps;
}

const DiskRow::Stretch& DiskRow::stretch_at(double t_s) const {
  for (const Stretch& st : stretches_) {
    if (t_s <= st.t1_s) return st;
  }
  return stretches_.back();
}

void DiskRow::body_states(double t_s, std::vector<BodyState>& out) const {
  out = initial_;
  std::vector<double> s, v;
  along_row(stretch_at(t_s), t_s, s, v);
  for (std::size_t k = 0; k < disks_.size(); ++k) {
    BodyState& b = out[static_cast<std::size_t>(disks_[k])];
    b.position_m = origin_m_ + s[k] * direction_;
    b.velocity_mps = v[k] * direction_;
    b.angle_rad += b.angular_velocity_radps * t_s;
  }
}

void DiskRow::contacts(double t_s, std::vector<ContactSample>& out) const {
  out.clear();
  const Stretch& st = stretch_at(t_s);
  if (st.pair < 0) return;
  const NormalState ns = st.motion->state_at(t_s - st.t0_s);
  if (!(ns.gap_m < 0.0)) return;
  std::vector<double> s, v;
  along_row(st, t_s, s, v);
  const auto k = static_cast<std::size_t>(st.pair);
  ContactSample cs;
  cs.body_a = disks_[k];
  cs.body_b = disks_[k + 1];
  cs.force_n = ns.force_n;
  cs.penetration_m = -ns.gap_m;
  cs.normal = direction_;
  const double mid = 0.5 * ((s[k] + radius_m_[k]) + (s[k + 1] - radius_m_[k + 1]));
  cs.point_m = origin_m_ + mid * direction_;
  out.push_back(cs);
}

std::vector<ContactEpisode> DiskRow::episodes(double now_s) const {
  std::vector<ContactEpisode> out;
  for (const Stretch& st : stretches_) {
    if (st.pair < 0 || st.t0_s > now_s) continue;
    for (ContactEpisode e : normal_contact_episodes(*st.motion, std::min(now_s, st.t1_s) - st.t0_s)) {
      e.body_a = disks_[static_cast<std::size_t>(st.pair)];
      e.body_b = disks_[static_cast<std::size_t>(st.pair) + 1];
      e.onset_time_s += st.t0_s;
      e.offset_time_s += st.t0_s;
      out.push_back(e);
    }
  }
  return out;
}

long DiskRow::impacts_begun(double t_s) const {
  long n = 0;
  for (const Stretch& st : stretches_) n += st.t0_s <= t_s ? 1 : 0;
  return n;
}

nlohmann::json DiskRow::mapping() const {
  nlohmann::json j;
  j["closed_form"] = "disk_row";
  j["description"] =
      "disks on a line without gravity: free flight between impacts, each impact binary, the "
      "clamped Kelvin-Voigt oscillator of the pair's reduced mass with the pair's centre of mass "
      "uniform through it (as two_disks_head_on); the impacts in time order, none overlapping";
  j["law"] = "kelvin_voigt";
  j["stiffness_n_per_m"] = stiffness_n_per_m_;
  j["damping_ns_per_m"] = damping_ns_per_m_;
  nlohmann::json im = nlohmann::json::array();
  for (const Stretch& st : stretches_) {
    if (st.pair >= 0) im.push_back({{"disks", {st.pair + 1, st.pair + 2}}, {"onset_s", st.t0_s}, {"offset_s", st.t1_s}});
  }
  j["impacts"] = im;
  j["not_expressed"] = nlohmann::json::array();
  return j;
}

}  // namespace pb::internal
