#pragma once
// Number formats shared by the text outputs, so that every printed number reads the same way.

#include <string>

namespace render {

// Fixed-point with `decimals` digits; a value that rounds to zero prints without a sign
// ("0.0000", never "-0.0000").
std::string fixed(double value, int decimals);

// At most four decimals with trailing zeros (and a bare point) removed: 200 -> "200",
// 2.5 -> "2.5", 0.30000000000000004 -> "0.3". For positions and other inputs a user typed.
std::string short_number(double value);

}  // namespace render
