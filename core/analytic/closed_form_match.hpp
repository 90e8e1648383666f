// Which closed form, if any, is the truth of a case (SPEC §3), for truth =
// analytic: a body translating on a line (body_on_line.hpp) or two free disks
// colliding head on (two_disks_head_on.hpp); for truth =
// analytic_until_first_contact: pendulums up to their first contact; for a
// scene (SPEC §11), a resting stack or a row of disks without gravity.
// Anything else is unsupported, with the reason.
#pragma once

#include <string>

#include "planarbench/case.hpp"

namespace pb::internal {

enum class ClosedFormKind {
  none,
  body_on_line,
  two_disks_head_on,
  pendulums_until_contact,
  resting_stack,  // a scene: a stack at rest (resting_stack.hpp)
  disk_row,       // a scene: a row of disks struck along its line (disk_row.hpp)
};

struct ClosedFormMatch {
  ClosedFormKind kind = ClosedFormKind::none;
  std::string reason;  // why there is none; empty otherwise
  // body_on_line: the moving body (disk), the fixed half-plane (line), their
  // contact pair; two_disks_head_on: the two disks (disk, line) and their pair
  int disk = -1;
  int line = -1;
  int pair = -1;
};

[[nodiscard]] ClosedFormMatch match_closed_form(const Case& c);

}  // namespace pb::internal
