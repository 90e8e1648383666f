#include "hdf5_copy.hpp"

#include <vector>

#include "hdf5_handle.hpp"

namespace pb::internal {

namespace {

struct AttributeCopy {
  hid_t to = H5I_INVALID_HID;
  std::string object;
  bool failed = false;
  std::string failed_name;
};

herr_t copy_attribute(hid_t from, const char* name, const H5A_info_t*, void* data) {
  auto& ctx = *static_cast<AttributeCopy*>(data);
  const hid_t a = H5Aopen(from, name, H5P_DEFAULT);
  if (a < 0) return -1;
  const hid_t type = H5Aget_type(a);
  const hid_t space = H5Aget_space(a);
  herr_t status = -1;
  if (type >= 0 && space >= 0) {
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    const std::size_t size = H5Tget_size(type);
    std::vector<unsigned char> buf(static_cast<std::size_t>(n > 0 ? n : 1) * (size > 0 ? size : 1));
    if (H5Aread(a, type, buf.data()) >= 0) {
      const hid_t b = H5Acreate2(ctx.to, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
      if (b >= 0) {
        status = H5Awrite(b, type, buf.data());
        H5Aclose(b);
      }
      // variable-length strings read into buf point at memory HDF5 gave
      if (H5Tdetect_class(type, H5T_VLEN) > 0 || H5Tis_variable_str(type) > 0) {
        H5Dvlen_reclaim(type, space, H5P_DEFAULT, buf.data());
      }
    }
  }
  if (space >= 0) H5Sclose(space);
  if (type >= 0) H5Tclose(type);
  H5Aclose(a);
  if (status < 0) {
    ctx.failed = true;
    ctx.failed_name = name;
    return -1;
  }
  return 0;
}

}  // namespace

void copy_group_contents(hid_t from, hid_t to, const std::vector<std::string>& names,
                         const std::string& object) {
  for (const auto& name : names) {
    check(H5Ocopy(from, name.c_str(), to, name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
          object + "/" + name, "cannot copy it into the results file");
  }
  AttributeCopy ctx;
  ctx.to = to;
  ctx.object = object;
  hsize_t idx = 0;
  const herr_t rc = H5Aiterate2(from, H5_INDEX_NAME, H5_ITER_INC, &idx, copy_attribute, &ctx);
  if (rc < 0 || ctx.failed) {
    check(-1, object, "cannot copy attribute '" + ctx.failed_name + "' into the results file");
  }
}

}  // namespace pb::internal
