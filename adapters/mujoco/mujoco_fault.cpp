#include "mujoco_fault.hpp"

#include <fmt/format.h>

#include <cstring>

namespace pb::internal::mujoco {

std::string describe_dof(const Case& c, const ModelLayout& layout, int dof) {
  for (std::size_t i = 0; i < layout.bodies.size() && i < c.bodies.size(); ++i) {
    const BodyLayout& b = layout.bodies[i];
    const std::string& name = c.bodies[i].name;
    if (dof == b.dof_x) return fmt::format("slide x of body '{}' (the case's x)", name);
    if (dof == b.dof_z) return fmt::format("slide z of body '{}' (the case's y)", name);
    if (dof == b.dof_hinge) return fmt::format("hinge of body '{}' (the case's angle)", name);
  }
  return fmt::format("DOF {}", dof);
}

std::string fault_reason(const Case& c, const ModelLayout& layout, const RaisedWarning& w,
                         double t_s, const std::string& mujoco_text) {
  const WarningInfo& info = warning_info(w.warning);
  // lastinfo names a coordinate for the per-DOF checks, a count otherwise
  const bool per_dof =
      std::strcmp(info.info, "DOF") == 0 || std::strcmp(info.info, "qpos index") == 0;
  const std::string where = per_dof ? fmt::format("{} {} = {}", info.info, w.lastinfo,
                                                  describe_dof(c, layout, w.lastinfo))
                                    : fmt::format("{} {}", w.lastinfo, info.info);
  std::string s = fmt::format(
      "mujoco: {} at t = {:.9g} s (its first occurrence; raised {} time{} in that step, last at "
      "{}): {}",
      info.name, t_s, w.count, w.count == 1 ? "" : "s", where, info.meaning);
  if (!mujoco_text.empty()) s += fmt::format("; MuJoCo: \"{}\"", mujoco_text);
  return s;
}

}  // namespace pb::internal::mujoco
