#pragma once
// An image surface's pixels as a PNG file: 8-bit RGB, every row with the Up filter, one
// zlib stream in IDAT chunks. Written here rather than through libpng, which filters each row
// again from a converted copy: a big map's page is about 21 megapixels, and this one pass
// from Cairo's words to the filtered row (a row equal to the one above is all zeros without
// a look at its bytes) is what the encoding costs besides zlib. A big picture is compressed
// with zlib's fast matcher (see kFastAbovePixels in png_encode.cpp).

#include <string>

namespace app {

// The PNG of a width x height image of 32-bit words 0x00RRGGBB (Cairo's RGB24, the top byte
// ignored), rows `stride` bytes apart from `pixels`.
std::string rgb24_png(const unsigned char *pixels, int width, int height, int stride);

}  // namespace app
