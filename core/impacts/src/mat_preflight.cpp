#include "planarbench/impacts/mat_preflight.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

// The MAT v5 layout (MathWorks, "MAT-File Format", R2024a, ch. 1): a 128-byte
// header (116 bytes of text, 8 of subsystem offset, a 16-bit version 0x0100
// and the endian indicator "IM" as written by a little-endian machine, "MI"
// byte-swapped), then data elements. An element is a tag (32-bit type, 32-bit
// byte count) and its data padded to 8 bytes; a "small" element packs a count
// <= 4 into the tag's upper 16 bits and its data into the tag's second word.
// miCOMPRESSED (15) holds a zlib stream of further elements (not padded);
// miMATRIX (14) holds sub-elements: array flags (class in the low byte),
// dimensions, name, then by class: numeric or char data; for a struct the
// field-name length, the names, and one miMATRIX per element and field; for
// a cell one per element.

namespace pb {

namespace {

constexpr std::uint32_t miINT8 = 1;
constexpr std::uint32_t miINT32 = 5;
constexpr std::uint32_t miUINT32 = 6;
constexpr std::uint32_t miMATRIX = 14;
constexpr std::uint32_t miCOMPRESSED = 15;
constexpr int kClassCell = 1;
constexpr int kClassStruct = 2;
constexpr int kClassObject = 3;
constexpr int kClassSparse = 5;

struct Problem : std::runtime_error {
  Problem(std::string var, const std::string& what) : std::runtime_error(what), variable(std::move(var)) {}
  std::string variable;
};

class Walker {
 public:
  explicit Walker(bool swap) : swap_(swap) {}

  // the elements of `bytes`, whose first byte is at `origin` in `where`
  void elements(std::string_view bytes, std::size_t origin, const std::string& where, int depth) {
    std::size_t pos = 0;
    while (pos < bytes.size()) {
      const Element e = element(bytes, pos, origin, where);
      if (e.type == miCOMPRESSED) {
        compressed(e.data, origin + e.at, where, depth);
      } else if (e.type == miMATRIX) {
        matrix(e.data, origin + e.at + 8, where, depth, "");
      }
      pos = e.next;
    }
  }

 private:
  struct Element {
    std::uint32_t type = 0;
    std::string_view data;
    std::size_t at = 0;    // of its tag, in the bytes walked
    std::size_t next = 0;  // of the element after it
  };

  std::uint32_t u32(std::string_view b, std::size_t at) const {
    std::uint32_t v = 0;
    std::memcpy(&v, b.data() + at, 4);
    return swap_ ? __builtin_bswap32(v) : v;
  }

  // the file's structure is broken: "is truncated or damaged"
  [[noreturn]] static void fail(const std::string& where, std::size_t at, const std::string& what) {
    throw Problem("", fmt::format("is truncated or damaged: {} byte {}: {}", where, at, what));
  }
  // a variable claims more than a file of impacts holds
  [[noreturn]] static void refuse(const std::string& variable, const std::string& what) {
    throw Problem(variable, what + "; refused before reading");
  }

  Element element(std::string_view b, std::size_t pos, std::size_t origin,
                  const std::string& where) const {
    if (b.size() - pos < 8) fail(where, origin + pos, "an element's tag is cut short");
    Element e;
    e.at = pos;
    const std::uint32_t first = u32(b, pos);
    if ((first >> 16) != 0) {  // small element: count and data in the tag
      const std::size_t n = first >> 16;
      if (n > 4) fail(where, origin + pos, fmt::format("a small element claims {} bytes (at most 4)", n));
      e.type = first & 0xffff;
      e.data = b.substr(pos + 4, n);
      e.next = pos + 8;
      return e;
    }
    e.type = first;
    const std::size_t n = u32(b, pos + 4);
    if (n > b.size() - pos - 8) {
      fail(where, origin + pos,
           fmt::format("an element claims {} bytes where {} remain", n, b.size() - pos - 8));
    }
    e.data = b.substr(pos + 8, n);
    // padded to 8 bytes, but for compressed data (and the end of the bytes)
    const std::size_t padded = e.type == miCOMPRESSED ? n : (n + 7) / 8 * 8;
    e.next = pos + 8 + std::min(padded, b.size() - pos - 8);
    return e;
  }

