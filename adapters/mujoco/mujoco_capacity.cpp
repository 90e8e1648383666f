#include "mujoco_capacity.hpp"

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace pb::internal::mujoco {

int model_dofs(const Case& c, const MujocoPlan& plan) {
  int nv = 0;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    if (!c.bodies[i].fixed) nv += plan.bodies[i].joint >= 0 ? 1 : 3;
  }
  return nv;
}

double capacity_bytes(int nconmax, int njmax, int nv) {
  const double con = static_cast<double>(nconmax);
  const double rows = static_cast<double>(njmax);
  const double dofs = static_cast<double>(nv);
  // mjxmacro.h (2.2.2) MJDATA_POINTERS: contact (nconmax); per row 8 ints
  // and 14 numbers; efc_J_colind, efc_JT_colind (ints) and efc_J, efc_JT
  // (numbers) njmax x nv; efc_AR_colind and efc_AR njmax x njmax
  return con * static_cast<double>(sizeof(mjContact)) +
         rows * (8.0 * sizeof(int) + 14.0 * sizeof(mjtNum)) +
         rows * dofs * 2.0 * (sizeof(int) + sizeof(mjtNum)) +
         rows * rows * (sizeof(int) + sizeof(mjtNum));
}

nlohmann::json ContactCapacity::json() const {
  return {{"nconmax", nconmax > 0 ? nconmax : kDefaultNconmax},
          {"njmax", njmax > 0 ? njmax : kDefaultNjmax},
          {"written", nconmax > 0 || njmax > 0},
          {"rule", rule},
          {"mjdata_capacity_bytes", data_bytes}};
}

int contacts_per_pair(GeomType a, GeomType b, bool multiccd) {
  if (a > b) std::swap(a, b);
  if (a == GeomType::mesh && b == GeomType::plane) return 3;
  if (a == GeomType::mesh && b == GeomType::mesh) return multiccd ? 5 : 1;
  return 1;
}

ContactCapacity contact_capacity(const Case& c, const MujocoPlan& plan, const MujocoSettings& s,
                                 int nv, bool multiccd) {
  ContactCapacity cap;
  long contacts = 0;  // the rule's contacts, over every moving member
  long members = 0;
  int rows_per_contact = 1;
  for (std::size_t g = 0; g < c.contact_groups.size(); ++g) {
    const ContactGroup& group = c.contact_groups[g];
    std::vector<GeomType> moving_types;
    std::vector<GeomType> fixed_types;  // one per fixed member
    for (const int i : group.bodies) {
      const GeomType t = plan.bodies[static_cast<std::size_t>(i)].geom;
      if (c.bodies[static_cast<std::size_t>(i)].fixed) {
        fixed_types.push_back(t);
      } else if (std::find(moving_types.begin(), moving_types.end(), t) == moving_types.end()) {
        moving_types.push_back(t);
      }
    }
    for (const int i : group.bodies) {
      if (c.bodies[static_cast<std::size_t>(i)].fixed) continue;
      const GeomType t = plan.bodies[static_cast<std::size_t>(i)].geom;
      int most = 0;
      for (const GeomType u : moving_types) most = std::max(most, contacts_per_pair(t, u, multiccd));
      long own = static_cast<long>(kPairsPerBody) * most;
      for (const GeomType u : fixed_types) own += contacts_per_pair(t, u, multiccd);
      contacts += own;
      ++members;
    }
    if (plan.groups[g].condim > 1) rows_per_contact = s.cone == "elliptic" ? 3 : 4;
  }
  std::string how;
  if (members > 0) {
    cap.nconmax = static_cast<int>(kDefaultNconmax + contacts);
    cap.njmax = static_cast<int>(kDefaultNjmax + rows_per_contact * contacts);
    how = fmt::format(
        "from the scene: {} moving group bodies, each in {} pairs of moving bodies and one with "
        "each fixed member, a pair the most contacts its collider reports ({}multiccd): "
        "nconmax = {} + {} = {}; njmax = {} + {} rows a contact x {}",
        members, kPairsPerBody, multiccd ? "" : "no ", kDefaultNconmax, contacts, cap.nconmax,
        kDefaultNjmax, rows_per_contact, contacts);
    // njmax^2 of efc_AR: the largest njmax within kMaxCapacityBytes
    if (capacity_bytes(cap.nconmax, cap.njmax, nv) > kMaxCapacityBytes) {
      int lo = kDefaultNjmax;
      int hi = cap.njmax;
      while (hi - lo > 1) {
        const int mid = lo + (hi - lo) / 2;
        (capacity_bytes(cap.nconmax, mid, nv) > kMaxCapacityBytes ? hi : lo) = mid;
      }
      how += fmt::format(" = {}, lowered to {}: mjData's capacity within {:.0f} MB (njmax x nv "
                         "Jacobians, njmax^2 efc_AR)",
                         cap.njmax, lo, kMaxCapacityBytes / (1024.0 * 1024.0));
      cap.njmax = lo;
    } else {
      how += fmt::format(" = {} (mujoco_capacity.hpp)", cap.njmax);
    }
  } else {
    how = "MuJoCo's compiled-in 100 contacts and 500 rows (no contact group)";
  }
  if (s.nconmax > 0) cap.nconmax = s.nconmax;
  if (s.njmax > 0) cap.njmax = s.njmax;
  if (s.nconmax > 0 || s.njmax > 0) {
    how += fmt::format("; set: mujoco.nconmax = {}, mujoco.njmax = {}", s.nconmax, s.njmax);
  }
  cap.rule = how;
  cap.data_bytes = capacity_bytes(cap.nconmax > 0 ? cap.nconmax : kDefaultNconmax,
                                  cap.njmax > 0 ? cap.njmax : kDefaultNjmax, nv);
  return cap;
}

}  // namespace pb::internal::mujoco
