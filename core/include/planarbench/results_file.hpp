// The HDF5 results file (SPEC §5), readable with h5py alone. Written to a
// temporary name in the target directory and renamed when complete.
#pragma once

#include <filesystem>

#include "planarbench/run_result.hpp"

namespace pb {

// Writes the whole file atomically. Throws InputError when the target
// directory is missing or not writable (nothing is left behind), and
// std::runtime_error on an HDF5 failure (the temporary file is removed).
// `threads` threads compress the chunked datasets (the file's largest cost);
// the datasets do not depend on it.
void write_results_file(const std::filesystem::path& path, const ResultsFile& results,
                        int threads = 1);

// Reads a results file written by write_results_file. Throws InputError naming
// the file and the missing or malformed object for a truncated or foreign file.
[[nodiscard]] ResultsFile read_results_file(const std::filesystem::path& path);

}  // namespace pb
