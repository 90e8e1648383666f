#include "planarbench/impacts/impact_data.hpp"

#include <fmt/format.h>
#include <matio.h>

#include <array>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "internal/hdf5_sha256.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/impacts/mat_preflight.hpp"

namespace pb {

namespace {

struct MatCloser {
  void operator()(mat_t* m) const { Mat_Close(m); }
};
struct VarFreer {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using MatFile = std::unique_ptr<mat_t, MatCloser>;
using MatVar = std::unique_ptr<matvar_t, VarFreer>;

[[noreturn]] void refuse(const std::string& path, const std::string& variable,
                         const std::string& what) {
  throw InputError(path, 0, variable, what);
}

std::string shape_of(const matvar_t* v) {
  std::string s;
  for (int i = 0; i < v->rank; ++i) s += (i ? " x " : "") + std::to_string(v->dims[i]);
  return s;
}

// MATLAB's name of a class (libmatio's enum matio_classes)
std::string class_name(matio_classes c) {
  static constexpr std::array<const char*, 18> names = {
      "empty", "cell",  "struct", "object", "char",   "sparse", "double", "single", "int8",
      "uint8", "int16", "uint16", "int32",  "uint32", "int64",  "uint64", "function", "opaque"};
  const auto k = static_cast<std::size_t>(c);
  return k < names.size() ? names[k] : fmt::format("class {}", k);
}

// a real double matrix, 2-D (what every variable of the layout is)
void require_real_double_2d(const std::string& path, const std::string& name, const matvar_t* v,
                            const std::string& shape) {
  if (v->class_type != MAT_C_DOUBLE || v->isComplex) {
    refuse(path, name,
           fmt::format("must be a real double matrix of {} (got {}{}): store the values as double",
                       shape, v->isComplex ? "complex " : "", class_name(v->class_type)));
  }
  if (v->rank != 2) {
    refuse(path, name,
           fmt::format("must be a 2-D matrix of {} (got {} dimensions: {})", shape, v->rank,
                       shape_of(v)));
  }
  if (v->data == nullptr) refuse(path, name, fmt::format("has no data (a matrix of {} expected)", shape));
}

// a real double matrix of `rows` x `cols` (cols == 0: a vector of rows
// entries, 1 x n or n x 1) in column-major order
std::vector<double> matrix(const std::string& path, const std::string& name, matvar_t* v,
                           std::size_t rows, std::size_t cols) {
  const std::string shape =
      cols == 0 ? fmt::format("{} values", rows) : fmt::format("{} x {}", rows, cols);
  if (v == nullptr) refuse(path, name, "missing: a double matrix of " + shape + " expected");
  require_real_double_2d(path, name, v, shape);
  const std::size_t r = v->dims[0];
  const std::size_t c = v->dims[1];
  const bool ok = cols == 0 ? (r == rows && c == 1) || (r == 1 && c == rows)
                            : (r == rows && c == cols);
  if (!ok) {
    const bool transposed = cols != 0 && r == cols && c == rows;
    refuse(path, name,
           fmt::format("must be {} (got {}{})", shape, shape_of(v),
                       transposed ? ": transposed? one impact per row" : ""));
  }
  const auto* d = static_cast<const double*>(v->data);
  return std::vector<double>(d, d + r * c);
}

// The number of impacts, from data.states_i: N x 6, one impact per row
std::size_t impact_count(const std::string& path, const matvar_t* states_i) {
  const std::string name = "data.states_i";
  const std::string shape = "N x 6 (one impact per row)";
  if (states_i == nullptr) refuse(path, name, "missing: a double matrix of " + shape + " expected");
  require_real_double_2d(path, name, states_i, shape);
  if (states_i->dims[1] != 6) {
    const bool transposed = states_i->dims[0] == 6;
    refuse(path, name,
           fmt::format("must be {} (got {}{})", shape, shape_of(states_i),
                       transposed ? ": transposed? store it as its transpose" : ""));
  }
  if (states_i->dims[0] == 0) refuse(path, name, "has no impacts (0 rows)");
  return states_i->dims[0];
}

// What a state of a drop onto a horizontal surface can be: x, y (m), theta
// (rad), x', y' (m/s), theta' (rad/s). The MCube drops reach |x|, |y| 0.51 m,
// |theta| 10.5 rad, speeds 2.9 m/s (1.3 after) and 76 rad/s
// (../shared/data/mcube/README.md); the limits are 20 to 200 times those, far
// past any bench drop (100 m/s is a fall of 510 m), and keep every engine's
// step well inside its range (issue 35: 2.9e5 m/s ran "ok" at 29 m per step).
struct StateLimit {
  const char* column;
  const char* unit;
  double limit;
};
constexpr std::array<StateLimit, 6> kStateLimits = {{{"x", "m", 100.0},
                                                     {"y", "m", 100.0},
                                                     {"theta", "rad", 1000.0},
                                                     {"x'", "m/s", 100.0},
                                                     {"y'", "m/s", 100.0},
                                                     {"theta'", "rad/s", 1e4}}};

// a value of row i (1-based column j) within its column's limit
void check_value(const std::string& path, const char* variable, std::size_t i, std::size_t j,
                 const std::string& column, const StateLimit& lim, double v) {
  if (std::isfinite(v) && std::abs(v) <= lim.limit) return;
  refuse(path, variable,
         fmt::format("row {} column {} ({}) is {:g} {}: must be a finite number within +-{:g} {}",
                     i + 1, j + 1, column, v, lim.unit, lim.limit, lim.unit));
}

void check_states(const ImpactSet& set) {
  const std::string& p = set.path;
  for (std::size_t i = 0; i < set.size(); ++i) {
    for (std::size_t j = 0; j < 6; ++j) {
      check_value(p, "data.states_i", i, j, kStateLimits[j].column, kStateLimits[j], set.pre[i][j]);
      check_value(p, "data.states_f", i, j, kStateLimits[j].column, kStateLimits[j], set.post[i][j]);
    }
    // (x', y', theta') of each stored model
    for (std::size_t j = 0; j < (set.models.empty() ? 0 : 18); ++j) {
      const StateLimit& lim = kStateLimits[3 + j % 3];
      check_value(p, "v_models", i, j, fmt::format("{} of {}", lim.column, kStoredModelNames[j / 3]),
                  lim, set.models[i][j]);
    }
    // the impact changes the velocity (every error is relative to that change;
    // whether the body approaches the ground is impact_arc_problem's, by its arc)
    if (set.pre[i][3] == set.post[i][3] && set.pre[i][4] == set.post[i][4] &&
        set.pre[i][5] == set.post[i][5]) {
      refuse(p, "data.states_f",
             fmt::format("row {}: the velocities after the impact equal those before: no "
                         "impact to predict (errors are relative to the velocity change)",
                         i + 1));
    }
  }
}

template <std::size_t N>
std::vector<std::array<double, N>> rows_of(const std::vector<double>& col_major, std::size_t rows) {
  std::vector<std::array<double, N>> out(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < N; ++j) out[i][j] = col_major[j * rows + i];
  }
  return out;
}

// the file's bytes, refused past kMaxMatFileBytes before they are read
std::string file_bytes(const std::string& path, const std::string& option) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) refuse(path, option, "is not a readable file (" + ec.message() + ")");
  if (size > kMaxMatFileBytes) {
    refuse(path, option,
           fmt::format("has {} bytes: a file of impacts has at most {} MB (1e5 impacts take 30 MB)",
                       size, kMaxMatFileBytes >> 20));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// what libmatio logs while a file is read (its errors and warnings: a
// compressed variable cut short is read as zeros and only logged, issue 35),
// gathered for the thread reading; Mat_LogInitFunc is process-wide
thread_local std::string* matio_said = nullptr;
void gather_matio_log(int /*level*/, char* message) {
  if (matio_said == nullptr || message == nullptr) return;
  if (!matio_said->empty()) *matio_said += "; ";
  *matio_said += message;
}
struct MatioLogScope {
  explicit MatioLogScope(std::string& said) {
    Mat_LogInitFunc("planarbench", gather_matio_log);
    matio_said = &said;
  }
  ~MatioLogScope() { matio_said = nullptr; }
  MatioLogScope(const MatioLogScope&) = delete;
  MatioLogScope& operator=(const MatioLogScope&) = delete;
};

// what a variable's header claims, checked before its data is read: stored
// uncompressed, no more bytes than the file has (a 416-byte file claimed
// 2.4 GB). How many values a matrix may claim (1e5 impacts of 18 values at
// most) is mat_preflight.cpp's, which walks every MAT v5 file before libmatio
// opens it, so the product below cannot overflow.
void check_claim(const std::string& path, const std::string& name, const matvar_t* v,
                 std::uintmax_t file_bytes) {
  if (v == nullptr || v->rank < 1 || v->dims == nullptr) return;
  std::size_t elements = 1;
  for (int k = 0; k < v->rank; ++k) elements *= v->dims[k];
  if (v->compression == MAT_COMPRESSION_NONE && elements * 8 > file_bytes) {
    refuse(path, name,
           fmt::format("claims {} doubles ({} bytes) in a {}-byte file: truncated or damaged",
                       shape_of(v), elements * 8, file_bytes));
  }
}

// a struct of exactly one element: libmatio 1.5.23's Mat_VarGetStructFieldByIndex
// reads through a null pointer for a struct of 0 elements (1 x 0), found by
// tests/fuzz/fuzz_impact_data.cpp
void require_one_struct(const std::string& path, const std::string& name, const matvar_t* v) {
  std::size_t elements = v->rank > 0 && v->dims != nullptr ? 1 : 0;
  for (int k = 0; k < v->rank && v->dims != nullptr; ++k) elements *= v->dims[k];
  if (elements != 1) {
    refuse(path, name,
           fmt::format("must be a 1 x 1 struct (got {}): one struct of states_i, states_f, n, d, "
                       "drop",
                       shape_of(v)));
  }
}

// every field of a struct variable's header (check_claim)
void check_struct_claims(const std::string& path, const std::string& name, matvar_t* v,
                         std::uintmax_t file_bytes) {
  if (v == nullptr) return;
  if (v->class_type != MAT_C_STRUCT) {
    check_claim(path, name, v, file_bytes);
    return;
  }
  require_one_struct(path, name, v);
  const unsigned fields = Mat_VarGetNumberOfFields(v);
  char* const* names = Mat_VarGetStructFieldnames(v);
  for (unsigned f = 0; f < fields; ++f) {
    check_claim(path, name + "." + (names != nullptr && names[f] != nullptr ? names[f] : "?"),
                Mat_VarGetStructFieldByIndex(v, f, 0), file_bytes);
  }
}

}  // namespace

ImpactSet read_impacts(const std::filesystem::path& path, const std::string& option) {
  const std::string p = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) refuse(p, option, "is not a readable file");
  const std::string bytes = file_bytes(p, option);
  // the structure libmatio would allocate by, checked first (mat_preflight.hpp)
  if (const MatProblem problem = mat_v5_problem(bytes); !problem.what.empty()) {
    refuse(p, problem.variable.empty() ? option : problem.variable, problem.what);
  }
  std::string matio_log;
  const MatioLogScope log_scope(matio_log);
  MatFile mat(Mat_Open(p.c_str(), MAT_ACC_RDONLY));
  if (!mat) refuse(p, option, "is not a MAT v5 file libmatio can read");
  for (const char* name : {"data", "v_models"}) {
    MatVar info(Mat_VarReadInfo(mat.get(), name));
    check_struct_claims(p, name, info.get(), bytes.size());
  }
  MatVar data(Mat_VarRead(mat.get(), "data"));
  if (!data || data->class_type != MAT_C_STRUCT) {
    refuse(p, "data", "missing or not a struct: data (states_i, states_f, n, d, drop) expected");
  }
  require_one_struct(p, "data", data.get());
  matvar_t* states_i = Mat_VarGetStructFieldByName(data.get(), "states_i", 0);
  const std::size_t n = impact_count(p, states_i);
  ImpactSet set;
  set.path = p;
  set.pre = rows_of<6>(matrix(p, "data.states_i", states_i, n, 6), n);
  set.post = rows_of<6>(
      matrix(p, "data.states_f", Mat_VarGetStructFieldByName(data.get(), "states_f", 0), n, 6), n);
  (void)matrix(p, "data.n", Mat_VarGetStructFieldByName(data.get(), "n", 0), n, 3);
  (void)matrix(p, "data.d", Mat_VarGetStructFieldByName(data.get(), "d", 0), n, 3);
  set.drop = matrix(p, "data.drop", Mat_VarGetStructFieldByName(data.get(), "drop", 0), n, 0);
  // v_models is optional (a file of impacts without the dataset's predictions)
  if (MatVar models(Mat_VarRead(mat.get(), "v_models")); models) {
    set.models = rows_of<18>(matrix(p, "v_models", models.get(), n, 18), n);
  }
  if (!matio_log.empty()) {
    refuse(p, option, "is truncated or damaged (libmatio: " + matio_log + ")");
  }
  check_states(set);
  set.sha256 = internal::sha256_hex(bytes);
  return set;
}

