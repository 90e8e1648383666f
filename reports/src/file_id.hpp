// A report's file names from what users named (cases, campaign axes,
// metrics): file_id keeps [A-Za-z0-9_-] and writes '_' for anything else,
// and keeps a name short enough for the suffixes and the writer's temporary
// (`.<name>.tmp.<pid>`) to fit a file name's 255 bytes (issue 49: a legal
// 244-byte case file name made `report` fail).
#pragma once

#include <cstddef>
#include <string>

namespace pb::internal {

// at most this many bytes; a longer name keeps its first bytes and a hash
// of the whole (distinct names stay distinct), suffixes add at most ~40
inline constexpr std::size_t kMaxFileIdBytes = 120;

[[nodiscard]] std::string file_id(const std::string& name);

}  // namespace pb::internal
