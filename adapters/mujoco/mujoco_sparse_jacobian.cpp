#include "mujoco_sparse_jacobian.hpp"

#include <algorithm>
#include <cstddef>

namespace pb::internal::mujoco {

namespace {

// the column of DOF `dof` in `dofs` (present: dofs hold whole chains)
std::size_t column(const std::vector<int>& dofs, int dof) {
  return static_cast<std::size_t>(std::lower_bound(dofs.begin(), dofs.end(), dof) - dofs.begin());
}

}  // namespace

bool bodies_hang_from_world(const mjModel* m) {
  for (int b = 1; b < m->nbody; ++b) {
    if (m->body_dofnum[b] > 0 && m->body_parentid[b] != 0) return false;
  }
  return true;
}

void append_body_dofs(const mjModel* m, int body, std::vector<int>& dofs) {
  if (body <= 0) return;
  for (int k = 0; k < m->body_dofnum[body]; ++k) dofs.push_back(m->body_dofadr[body] + k);
}

void pair_dofs(const mjModel* m, int body_a, int body_b, std::vector<int>& dofs) {
  dofs.clear();
  // a body's DOFs are contiguous (body_dofadr): the lower body's come first
  const bool a_first = body_a <= 0 || (body_b > 0 && m->body_dofadr[body_a] < m->body_dofadr[body_b]);
  append_body_dofs(m, a_first ? body_a : body_b, dofs);
  append_body_dofs(m, a_first ? body_b : body_a, dofs);
}

void point_jacobian(const mjModel* m, const mjData* d, int body, const mjtNum p[3],
                    const std::vector<int>& dofs, mjtNum* jac) {
  const std::size_t w = dofs.size();
  std::fill(jac, jac + 3 * w, 0.0);
  // mj_jac (engine_support.c, 2.2.2): the point's offset from the root's
  // subtree centre of mass, then each DOF of the chain, last to first
  mjtNum offset[3];
  mju_sub3(offset, p, d->subtree_com + 3 * m->body_rootid[body]);
  while (body > 0 && !m->body_dofnum[body]) body = m->body_parentid[body];
  if (body <= 0) return;
  int da = m->body_dofadr[body] + m->body_dofnum[body] - 1;
  while (da >= 0) {
    const mjtNum* cdof = d->cdof + 6 * da;
    mjtNum tmp[3];
    mju_cross(tmp, cdof, offset);
    const std::size_t c = column(dofs, da);
    jac[c] = cdof[3] + tmp[0];
    jac[c + w] = cdof[4] + tmp[1];
    jac[c + 2 * w] = cdof[5] + tmp[2];
    da = m->dof_parentid[da];
  }
}

void solve_m_on(const mjModel* m, const mjData* d, const std::vector<int>& dofs, mjtNum* x,
                const mjtNum* y, int n) {
  const std::size_t w = dofs.size();
  const auto rows = static_cast<std::size_t>(n);
  if (x != y) std::copy(y, y + rows * w, x);
  const mjtNum* qLD = d->qLD;
  const mjtNum* diag_inv = d->qLDiagInv;
  // mj_solveLD (engine_core_smooth.c, 2.2.2), its single- and
  // multiple-vector branches, on the columns of `dofs`
  if (n == 1) {
    // x <- inv(L') x; skip simple, and zeros
    for (std::size_t c = w; c-- > 0;) {
      const int i = dofs[c];
      mjtNum tmp = 0.0;
      if (!m->dof_simplenum[i] && (tmp = x[c])) {
        int adr = m->dof_Madr[i] + 1;
        for (int j = m->dof_parentid[i]; j >= 0; j = m->dof_parentid[j]) {
          x[column(dofs, j)] -= qLD[adr++] * tmp;
        }
      }
    }
    for (std::size_t c = 0; c < w; ++c) x[c] *= diag_inv[dofs[c]];
    // x <- inv(L) x; skip simple
    for (std::size_t c = 0; c < w; ++c) {
      const int i = dofs[c];
      if (m->dof_simplenum[i]) continue;
      int adr = m->dof_Madr[i] + 1;
      mjtNum tmp = x[c];
      for (int j = m->dof_parentid[i]; j >= 0; j = m->dof_parentid[j]) {
        tmp -= qLD[adr++] * x[column(dofs, j)];
      }
      x[c] = tmp;
    }
    return;
  }
  for (std::size_t c = w; c-- > 0;) {
    const int i = dofs[c];
    if (m->dof_simplenum[i]) continue;
    int adr = m->dof_Madr[i] + 1;
    for (int j = m->dof_parentid[i]; j >= 0; j = m->dof_parentid[j]) {
      const std::size_t cj = column(dofs, j);
      for (std::size_t r = 0; r < rows; ++r) {
        if (const mjtNum tmp = x[r * w + c]) x[r * w + cj] -= qLD[adr] * tmp;
      }
      ++adr;
    }
  }
  for (std::size_t c = 0; c < w; ++c) {
    for (std::size_t r = 0; r < rows; ++r) x[r * w + c] *= diag_inv[dofs[c]];
  }
  for (std::size_t c = 0; c < w; ++c) {
    const int i = dofs[c];
    if (m->dof_simplenum[i]) continue;
    int adr = m->dof_Madr[i] + 1;
    for (int j = m->dof_parentid[i]; j >= 0; j = m->dof_parentid[j]) {
      const std::size_t cj = column(dofs, j);
      for (std::size_t r = 0; r < rows; ++r) x[r * w + c] -= qLD[adr] * x[r * w + cj];
      ++adr;
    }
  }
}

}  // namespace pb::internal::mujoco
