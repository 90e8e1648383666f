#include "mujoco3_mirror.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "planarbench/errors.hpp"

namespace pb::internal::mujoco3 {

void mirror_state(const mjModel* m, mjData* d, std::span<const double> qpos,
                  std::span<const double> qvel) {
  std::copy(qpos.begin(), qpos.end(), d->qpos);
  std::copy(qvel.begin(), qvel.end(), d->qvel);
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_crb(m, d);
  mj_factorM(m, d);
  mj_comVel(m, d);
}

void mirror_contacts(const mjModel* m, mjData* d, std::span<const double> c, std::size_t n,
                     std::size_t stride) {
  if (stride < kContactNumbers || c.size() < n * stride) {
    throw EngineError("mujoco3: a message's contacts are cut short");
  }
  if (n > static_cast<std::size_t>(m->nconmax)) {
    throw EngineError(fmt::format(
        "mujoco3: MuJoCo 3 reported {} contacts, more than the 2.2.2 mirror's nconmax {} "
        "(mujoco3.nconmax raises it)",
        n, m->nconmax));
  }
  d->ncon = static_cast<int>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* v = &c[i * stride];
    mjContact& con = d->contact[i];
    con = mjContact{};
    con.geom1 = static_cast<int>(v[0]);
    con.geom2 = static_cast<int>(v[1]);
    con.dist = v[2];
    std::copy(v + 3, v + 6, con.pos);
    std::copy(v + 6, v + 15, con.frame);
    con.exclude = static_cast<int>(v[15]);
    con.efc_address = stride > kContactNumbers ? static_cast<int>(v[kContactNumbers]) : -1;
  }
}

void mirror_warnings(mjData* d, std::span<const double> w) {
  for (std::size_t i = 0; i < kWarnings && i < static_cast<std::size_t>(mjNWARNING); ++i) {
    d->warning[i].number = static_cast<int>(w[i]);
    d->warning[i].lastinfo = static_cast<int>(w[kWarnings + i]);
  }
}

}  // namespace pb::internal::mujoco3
