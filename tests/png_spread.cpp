// png_spread FILE: reads a PNG with libpng and fails (exit 1) unless its pixels are spread:
// a screenshot that is not blank. Prints the counts it judged by. Used by replay_chromium.sh.
//   dark   pixels with luminance < 80 (walls, text)       at least 0.5 % of the picture
//   light  pixels with luminance > 200 (free space, page)  at least 5 %
//   mid    the rest (never-observed blue-grey, the path)   at least 0.5 %
//   colours at least 16 distinct RGB values
#include <png.h>

#include <cstdio>
#include <set>
#include <vector>

int main(int argc, char **argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: png_spread FILE.png\n");
    return 2;
  }
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&image, argv[1]) == 0) {
    std::fprintf(stderr, "error: %s: %s\n", argv[1], image.message);
    return 1;
  }
  image.format = PNG_FORMAT_RGB;
  std::vector<png_byte> rgb(PNG_IMAGE_SIZE(image));
  if (png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr) == 0) {
    std::fprintf(stderr, "error: %s: %s\n", argv[1], image.message);
    return 1;
  }
  double dark = 0, light = 0, mid = 0;
  std::set<unsigned> colours;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
    const double y = 0.299 * rgb[i] + 0.587 * rgb[i + 1] + 0.114 * rgb[i + 2];
    (y < 80 ? dark : y > 200 ? light : mid) += 1;
    colours.insert(static_cast<unsigned>(rgb[i]) << 16 | static_cast<unsigned>(rgb[i + 1]) << 8 | rgb[i + 2]);
  }
  const double total = static_cast<double>(image.width) * image.height;
  std::printf("%ux%u: dark %.2f%%, light %.2f%%, mid %.2f%%, %zu colours\n", image.width, image.height,
              100.0 * dark / total, 100.0 * light / total, 100.0 * mid / total, colours.size());
  const bool spread = dark >= 0.005 * total && light >= 0.05 * total && mid >= 0.005 * total && colours.size() >= 16;
  if (!spread) std::fprintf(stderr, "FAIL: %s looks blank (too little spread of pixel values)\n", argv[1]);
  return spread ? 0 : 1;
}
