#pragma once
// The diagnostic line `mapping::validate(options)` throws for an options struct, or "" when
// the options are valid: error messages are part of the product, so tests compare them whole.

#include <string>

#include "common/error.hpp"

template <typename Options>
std::string validation_error(const Options &options) {
  try {
    validate(options);  // found by argument-dependent lookup in the options' namespace
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "";
}
