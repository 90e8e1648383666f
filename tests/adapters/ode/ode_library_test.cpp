// Tests for adapters/ode/ode_library.cpp
#include "ode_library.hpp"

#include <gtest/gtest.h>
#include <ode/ode.h>

#include <thread>

namespace pb::internal::ode {
namespace {

// the versions reported: headers and pkg-config agree on 0.16.x (Debian 12's
// libode-dev), and the library says it is the double-precision build
TEST(OdeLibrary, VersionsAndConfiguration) {
  EXPECT_EQ(ode_header_version().rfind("0.16", 0), 0u) << ode_header_version();
  EXPECT_EQ(ode_pkgconfig_version(), ode_header_version());
  EXPECT_NE(ode_configuration().find("ODE_double_precision"), std::string::npos)
      << ode_configuration();
}

// ODE works in a second thread once that thread has its own data
TEST(OdeLibrary, UsableFromAnotherThread) {
  bool ok = false;
  std::thread t([&ok] {
    ensure_ode_ready_in_this_thread();
    ensure_ode_ready_in_this_thread();  // a second call is harmless
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    dWorldSetGravity(w, 0.0, -9.8066, 0.0);
    dWorldStep(w, 0.01);
    // one semi-implicit Euler step: v = g h; 1e-15 m/s: one rounding of 0.098
    ok = std::abs(dBodyGetLinearVel(b)[1] + 0.098066) < 1e-15;
    dWorldDestroy(w);
  });
  t.join();
  EXPECT_TRUE(ok);
}

}  // namespace
}  // namespace pb::internal::ode