  void compressed(std::string_view z, std::size_t at, const std::string& where, int depth) {
    std::string out;
    z_stream s{};
    if (inflateInit(&s) != Z_OK) fail(where, at, "zlib cannot start");
    s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(z.data()));
    s.avail_in = static_cast<uInt>(z.size());
    char buf[65536];
    int rc = Z_OK;
    while (rc == Z_OK) {
      s.next_out = reinterpret_cast<Bytef*>(buf);
      s.avail_out = sizeof buf;
      rc = inflate(&s, Z_NO_FLUSH);
      out.append(buf, sizeof buf - s.avail_out);
      if (out.size() > kMaxInflatedBytes) {
        inflateEnd(&s);
        fail(where, at,
             fmt::format("a compressed variable inflates past {} MB (a file of impacts needs less)",
                         kMaxInflatedBytes >> 20));
      }
      if (rc == Z_BUF_ERROR && s.avail_in == 0) break;  // input used up before the stream ended
    }
    const std::string msg = s.msg != nullptr ? s.msg : "";
    inflateEnd(&s);
    if (rc != Z_STREAM_END) {
      fail(where, at,
           rc == Z_BUF_ERROR ? std::string("a compressed variable is cut short (its stream does not end)")
                             : fmt::format("a compressed variable does not inflate (zlib: {})",
                                           msg.empty() ? std::to_string(rc) : msg));
    }
    elements(out, 0, fmt::format("{} byte {} inflated:", where, at), depth);
  }

  // `path`: the variable's name as impact_data.cpp names it ("data.states_i");
  // empty at the top level, where the matrix's own name element gives it
  void matrix(std::string_view m, std::size_t origin, const std::string& where, int depth,
              std::string path) {
    if (m.empty()) return;  // an empty array
    if (depth > kMaxMatDepth) refuse(path, fmt::format("is nested past {} levels", kMaxMatDepth));
    std::size_t pos = 0;
    const Element flags = element(m, pos, origin, where);
    if (flags.type != miUINT32 || flags.data.size() != 8) {
      fail(where, origin, "a matrix's array flags are not 8 bytes of miUINT32");
    }
    const int cls = static_cast<int>(u32(flags.data, 0) & 0xff);
    pos = flags.next;
    const Element dims = element(m, pos, origin, where);
    if (dims.type != miINT32 || dims.data.size() < 8 || dims.data.size() % 4 != 0 ||
        dims.data.size() > 4 * 32) {
      fail(where, origin + pos, "a matrix's dimensions are not 2 to 32 miINT32 values");
    }
    pos = dims.next;
    const Element name = element(m, pos, origin, where);
    if (name.type != miINT8) fail(where, origin + pos, "a matrix's name is not miINT8");
    if (path.empty()) path = printable_name(name.data);
    pos = name.next;
    std::size_t count = 1;
    std::string shape;
    bool too_many = false;
    for (std::size_t k = 0; k < dims.data.size(); k += 4) {
      const auto d = static_cast<std::int32_t>(u32(dims.data, k));
      if (d < 0) fail(where, origin, fmt::format("{}'s dimension is {}", path, d));
      shape += (k ? " x " : "") + std::to_string(d);
      if (d != 0 && count > kMaxMatElements / static_cast<std::size_t>(d)) too_many = true;
      count = too_many ? count : count * static_cast<std::size_t>(d);
    }
    if (too_many) {
      refuse(path, fmt::format("claims {} values: a file holds at most 100000 impacts (18 values "
                               "each at most)",
                               shape));
    }
    // a sparse matrix's row indices are sized by its nzmax, which libmatio
    // allocates before reading them (found by fuzz_impact_data: 3.2 GB from
    // a struct whose class byte was changed to sparse); a file of impacts
    // holds full matrices only
    if (cls == kClassSparse) refuse(path, "is a sparse matrix: a file of impacts holds full ones");
    if (cls == kClassObject) {  // its class name
      pos = element(m, pos, origin, where).next;
    }
    if (cls == kClassStruct || cls == kClassObject) {
      const Element len = element(m, pos, origin, where);
      if (len.type != miINT32 || len.data.size() != 4) {
        fail(where, origin + pos, "a struct's field-name length is not one miINT32");
      }
      const std::size_t l = u32(len.data, 0);
      pos = len.next;
      const Element names = element(m, pos, origin, where);
      if (l == 0 || l > 64 || names.data.size() % l != 0) {
        fail(where, origin + pos,
             fmt::format("{}'s field names ({} bytes) are not a whole number of {}-byte names (a "
                         "name holds 1 to 64)",
                         path, names.data.size(), l));
      }
      const std::size_t fields = names.data.size() / l;
      if (fields > kMaxStructFields || count * fields > kMaxStructCells) {
        refuse(path, fmt::format("claims a struct of {} elements of {} fields: at most {} fields, {} "
                                 "in all",
                                 shape, fields, kMaxStructFields, kMaxStructCells));
      }
      std::vector<std::string> children;
      for (std::size_t c = 0; c < count * fields; ++c) {
        children.push_back(path + "." + printable_name(names.data.substr((c % fields) * l, l)));
      }
      pos = names.next;
      walk_children(m, pos, origin, where, depth, children);
    } else if (cls == kClassCell) {
      if (count > kMaxStructCells) {
        refuse(path, fmt::format("claims a cell array of {} cells: at most {}", shape, kMaxStructCells));
      }
      std::vector<std::string> children;
      for (std::size_t c = 0; c < count; ++c) children.push_back(fmt::format("{}{{{}}}", path, c + 1));
      walk_children(m, pos, origin, where, depth, children);
    }
    if (cls != kClassStruct && cls != kClassObject && cls != kClassCell) {
      // numeric, char and logical data: every element it has, sized within
      // the matrix (its real part, an imaginary part)
      while (pos < m.size()) pos = element(m, pos, origin, where).next;
    }
  }

