// The provenance of a results file for the report: every string attribute of
// /parameters (build revision, compiler and flags, host, UTC time, version,
// command line; SPEC §5) and each case's sha256, read from the file itself
// because pb::ResultsFile keeps only part of /parameters.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace pb::internal {

struct FileProvenance {
  std::vector<std::pair<std::string, std::string>> parameters;  // name, value, by name
  std::map<std::string, std::string> case_sha256;               // case name -> hex digest
};

// Reads what there is; a missing attribute is left out (the results file was
// validated by read_results_file already). Throws InputError when the file
// cannot be opened.
[[nodiscard]] FileProvenance read_file_provenance(const std::filesystem::path& path);

}  // namespace pb::internal
