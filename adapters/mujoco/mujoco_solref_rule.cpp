#include "mujoco_solref_rule.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "mujoco_frame.hpp"
#include "mujoco_shared_vertex.hpp"
#include "mujoco_sparse_jacobian.hpp"
#include "planarbench/contact_force.hpp"

namespace pb::internal::mujoco {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

SolrefRule::SolrefRule(const Case& /*c*/, mjModel* model, ModelLayout& layout)
    : model_(model), layout_(layout), scratch_(model) {
  const auto width = static_cast<std::size_t>(scratch_.sparse ? 6 * 3 : model->nv);
  jrows_.resize(static_cast<std::size_t>(kMaxContactSetPoints) * width);
  minv_rows_.resize(static_cast<std::size_t>(kMaxContactSetPoints) * width);
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

void SolrefRule::set_matrix(const mjModel* m, mjData* d, const PairLayout& p, int k, int n,
                            ContactSetMatrix& a,
                            std::array<double, kMaxContactSetPoints>& depth) {
  // each row n^T (J_b - J_a) at its point, along its normal a -> b, and M^-1 of it
  std::size_t w = static_cast<std::size_t>(m->nv);
  if (scratch_.sparse) {
    pair_dofs(m, p.mj_body_a, p.mj_body_b, scratch_.dofs);
    w = scratch_.dofs.size();
    if (jrows_.size() < static_cast<std::size_t>(n) * w) {
      jrows_.resize(static_cast<std::size_t>(kMaxContactSetPoints) * w);
      minv_rows_.resize(jrows_.size());
    }
  }
  for (int r = 0; r < n; ++r) {
    const mjContact& c = d->contact[rows_[static_cast<std::size_t>(r)]];
    const double sign = layout_.on_body_a(c.geom1, k) ? 1.0 : -1.0;
    const double normal[3] = {sign * c.frame[0], sign * c.frame[1], sign * c.frame[2]};
    double* row = &jrows_[static_cast<std::size_t>(r) * w];
    if (scratch_.sparse) {
      normal_row_on_dofs(m, d, p.mj_body_a, p.mj_body_b, c.pos, normal, scratch_, row);
    } else {
      normal_row(m, d, p.mj_body_a, p.mj_body_b, c.pos, normal, scratch_, row);
    }
    depth[static_cast<std::size_t>(r)] = -c.dist;
  }
  if (scratch_.sparse) {
    solve_m_on(m, d, scratch_.dofs, minv_rows_.data(), jrows_.data(), n);
  } else {
    mj_solveM(m, d, minv_rows_.data(), jrows_.data(), n);
  }
  a.resize(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      double v = 0.0;
      for (std::size_t q = 0; q < w; ++q) {
        v += jrows_[static_cast<std::size_t>(i) * w + q] *
             minv_rows_[static_cast<std::size_t>(j) * w + q];
      }
      a(i, j) = v;
    }
  }
}

void SolrefRule::apply(const mjModel* m, mjData* d) {
  ++evaluation_;
  buckets_.build(d, layout_);
  // a vertex two convex pieces share is one contact (mujoco_shared_vertex.hpp)
  fused_ = std::max(fused_, fuse_shared_vertex_contacts(d, layout_, buckets_));
  if (approach_mps_.size() < layout_.pairs.size()) {
    approach_mps_.resize(layout_.pairs.size(), kNaN);
    pressed_at_.resize(layout_.pairs.size(), -2);
    last_.resize(layout_.pairs.size());
  }
  for (std::size_t bucket = 0; bucket < buckets_.pairs().size(); ++bucket) {
    const int k = buckets_.pairs()[bucket];
    const auto uk = static_cast<std::size_t>(k);
    const PairLayout& p = layout_.pairs[uk];
    if (!p.present) continue;
    const auto list = buckets_.contacts(bucket);
    // the pair's pressed contacts (dist < 0: in the constraint), deepest first
    rows_.clear();
    for (const int i : list) {
      const mjContact& c = d->contact[i];
      if (c.dist < 0.0 && c.exclude == 0) rows_.push_back(i);
    }
    if (rows_.empty()) continue;
    // not pressed in the evaluation before: the contact is new and latches anew
    if (pressed_at_[uk] != evaluation_ - 1) approach_mps_[uk] = kNaN;
    pressed_at_[uk] = evaluation_;
    std::stable_sort(rows_.begin(), rows_.end(),
                     [&](int a, int b) { return d->contact[a].dist < d->contact[b].dist; });
    const int n = std::min(static_cast<int>(rows_.size()), kMaxContactSetPoints);
    ContactSetMatrix a(n, n);
    std::array<double, kMaxContactSetPoints> depth{};
    set_matrix(m, d, p, k, n, a, depth);
    const ContactSetScale set =
        contact_set_scale(a, std::span<const double>(depth.data(), static_cast<std::size_t>(n)));
    if (!(set.mass_kg > 0.0) || !std::isfinite(set.mass_kg)) continue;

    // eq. 7's approach speed: the normal rate at the pair's first step pressed
    const mjContact& deepest = d->contact[rows_.front()];
    if (std::isnan(approach_mps_[uk])) {
      const double sign = layout_.on_body_a(deepest.geom1, k) ? 1.0 : -1.0;
      const double normal[3] = {sign * deepest.frame[0], sign * deepest.frame[1],
                                sign * deepest.frame[2]};
      approach_mps_[uk] = std::max(
          0.0, approach_speed_mps(m, d, p.mj_body_a, p.mj_body_b, deepest.pos, normal, scratch_));
    }
    const LinearizedLaw lin = linearize_law(layout_.pair(k).law, -deepest.dist, approach_mps_[uk]);
    const double solref_k = -set.scale * lin.stiffness_n_per_m / set.mass_kg;  // 1/s^2
    // the damper unscaled: c times the w-weighted mean normal speed of the rows
    const double solref_b = -lin.damping_ns_per_m / set.mass_kg;  // 1/s
    for (const int i : list) {
      mjContact& c = d->contact[i];
      c.solref[0] = solref_k;
      c.solref[1] = solref_b;
    }
    for (const int id : p.mj_pairs) {
      model_->pair_solref[mjNREF * id] = solref_k;
      model_->pair_solref[mjNREF * id + 1] = solref_b;
    }
    last_[uk] = Last{solref_k, solref_b, set.mass_kg, set.scale, n};
    largest_scale_ = std::max(largest_scale_, set.scale);
    most_rows_ = std::max(most_rows_, n);
  }
}

}  // namespace pb::internal::mujoco
