#include "report_files.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

#include "planarbench/errors.hpp"
#include "planarbench/output_file.hpp"

namespace pb::internal {

namespace fs = std::filesystem;

void write_text_atomically(const fs::path& path, const std::string& text) {
  // the report's files are all under its --out folder
  (void)pb::write_text_atomically("--out", path, text);
}

std::string read_text_file(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(path.string(), 0, "", "cannot be read");
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

void ensure_directory(const fs::path& dir) {
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  if (fs::exists(dir, ec)) throw InputError(dir.string(), 0, "", "exists and is not a directory");
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string(), 0, "", "cannot be created: " + ec.message());
}

}  // namespace pb::internal
