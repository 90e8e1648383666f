#include "file_id.hpp"

#include <fmt/format.h>

#include <cstdint>

namespace pb::internal {

namespace {

// FNV-1a, 64 bits (Fowler, Noll, Vo; the offset basis and prime of
// http://www.isthe.com/chongo/tech/comp/fnv/): the same name gives the same
// file on every machine
std::uint64_t fnv1a64(const std::string& s) {
  std::uint64_t h = 14695981039346656037ULL;
  for (const char ch : s) {
    h ^= static_cast<unsigned char>(ch);
    h *= 1099511628211ULL;
  }
  return h;
}

}  // namespace

std::string file_id(const std::string& name) {
  std::string out = name;
  for (char& ch : out) {
    const bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                    (ch >= '0' && ch <= '9') || ch == '_' || ch == '-';
    if (!ok) ch = '_';
  }
  if (out.empty()) return "_";
  if (out.size() <= kMaxFileIdBytes) return out;
  const std::string tag = fmt::format("-{:016x}", fnv1a64(name));
  return out.substr(0, kMaxFileIdBytes - tag.size()) + tag;
}

}  // namespace pb::internal
