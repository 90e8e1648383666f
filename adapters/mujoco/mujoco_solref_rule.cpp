#include "mujoco_solref_rule.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "mujoco_frame.hpp"
#include "mujoco_shared_vertex.hpp"
#include "planarbench/contact_force.hpp"

namespace pb::internal::mujoco {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

SolrefRule::SolrefRule(const Case& c, mjModel* model, const ModelLayout& layout)
    : case_(c),
      model_(model),
      layout_(layout),
      scratch_(model),
      jrows_(static_cast<std::size_t>(kMaxContactSetPoints * model->nv)),
      minv_rows_(static_cast<std::size_t>(kMaxContactSetPoints * model->nv)),
      approach_mps_(c.contacts.size(), kNaN),
      last_(c.contacts.size()) {
  rows_.reserve(static_cast<std::size_t>(model->nconmax > 0 ? model->nconmax : 64));
}

nlohmann::json SolrefRule::seen_json() const {
  return {{"what", "over this run: the most pressed contacts of one pair in one step, and the "
                   "largest spread factor sigma = delta / delta_w the rule applied, and the most "
                   "contacts fused into another in one step (a vertex two convex pieces share, "
                   "reported by both: one contact, exclude = 2)"},
          {"most_rows", most_rows_},
          {"most_fused", fused_},
          {"largest_sigma", largest_scale_}};
}

void SolrefRule::hook(void* self, const mjModel* m, mjData* d) {
  static_cast<SolrefRule*>(self)->apply(m, d);
}

void SolrefRule::apply(const mjModel* m, mjData* d) {
  const auto nv = static_cast<std::size_t>(m->nv);
  // a vertex two convex pieces share is one contact (mujoco_shared_vertex.hpp)
  fused_ = std::max(fused_, fuse_shared_vertex_contacts(d, layout_));
  for (std::size_t k = 0; k < layout_.pairs.size(); ++k) {
    const PairLayout& p = layout_.pairs[k];
    if (!p.present) continue;
    // the pair's pressed contacts (dist < 0: in the constraint), deepest first
    rows_.clear();
    for (int i = 0; i < d->ncon; ++i) {
      const mjContact& c = d->contact[i];
      if (c.dist < 0.0 && c.exclude == 0 &&
          layout_.pair_of(c.geom1, c.geom2) == static_cast<int>(k)) {
        rows_.push_back(i);
      }
    }
    if (rows_.empty()) {
      approach_mps_[k] = kNaN;  // the contact is over: the next one latches anew
      continue;
    }
    std::stable_sort(rows_.begin(), rows_.end(),
                     [&](int a, int b) { return d->contact[a].dist < d->contact[b].dist; });
    const int n = std::min(static_cast<int>(rows_.size()), kMaxContactSetPoints);
    // each row n^T (J_b - J_a) at its point, along its normal a -> b, and M^-1 of it
    std::array<double, kMaxContactSetPoints> depth{};
    for (int r = 0; r < n; ++r) {
      const mjContact& c = d->contact[rows_[static_cast<std::size_t>(r)]];
      const double sign = layout_.on_body_a(c.geom1, static_cast<int>(k)) ? 1.0 : -1.0;
      const double normal[3] = {sign * c.frame[0], sign * c.frame[1], sign * c.frame[2]};
      double* row = &jrows_[static_cast<std::size_t>(r) * nv];
      normal_row(m, d, p.mj_body_a, p.mj_body_b, c.pos, normal, scratch_, row);
      depth[static_cast<std::size_t>(r)] = -c.dist;
    }
    mj_solveM(m, d, minv_rows_.data(), jrows_.data(), n);
    ContactSetMatrix a(n, n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        double v = 0.0;
        for (std::size_t q = 0; q < nv; ++q) {
          v += jrows_[static_cast<std::size_t>(i) * nv + q] *
               minv_rows_[static_cast<std::size_t>(j) * nv + q];
        }
        a(i, j) = v;
      }
    }
    const ContactSetScale set =
        contact_set_scale(a, std::span<const double>(depth.data(), static_cast<std::size_t>(n)));
    if (!(set.mass_kg > 0.0) || !std::isfinite(set.mass_kg)) continue;

    // eq. 7's approach speed: the normal rate at the pair's first step pressed
    const mjContact& deepest = d->contact[rows_.front()];
    if (std::isnan(approach_mps_[k])) {
      const double sign = layout_.on_body_a(deepest.geom1, static_cast<int>(k)) ? 1.0 : -1.0;
      const double normal[3] = {sign * deepest.frame[0], sign * deepest.frame[1],
                                sign * deepest.frame[2]};
      approach_mps_[k] = std::max(
          0.0, approach_speed_mps(m, d, p.mj_body_a, p.mj_body_b, deepest.pos, normal, scratch_));
    }
    const LinearizedLaw lin =
        linearize_law(case_.contacts[k].law, -deepest.dist, approach_mps_[k]);
    const double solref_k = -set.scale * lin.stiffness_n_per_m / set.mass_kg;  // 1/s^2
    // the damper unscaled: c times the w-weighted mean normal speed of the rows
    const double solref_b = -lin.damping_ns_per_m / set.mass_kg;  // 1/s
    for (int i = 0; i < d->ncon; ++i) {
      mjContact& c = d->contact[i];
      if (layout_.pair_of(c.geom1, c.geom2) != static_cast<int>(k)) continue;
      c.solref[0] = solref_k;
      c.solref[1] = solref_b;
    }
    for (const int id : p.mj_pairs) {
      model_->pair_solref[mjNREF * id] = solref_k;
      model_->pair_solref[mjNREF * id + 1] = solref_b;
    }
    last_[k] = Last{solref_k, solref_b, set.mass_kg, set.scale, n};
    largest_scale_ = std::max(largest_scale_, set.scale);
    most_rows_ = std::max(most_rows_, n);
  }
}

}  // namespace pb::internal::mujoco
