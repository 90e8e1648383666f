// Files of a report: written whole to a temporary name beside the target and
// renamed, so a reader never sees half a file.
#pragma once

#include <filesystem>
#include <string>

namespace pb::internal {

// Writes `text` to `path` through "<path>.tmp" and a rename. Throws InputError
// naming the file when it cannot be written (the temporary file is removed).
void write_text_atomically(const std::filesystem::path& path, const std::string& text);

// Reads a whole text file; throws InputError naming it when it cannot be read.
[[nodiscard]] std::string read_text_file(const std::filesystem::path& path);

// Creates `dir` (and its parents) when missing; InputError when it cannot be
// created or is a file.
void ensure_directory(const std::filesystem::path& dir);

}  // namespace pb::internal
