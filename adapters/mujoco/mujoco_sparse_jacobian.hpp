// Contact rows on the few DOFs that move a pair's two bodies. A contact's
// normal row n^T (J_b(p) - J_a(p)) and M^-1 of it are zero outside the DOFs
// of bodies a and b whenever every moving body hangs from the world body by
// its own joints (the models this adapter writes: a free planar body's slide
// x, slide z, hinge y; a pendulum's hinge), so a row is at most 6 numbers,
// not nv: mj_jac and mj_solveM on nv-wide rows cost O(nv) per contact, which
// at a 1000-body scene (nv = 3000) is most of a step. The arithmetic is
// MuJoCo 2.2.2's own on the DOFs it touches, in its order (engine_support.c
// mj_jac: cdof[3..5] + cdof[0..2] x (p - subtree_com[root]);
// engine_core_smooth.c mj_solveLD: L^-T, D^-1, L^-1 over dof_parentid, skipping
// simple DOFs and zeros), and the dot products run over the DOFs ascending,
// so every number is the dense computation's to the bit (the terms outside
// are exact zeros; tested against mj_jac and mj_solveM).
#pragma once

#include <mujoco/mujoco.h>

#include <vector>

namespace pb::internal::mujoco {

// whether every body with DOFs is a child of the world body (no body hangs
// from another): then each body's DOFs are its own chain in dof_parentid and
// M^-1 does not couple two bodies
[[nodiscard]] bool bodies_hang_from_world(const mjModel* m);

// the DOFs of a body (its own: bodies_hang_from_world), appended ascending to
// `dofs`; none for the world body (fixed case bodies)
void append_body_dofs(const mjModel* m, int body, std::vector<int>& dofs);

// the DOFs of bodies a and b, ascending (a and b distinct, or one the world)
void pair_dofs(const mjModel* m, int body_a, int body_b, std::vector<int>& dofs);

// mj_jac's translational Jacobian of world point p on `body`, on the columns
// `dofs` (ascending; 3 rows of dofs.size(), row-major into jac): exactly the
// entries mj_jac computes there (zero for a DOF outside the body's chain)
void point_jacobian(const mjModel* m, const mjData* d, int body, const mjtNum p[3],
                    const std::vector<int>& dofs, mjtNum* jac);

// mj_solveM(m, d, x, y, n) on the columns `dofs` (a union of whole bodies'
// DOFs, ascending): y and x are n rows of dofs.size(); x may be y
void solve_m_on(const mjModel* m, const mjData* d, const std::vector<int>& dofs, mjtNum* x,
                const mjtNum* y, int n);

}  // namespace pb::internal::mujoco
