#include "report_provenance.hpp"

#include <hdf5.h>

#include <vector>

#include "planarbench/errors.hpp"

namespace pb::internal {

namespace {

// closes an HDF5 handle with the function that owns it
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  [[nodiscard]] hid_t get() const { return id_; }
  [[nodiscard]] bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// HDF5 prints its error stack on every failed call; a probe must not
class QuietErrors {
 public:
  QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// a scalar string attribute (variable or fixed length); false if it is not one
bool read_string(hid_t attr, std::string& out) {
  Handle type(H5Aget_type(attr), H5Tclose);
  if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING) return false;
  Handle space(H5Aget_space(attr), H5Sclose);
  if (!space.valid() || H5Sget_simple_extent_npoints(space.get()) != 1) return false;
  if (H5Tis_variable_str(type.get()) > 0) {
    Handle mem(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(mem.get(), H5T_VARIABLE);
    H5Tset_cset(mem.get(), H5Tget_cset(type.get()));
    char* text = nullptr;
    if (H5Aread(attr, mem.get(), &text) < 0) return false;
    out = text != nullptr ? text : "";
    H5free_memory(text);
    return true;
  }
  const std::size_t size = H5Tget_size(type.get());
  std::vector<char> buffer(size + 1, '\0');
  Handle mem(H5Tcopy(type.get()), H5Tclose);
  if (H5Aread(attr, mem.get(), buffer.data()) < 0) return false;
  out.assign(buffer.data());
  return true;
}

herr_t collect_attribute(hid_t loc, const char* name, const H5A_info_t* /*info*/, void* data) {
  auto* out = static_cast<std::vector<std::pair<std::string, std::string>>*>(data);
  Handle attr(H5Aopen(loc, name, H5P_DEFAULT), H5Aclose);
  std::string value;
  if (attr.valid() && read_string(attr.get(), value)) out->emplace_back(name, value);
  return 0;
}

herr_t collect_case(hid_t group, const char* name, const H5L_info_t* /*info*/, void* data) {
  auto* out = static_cast<std::map<std::string, std::string>*>(data);
  Handle g(H5Gopen2(group, name, H5P_DEFAULT), H5Gclose);
  if (!g.valid() || H5Aexists(g.get(), "case_sha256") <= 0) return 0;
  Handle attr(H5Aopen(g.get(), "case_sha256", H5P_DEFAULT), H5Aclose);
  std::string value;
  if (attr.valid() && read_string(attr.get(), value)) (*out)[name] = value;
  return 0;
}

}  // namespace

FileProvenance read_file_provenance(const std::filesystem::path& path) {
  QuietErrors quiet;
  FileProvenance p;
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw InputError(path.string(), 0, "", "cannot be opened as an HDF5 file");
  if (H5Lexists(file.get(), "parameters", H5P_DEFAULT) > 0) {
    Handle params(H5Gopen2(file.get(), "parameters", H5P_DEFAULT), H5Gclose);
    hsize_t idx = 0;
    if (params.valid()) {
      H5Aiterate2(params.get(), H5_INDEX_NAME, H5_ITER_INC, &idx, collect_attribute, &p.parameters);
    }
  }
  if (H5Lexists(file.get(), "runs", H5P_DEFAULT) > 0) {
    Handle runs(H5Gopen2(file.get(), "runs", H5P_DEFAULT), H5Gclose);
    if (runs.valid()) {
      H5Literate(runs.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_case, &p.case_sha256);
    }
  }
  return p;
}

}  // namespace pb::internal