  void walk_children(std::string_view m, std::size_t pos, std::size_t origin,
                     const std::string& where, int depth, const std::vector<std::string>& children) {
    for (std::size_t c = 0; c < children.size() && pos < m.size(); ++c) {
      const Element e = element(m, pos, origin, where);
      if (e.type != miMATRIX) fail(where, origin + pos, children[c] + " is not a matrix");
      matrix(e.data, origin + pos + 8, where, depth + 1, children[c]);
      pos = e.next;
    }
  }

  // a name as stored (NUL-padded), printable, at most 64 characters
  static std::string printable_name(std::string_view raw) {
    std::string out;
    for (const char c : raw.substr(0, std::min<std::size_t>(raw.size(), 64))) {
      if (c == '\0') break;
      out += (c >= 0x20 && c < 0x7f) ? c : '?';
    }
    return out.empty() ? "?" : out;
  }

  bool swap_;
};

}  // namespace

MatProblem mat_v5_problem(std::string_view bytes) {
  const MatProblem not_v5{
      "", "is not a MAT v5 file (no MATLAB 5.0 header): a file of impacts is MAT v5 "
          "(scipy.io.savemat; MATLAB save -v7; Octave save -7)"};
  if (bytes.size() < 128) return not_v5;
  const bool little = bytes[126] == 'I' && bytes[127] == 'M';
  const bool swapped = bytes[126] == 'M' && bytes[127] == 'I';
  if (!little && !swapped) return not_v5;
  std::uint16_t version = 0;
  std::memcpy(&version, bytes.data() + 124, 2);
  if (swapped) version = static_cast<std::uint16_t>((version >> 8) | (version << 8));
  if (version == 0x0200) {
    return {"", "is a MAT v7.3 file (HDF5): a file of impacts is MAT v5 (MATLAB save -v7; "
                "scipy.io.savemat)"};
  }
  if (version != 0x0100) return not_v5;
  try {
    Walker(swapped).elements(bytes.substr(128), 128, "at", 0);
  } catch (const Problem& p) {
    return {p.variable, p.what()};
  }
  return {};
}

}  // namespace pb
