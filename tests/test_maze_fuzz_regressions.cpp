// Inputs the fuzz targets (fuzz/) found; each must now be rejected with common::InputError
// (or read) instead of crashing. One case a finding, the input verbatim.

#include <doctest/doctest.h>

#include <string>

#include "common/error.hpp"
#include "maze/world.hpp"

namespace {

// The reader's verdict: "ok" or the diagnostic.
std::string verdict(const std::string &text) {
  try {
    maze::read_world(text, "fuzz");
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "ok";
}

}  // namespace

TEST_CASE("fuzz regressions: the seed worlds still read") {
  CHECK(verdict("o---o\n| S |\no---o\n") == "ok");
}
