#pragma once
/// @file robot_test_support.hpp
/// What the covopt::robot tests share: the planar test arm's path and MessageOf.
#include <functional>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

namespace covopt::robot::testing {

/// tests/robot/data/planar_2link.urdf: two links about z, shoulder [-3.14, 3.14] rad, 2 rad/s.
inline const std::string kPlanar = std::string(COVOPT_ROBOT_TEST_DATA_DIR) + "/planar_2link.urdf";

/// The message of the std::invalid_argument `action` throws; a test failure if none.
inline std::string MessageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  FAIL("no std::invalid_argument thrown");
  return {};
}

}  // namespace covopt::robot::testing
