#include <doctest/doctest.h>

#include "render/text_format.hpp"

TEST_CASE("text_format: fixed never prints -0, short_number trims zeros") {
  CHECK(render::fixed(-0.00001, 4) == "0.0000");
  CHECK(render::fixed(-0.8473, 4) == "-0.8473");
  CHECK(render::fixed(0.73819, 4) == "0.7382");
  CHECK(render::short_number(200) == "200");
  CHECK(render::short_number(2.5) == "2.5");
  CHECK(render::short_number(0.1 * 3) == "0.3");
  CHECK(render::short_number(-0.0) == "0");
}
