// RAII ownership of HDF5 hid_t handles and the error type the results-file
// code throws. HDF5's own error printing is switched off while we work; a
// failed call is turned into an Hdf5Error naming the object, with HDF5's
// innermost message appended.
#pragma once

#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace pb::internal {

// A failure at one object of the file. `object` is its path in the file
// ("/runs/falling_ball/mujoco"), `what` says what is wrong with it.
class Hdf5Error : public std::runtime_error {
 public:
  Hdf5Error(std::string object, std::string what)
      : std::runtime_error(object + ": " + what),
        object_(std::move(object)),
        what_(std::move(what)) {}
  [[nodiscard]] const std::string& object() const { return object_; }
  [[nodiscard]] const std::string& what_is_wrong() const { return what_; }

 private:
  std::string object_;
  std::string what_;
};

// the description of the innermost error on HDF5's default stack, then clears it
inline std::string hdf5_last_error() {
  std::string message;
  auto first = [](unsigned n, const H5E_error2_t* err, void* data) -> herr_t {
    // walking upward, entry 0 is the innermost (most specific) error
    if (n == 0 && err != nullptr && err->desc != nullptr) {
      *static_cast<std::string*>(data) = err->desc;
    }
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, first, &message);
  H5Eclear2(H5E_DEFAULT);
  return message;
}

// throws Hdf5Error(object, what + HDF5's reason) when status < 0
inline void check(herr_t status, const std::string& object, const std::string& what) {
  if (status < 0) {
    const std::string reason = hdf5_last_error();
    throw Hdf5Error(object, reason.empty() ? what : what + " (" + reason + ")");
  }
}

// Owns one hid_t and closes it with the matching H5?close on destruction.
class Hid {
 public:
  using Closer = herr_t (*)(hid_t);
  Hid() = default;
  Hid(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ~Hid() { reset(); }
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  Hid(Hid&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), closer_(o.closer_) {}
  Hid& operator=(Hid&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, H5I_INVALID_HID);
      closer_ = o.closer_;
    }
    return *this;
  }

  [[nodiscard]] hid_t get() const { return id_; }
  [[nodiscard]] bool valid() const { return id_ >= 0; }

  // closes now and reports failure (a file's close flushes it)
  void close(const std::string& object) {
    if (id_ < 0) return;
    const herr_t status = closer_(std::exchange(id_, H5I_INVALID_HID));
    check(status, object, "cannot be closed");
  }

 private:
  void reset() noexcept {
    if (id_ >= 0 && closer_ != nullptr) closer_(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

// wraps a freshly returned id; throws Hdf5Error when the call failed
inline Hid owned(hid_t id, Hid::Closer closer, const std::string& object, const std::string& what) {
  if (id < 0) {
    const std::string reason = hdf5_last_error();
    throw Hdf5Error(object, reason.empty() ? what : what + " (" + reason + ")");
  }
  return Hid(id, closer);
}

inline Hid owned_file(hid_t id, const std::string& o, const std::string& w) {
  return owned(id, H5Fclose, o, w);
}
inline Hid owned_group(hid_t id, const std::string& o, const std::string& w) {
  return owned(id, H5Gclose, o, w);
}
inline Hid owned_dataset(hid_t id, const std::string& o, const std::string& w) {
  return owned(id, H5Dclose, o, w);
}
inline Hid owned_attribute(hid_t id, const std::string& o, const std::string& w) {
  return owned(id, H5Aclose, o, w);
}
inline Hid owned_space(hid_t id, const std::string& o, const std::string& w) {
  return owned(id, H5Sclose, o, w);
}
inline Hid owned_type(hid_t id, const std::string& o, const std::string& w) {
  return owned(id, H5Tclose, o, w);
}
inline Hid owned_plist(hid_t id, const std::string& o, const std::string& w) {
  return owned(id, H5Pclose, o, w);
}

// Switches HDF5's automatic error printing off for its lifetime and restores
// whatever was installed before: we report errors ourselves.
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &old_func_, &old_data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, old_func_, old_data_); }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t old_func_ = nullptr;
  void* old_data_ = nullptr;
};

// the path of an open object in its file, for messages
inline std::string object_path(hid_t id) {
  const ssize_t n = H5Iget_name(id, nullptr, 0);
  if (n <= 0) {
    H5Eclear2(H5E_DEFAULT);
    return "?";
  }
  std::string name(static_cast<std::size_t>(n) + 1, '\0');
  H5Iget_name(id, name.data(), name.size());
  name.resize(static_cast<std::size_t>(n));
  return name;
}

}  // namespace pb::internal
