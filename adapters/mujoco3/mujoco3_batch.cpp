#include "mujoco3_batch.hpp"

#include <fmt/format.h>

#include <cmath>

#include "planarbench/errors.hpp"

namespace pb::internal::mujoco3 {

namespace {

bool is_index(double x, double lo, double hi) {
  return x >= lo && x < hi && x == std::floor(x);
}

// A message's numbers, read in order; a short one is the other side's fault.
class Reader {
 public:
  explicit Reader(std::span<const double> v) : v_(v) {}
  std::span<const double> take(std::size_t n) {
    if (n > v_.size() - at_) throw EngineError("mujoco3: a BATCH message cut short");
    const auto out = v_.subspan(at_, n);
    at_ += n;
    return out;
  }
  double next() { return take(1)[0]; }
  // a count of things of `each` numbers: no more than the message still holds
  std::size_t count(std::size_t each) {
    const double x = next();
    const double left = static_cast<double>(v_.size() - at_);
    if (!(x >= 0.0) || x != std::floor(x) || x * static_cast<double>(each) > left) {
      throw EngineError(fmt::format("mujoco3: a bad count in a BATCH ({})", x));
    }
    return static_cast<std::size_t>(x);
  }
  [[nodiscard]] bool done() const { return at_ == v_.size(); }

 private:
  std::span<const double> v_;
  std::size_t at_ = 0;
};

// contact i's integers (`stride` numbers: kContactNumbers, or a record's
// kRecordContactNumbers) against the model's ngeom; EngineError
void check_contact_numbers(std::span<const double> v, std::size_t i, std::size_t stride,
                           std::size_t ngeom) {
  const auto bad = [&](const char* field, double x, const std::string& allowed) {
    throw EngineError(fmt::format("mujoco3: the WebAssembly side reported contact {} with {} = {} "
                                  "({} allowed)",
                                  i, field, x, allowed));
  };
  const auto n = static_cast<double>(ngeom);
  const std::string geoms = ngeom == 0 ? std::string("none") : fmt::format("0 to {}", ngeom - 1);
  if (!is_index(v[0], 0.0, n)) bad("geom1", v[0], geoms);
  if (!is_index(v[1], 0.0, n)) bad("geom2", v[1], geoms);
  // mjContact::exclude: 0 include, 1 in gap, 2 fused, then 3-4 (no dofs,
  // equality, passive: the meaning of 3 and 4 differs between 3.x releases)
  if (!is_index(v[15], 0.0, 5.0)) bad("exclude", v[15], "0 to 4");
  if (stride > kContactNumbers && !is_index(v[kContactNumbers], -1.0, 1e9)) {
    bad("efc_address", v[kContactNumbers], "-1 or a row");
  }
}

// warnings, qpos, qvel, ncon, the contacts: a record's or the question's
BatchStep read_step(Reader& r, const BatchLayout& layout, std::size_t stride) {
  BatchStep s;
  s.warnings = r.take(2 * kWarnings);
  for (const double w : s.warnings) {
    // mjWarningStat's counts and last info are ints
    if (!std::isfinite(w) || w != std::floor(w)) {
      throw EngineError(fmt::format("mujoco3: a BATCH warning counter of {}", w));
    }
  }
  s.qpos = r.take(layout.nq);
  s.qvel = r.take(layout.nv);
  s.ncon = r.count(stride);
  s.contacts = r.take(s.ncon * stride);
  for (std::size_t i = 0; i < s.ncon; ++i) {
    check_contact_numbers(s.contacts.subspan(i * stride, stride), i, stride, layout.ngeom);
  }
  return s;
}

}  // namespace

Batch read_batch(std::span<const double> message, const BatchLayout& layout) {
  Reader r(message);
  Batch b;
  // a record holds at least its asked flag, warnings and ncon
  const std::size_t records = r.count(2 + 2 * kWarnings + layout.nq + layout.nv);
  b.records.reserve(records);
  for (std::size_t k = 0; k < records; ++k) {
    const double asked = r.next();
    if (asked != 0.0 && asked != 1.0) {
      throw EngineError(fmt::format("mujoco3: a BATCH record's asked flag of {}", asked));
    }
    BatchStep s = read_step(r, layout, kRecordContactNumbers);
    s.asked = asked != 0.0;
    b.records.push_back(s);
  }
  const double asking = r.next();
  if (asking == 1.0) {
    b.question = read_step(r, layout, kContactNumbers);
  } else if (asking != 0.0) {
    throw EngineError(fmt::format("mujoco3: a BATCH's question flag of {}", asking));
  }
  if (!r.done()) throw EngineError("mujoco3: a BATCH message too long");
  return b;
}

}  // namespace pb::internal::mujoco3
