#pragma once
// A device the robot must have, as webots::Robot::get*(name) returned it.

#include <string>

#include <fmt/format.h>

#include "common/error.hpp"

namespace robot {

// The device; throws common::InputError `the robot has no device "NAME"` when it is nullptr.
template <typename Device>
Device *require_device(Device *device, const std::string &name) {
  if (device == nullptr) throw common::InputError(fmt::format("the robot has no device \"{}\"", name));
  return device;
}

}  // namespace robot
