#pragma once
// An RGB canvas to draw the pictures of `--out` on (map.png, truth.png, the snapshots), its
// text in the embedded 5 x 7 font (app/picture/bitmap_font.hpp), and its PNG encoding (libpng).
// Pixel (0, 0) is the top-left corner; drawing outside the canvas is clipped.

#include <string>
#include <string_view>
#include <vector>

namespace app {

struct Rgb {
  unsigned char r = 0, g = 0, b = 0;
  bool operator==(const Rgb &) const = default;
};

class Canvas {
 public:
  Canvas(int width, int height, Rgb background);

  int width() const { return width_; }
  int height() const { return height_; }
  Rgb at(int x, int y) const;
  const std::vector<unsigned char> &pixels() const { return pixels_; }

  void set(int x, int y, Rgb c);
  // The rectangle [x0, x0 + w) x [y0, y0 + h).
  void fill(int x0, int y0, int w, int h, Rgb c);
  // Its border, `thickness` pixels inside the rectangle.
  void frame(int x0, int y0, int w, int h, int thickness, Rgb c);
  // A line of square dots `thickness` wide between two pixel centres (Bresenham).
  void line(int x0, int y0, int x1, int y1, int thickness, Rgb c);
  // A filled disc of radius r pixels around (cx, cy).
  void disc(int cx, int cy, int r, Rgb c);
  // Text in the 5 x 7 font, each font pixel a square of `scale` pixels, the top-left corner
  // of the first character at (x, y). Returns the x after the text.
  int text(int x, int y, std::string_view s, int scale, Rgb c);

 private:
  int width_;
  int height_;
  std::vector<unsigned char> pixels_;  // row-major RGB
};

// The width in pixels `text` takes at `scale` (kGlyphAdvance a character).
int text_width(std::string_view s, int scale);

// The canvas as a PNG file's bytes (8-bit RGB, libpng's simplified API); throws
// common::RuntimeFailure when libpng fails.
std::string encode_png(const Canvas &canvas);

// A scale bar's length: the largest of 1, 2, 5 x 10^n metres that is at most max_px long at
// px_per_m pixels a metre (and at least 0.001 m).
double scale_bar_length_m(double px_per_m, int max_px);

// The legend strip under a picture: text lines first (the caption, the numbers), then the
// swatches with their labels flowing left to right, then a scale bar in metres. `font` is
// the size of a font pixel; a row is 10 font pixels high.
enum class Swatch { box, line, square, disc, frame };
struct LegendItem {
  Swatch swatch = Swatch::box;
  Rgb colour;
  std::string label;
};
struct Legend {
  std::vector<std::string> lines;
  std::vector<LegendItem> items;
  double px_per_m = 0.0;  // of the picture above: the scale bar's unit
};

// The font pixel size for a picture `width` pixels wide: 2 to 6.
int legend_font(int width);
// The narrowest picture a legend is drawn in at font 2 (its longest text fits).
inline constexpr int kMinPictureWidth = 480;
// The strip's height in pixels when `width` pixels wide.
int legend_height(const Legend &legend, int width, int font);
// Draws the strip from row `top` down, over the canvas's whole width.
void draw_legend(Canvas &canvas, int top, const Legend &legend, int font);

}  // namespace app
