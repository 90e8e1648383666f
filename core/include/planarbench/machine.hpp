// Facts about the machine a result was measured on, for provenance: a cost
// figure means little without the CPU it ran on (issue 13).
#pragma once

#include <string>

namespace pb {

// The CPU model as the kernel names it (x86 /proc/cpuinfo "model name"), or
// "unknown".
[[nodiscard]] std::string machine_cpu_model();

// The number of CPUs this process may run on (its affinity mask, as
// `nproc` counts), at least 1.
[[nodiscard]] int machine_cpus();

}  // namespace pb