void write_impacts(const std::filesystem::path& path, const ImpactSet& set) {
  const std::size_t n = set.size();
  MatFile mat(Mat_CreateVer(path.string().c_str(), nullptr, MAT_FT_MAT5));
  if (!mat) throw std::runtime_error("libmatio cannot create " + path.string());
  auto column_major = [n](auto&& rows, std::size_t cols) {
    std::vector<double> v(n * cols);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < cols; ++j) v[j * n + i] = rows[i][j];
    }
    return v;
  };
  std::vector<double> pre = column_major(set.pre, 6);
  std::vector<double> post = column_major(set.post, 6);
  // the dataset's Jacobian rows: n = [0, 1, r_x], d = [1, 0, h] (values not used here)
  std::vector<double> jn(n * 3, 0.0), jd(n * 3, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    jn[1 * n + i] = 1.0;
    jd[0 * n + i] = 1.0;
  }
  std::vector<double> drop = set.drop;
  size_t dims6[2] = {n, 6}, dims3[2] = {n, 3}, dimsd[2] = {1, n}, one[2] = {1, 1};
  const char* fields[] = {"states_i", "states_f", "n", "d", "drop", nullptr};  // NULL-terminated
  matvar_t* data = Mat_VarCreateStruct2("data", 2, one, fields);
  auto field = [&](const char* name, size_t* dims, std::vector<double>& v) {
    matvar_t* f = Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, v.data(), 0);
    Mat_VarSetStructFieldByName(data, name, 0, f);
  };
  field("states_i", dims6, pre);
  field("states_f", dims6, post);
  field("n", dims3, jn);
  field("d", dims3, jd);
  field("drop", dimsd, drop);
  const int rc = Mat_VarWrite(mat.get(), data, MAT_COMPRESSION_ZLIB);
  Mat_VarFree(data);
  if (rc != 0) throw std::runtime_error("libmatio cannot write data to " + path.string());
  if (!set.models.empty()) {
    std::vector<double> models = column_major(set.models, 18);
    size_t dims18[2] = {n, 18};
    matvar_t* v = Mat_VarCreate("v_models", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims18, models.data(), 0);
    const int rv = Mat_VarWrite(mat.get(), v, MAT_COMPRESSION_ZLIB);
    Mat_VarFree(v);
    if (rv != 0) throw std::runtime_error("libmatio cannot write v_models to " + path.string());
  }
}

}  // namespace pb
