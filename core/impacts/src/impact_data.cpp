#include "planarbench/impacts/impact_data.hpp"

#include <fmt/format.h>
#include <matio.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "internal/hdf5_sha256.hpp"
#include "planarbench/errors.hpp"

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

// a real double matrix of `rows` x `cols` (cols == 0: a vector of rows
// entries, 1 x n or n x 1) in column-major order
std::vector<double> matrix(const std::string& path, const std::string& name, matvar_t* v,
                           std::size_t rows, std::size_t cols) {
  if (v == nullptr) refuse(path, name, "missing: " + name + " must be a double matrix");
  if (v->class_type != MAT_C_DOUBLE || v->isComplex || v->rank != 2 || v->data == nullptr) {
    refuse(path, name,
           fmt::format("must be a real double matrix (got class {}, rank {}{})",
                       static_cast<int>(v->class_type), v->rank, v->isComplex ? ", complex" : ""));
  }
  const std::size_t r = v->dims[0];
  const std::size_t c = v->dims[1];
  const bool ok = cols == 0 ? (r == rows && c == 1) || (r == 1 && c == rows)
                            : (r == rows && c == cols);
  if (!ok) {
    refuse(path, name,
           fmt::format("must be {} (got {})",
                       cols == 0 ? fmt::format("{} values", rows) : fmt::format("{} x {}", rows, cols),
                       shape_of(v)));
  }
  const auto* d = static_cast<const double*>(v->data);
  return std::vector<double>(d, d + r * c);
}

template <std::size_t N>
std::vector<std::array<double, N>> rows_of(const std::vector<double>& col_major, std::size_t rows) {
  std::vector<std::array<double, N>> out(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < N; ++j) out[i][j] = col_major[j * rows + i];
  }
  return out;
}

std::string file_sha256(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return internal::sha256_hex(bytes.str());
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

// the most impacts a file may hold: 1e5 (MCube's training split has 1146),
// 1e5 x 36 doubles = 29 MB of data and v_models; a header claiming more is
// refused before anything is allocated (issue 35: 5e7 x 6 ended in bad_alloc)
constexpr std::size_t kMaxImpacts = 100000;

// what a variable's header claims, checked before its data is read: at most
// kMaxImpacts rows of at most 18 columns, and, stored uncompressed, no more
// bytes than the file has (a 416-byte file claimed 2.4 GB)
void check_claim(const std::string& path, const std::string& name, const matvar_t* v,
                 std::uintmax_t file_bytes) {
  if (v == nullptr || v->rank < 1 || v->dims == nullptr) return;
  std::size_t elements = 1;
  for (int k = 0; k < v->rank; ++k) {
    const std::size_t d = v->dims[k];
    if (d > kMaxImpacts * 18 || (d != 0 && elements > kMaxImpacts * 18 / d)) {
      refuse(path, name,
             fmt::format("claims {} values: a file holds at most {} impacts (18 values each at "
                         "most); refused before reading",
                         shape_of(v), kMaxImpacts));
    }
    elements *= d;
  }
  if (v->compression == MAT_COMPRESSION_NONE && elements * 8 > file_bytes) {
    refuse(path, name,
           fmt::format("claims {} doubles ({} bytes) in a {}-byte file: truncated or damaged",
                       shape_of(v), elements * 8, file_bytes));
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
  const unsigned fields = Mat_VarGetNumberOfFields(v);
  char* const* names = Mat_VarGetStructFieldnames(v);
  for (unsigned f = 0; f < fields; ++f) {
    check_claim(path, name + "." + (names != nullptr && names[f] != nullptr ? names[f] : "?"),
                Mat_VarGetStructFieldByIndex(v, f, 0), file_bytes);
  }
}

}  // namespace

ImpactSet read_impacts(const std::filesystem::path& path) {
  const std::string p = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) refuse(p, "--data", "is not a readable file");
  std::string matio_log;
  const MatioLogScope log_scope(matio_log);
  MatFile mat(Mat_Open(p.c_str(), MAT_ACC_RDONLY));
  if (!mat) refuse(p, "--data", "is not a MAT file libmatio can read (MAT v5 or v7.3 expected)");
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  for (const char* name : {"data", "v_models"}) {
    MatVar info(Mat_VarReadInfo(mat.get(), name));
    check_struct_claims(p, name, info.get(), bytes);
  }
  MatVar data(Mat_VarRead(mat.get(), "data"));
  if (!data || data->class_type != MAT_C_STRUCT) {
    refuse(p, "data", "missing or not a struct: data (states_i, states_f, n, d, drop) expected");
  }
  matvar_t* states_i = Mat_VarGetStructFieldByName(data.get(), "states_i", 0);
  if (states_i == nullptr || states_i->rank != 2) {
    refuse(p, "data.states_i", "missing: an N x 6 double matrix of pre-impact states expected");
  }
  const std::size_t n = states_i->dims[0];
  if (n == 0) refuse(p, "data.states_i", "has no impacts (0 rows)");
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
    refuse(p, "--data", "is truncated or damaged (libmatio: " + matio_log + ")");
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < 6; ++j) {
      if (!std::isfinite(set.pre[i][j]) || !std::isfinite(set.post[i][j])) {
        refuse(p, fmt::format("data.states_{}", std::isfinite(set.pre[i][j]) ? 'f' : 'i'),
               fmt::format("row {} column {} is not finite: every state must be a finite number",
                           i + 1, j + 1));
      }
    }
  }
  set.sha256 = file_sha256(path);
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
