// Which closed form, if any, is the truth of a case (SPEC §3): the disk on a
// line (truth = analytic) or pendulums up to their first contact (truth =
// analytic_until_first_contact). Anything else is unsupported, with the reason.
#pragma once

#include <string>

#include "planarbench/case.hpp"

namespace pb::internal {

enum class ClosedFormKind { none, disk_on_line, pendulums_until_contact };

struct ClosedFormMatch {
  ClosedFormKind kind = ClosedFormKind::none;
  std::string reason;  // why there is none; empty otherwise
  // disk_on_line: the moving disk, the fixed half-plane, their contact pair
  int disk = -1;
  int line = -1;
  int pair = -1;
};

[[nodiscard]] ClosedFormMatch match_closed_form(const Case& c);

}  // namespace pb::internal
