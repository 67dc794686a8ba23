#pragma once
// The tests' readers of the pictures and files run --out writes: libpng's own decoder, not
// the program's encoder, reads a PNG back into RGB pixels.
#include <doctest/doctest.h>
#include <png.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "app/picture/drawing.hpp"

namespace test_png {

// A colour as the pixels Png::at() returns.
inline std::vector<int> rgb(app::Rgb c) { return {c.r, c.g, c.b}; }

inline std::string read_all(const std::filesystem::path &path) {
  std::string bytes(static_cast<std::size_t>(std::filesystem::file_size(path)), '\0');
  std::FILE *file = std::fopen(path.c_str(), "rb");
  REQUIRE(file != nullptr);
  const std::size_t read = std::fread(bytes.data(), 1, bytes.size(), file);
  std::fclose(file);
  REQUIRE(read == bytes.size());
  return bytes;
}

struct Png {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgb;
  std::vector<int> at(int x, int y) const {
    const std::size_t i = offset(x, y);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
  // Whether pixel (x, y) is colour c, without a copy (for scans over every pixel).
  bool is(int x, int y, app::Rgb c) const {
    const std::size_t i = offset(x, y);
    return rgb[i] == c.r && rgb[i + 1] == c.g && rgb[i + 2] == c.b;
  }

 private:
  // One branch a pixel, not four assertions: the scans read every pixel of a picture.
  std::size_t offset(int x, int y) const {
    if (x < 0 || y < 0 || x >= width || y >= height) {
      FAIL("pixel (" << x << ", " << y << ") outside a " << width << " x " << height << " picture");
    }
    return static_cast<std::size_t>((y * width + x) * 3);
  }
};

inline Png read_png(const std::string &bytes) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  REQUIRE(png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()) != 0);
  image.format = PNG_FORMAT_RGB;
  Png png;
  png.width = static_cast<int>(image.width);
  png.height = static_cast<int>(image.height);
  png.rgb.resize(PNG_IMAGE_SIZE(image));
  REQUIRE(png_image_finish_read(&image, nullptr, png.rgb.data(), 0, nullptr) != 0);
  return png;
}

// The map area of a picture whose map has no white pixel on its north row and west column
// (demo pie and demo cone: a margin of never-updated cells): its top-left corner is the
// first pixel, row by row, that starts a run of at least 40 non-white pixels (the axes'
// labels are shorter), its width that run and its height the non-white pixels down from it.
struct Box {
  int x = 0;
  int y = 0;
  int w = 0;
  int h = 0;
};
inline Box map_box(const Png &png) {
  const std::vector<int> white{255, 255, 255};
  for (int y = 0; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      int run = 0;
      while (x + run < png.width && png.at(x + run, y) != white) ++run;
      if (run >= 40) {
        int h = 0;
        while (y + h < png.height && png.at(x, y + h) != white) ++h;
        return {x, y, run, h};
      }
      x += run;
    }
  }
  FAIL("no map area in the picture");
  return {};
}

}  // namespace test_png
