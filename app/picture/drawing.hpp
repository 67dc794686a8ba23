#pragma once
// The one drawing module of every picture the program writes (map.png, truth.png, the
// snapshots, plan.png, demo pie / demo cone, map-log's): a page of a fixed size in pixels
// drawn with Cairo, encoded as PNG, SVG or PDF. Coordinates are pixels, (0, 0) the top-left
// corner, y down. Shapes are anti-aliased; blocks() (a grid of flat tones, the maps) keeps
// crisp edges at any scale.
//
// Text is Cairo's toy text API in "DejaVu Sans" (Debian's fonts-dejavu-core, found through
// fontconfig): the program needs no text-layout library (Pango) for its one-line labels;
// without the font fontconfig substitutes another sans font.
//
// PNG and SVG bytes are the same on every run of the same input (PDF carries its creation
// date). PNG is 8-bit RGB, every row Up-filtered (app/picture/png_encode.hpp).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;

namespace app {

struct Rgb {
  unsigned char r = 0, g = 0, b = 0;
  bool operator==(const Rgb &) const = default;
};

inline constexpr Rgb kInk{20, 20, 20};
inline constexpr Rgb kWhite{255, 255, 255};

enum class PictureFormat { png, svg, pdf };
// "png", "svg", "pdf"; the file extension without its dot.
std::string_view to_string(PictureFormat f);
// The format named (png, svg, pdf), or nothing.
std::optional<PictureFormat> picture_format_named(std::string_view name);
// The format a file name's extension asks for (.png, .svg, .pdf, any case), or nothing.
std::optional<PictureFormat> picture_format_of_file(std::string_view path);

struct PointPx {
  double x = 0.0;
  double y = 0.0;
};

struct RectPx {
  double x = 0.0;
  double y = 0.0;
  double w = 0.0;
  double h = 0.0;
};

enum class Align { left, centre, right };

class Drawing {
 public:
  // A white page width_px x height_px (each at least 1) for `format`.
  Drawing(int width_px, int height_px, PictureFormat format = PictureFormat::png);
  ~Drawing();
  Drawing(const Drawing &) = delete;
  Drawing &operator=(const Drawing &) = delete;
  Drawing(Drawing &&other) noexcept;
  Drawing &operator=(Drawing &&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  PictureFormat format() const { return format_; }

  void fill_rect(RectPx r, Rgb c);
  // Many rectangles of one colour as one shape (a maze's walls), handed over a band of rows
  // at a time: rects_in(top_px, bottom_px, add) calls add() for every rectangle that reaches
  // into the rows [top_px, bottom_px); more do no harm (the band's clip leaves them out). A
  // PNG page asks band by band (see kBandRows in drawing.cpp), so that neither the caller nor
  // Cairo holds more than a band's rectangles; SVG and PDF ask once, for the whole page, and
  // keep the order in which they were added.
  using RectSink = std::function<void(const RectPx &)>;
  using RectsInRows = std::function<void(double top_px, double bottom_px, const RectSink &add)>;
  void fill_rects(const RectsInRows &rects_in, Rgb c);
  // The rectangle's outline, the line `line_px` wide centred on its edges.
  void stroke_rect(RectPx r, double line_px, Rgb c);
  // A line through the points, round joins and caps.
  void polyline(const std::vector<PointPx> &points, double line_px, Rgb c);
  // The same through `count` points given one at a time, point_at(0) first (no copy of a
  // long line's points: a 1024 x 1024 run's path is two million of them).
  using PointAt = std::function<PointPx(std::size_t index)>;
  void polyline(std::size_t count, const PointAt &point_at, double line_px, Rgb c);
  void disc(PointPx centre, double radius_px, Rgb c);
  // A disc with a ring of `ring_px` around it.
  void ringed_disc(PointPx centre, double radius_px, Rgb c, double ring_px, Rgb ring);
  // `columns` x `rows` blocks, block (i, j) (j = 0 the top row) in tone_at(i, j), each
  // block_w x block_h px from (x, y); edges crisp (nearest-neighbour) at any scale. On a PNG
  // page at whole-pixel places and sizes the blocks are written straight into the page (no
  // copy of the tones: a 1024 x 1024 maze's map is 9.4 million of them).
  using ToneAt = std::function<Rgb(int column, int row)>;
  void blocks(const ToneAt &tone_at, int columns, int rows, PointPx top_left, double block_w, double block_h);
  // The same with the tones in a vector, tones[j * columns + i].
  void blocks(const std::vector<Rgb> &tones, int columns, int rows, PointPx top_left, double block_w,
              double block_h);

  // One line of text, `size_px` the font size, its baseline at y; x is its left end, centre
  // or right end by `align`. Returns its width.
  double text(PointPx at, std::string_view s, double size_px, Rgb c, Align align = Align::left);

  // The pixel at (x, y) of a PNG page (for the tests).
  Rgb at(int x, int y);

  // The encoded file; the page can be drawn on no more after it.
  std::string encode();

 private:
  // Calls draw() once for the whole page, or (banded, PNG only) once a band of kBandRows rows,
  // clipped to the band on whole pixels (every pixel as one call for the page would draw it).
  void each_band(bool banded, const std::function<void(int top_px, int bottom_px)> &draw);
  // blocks() on a PNG page at whole pixels: the page's words written directly.
  void write_blocks(const ToneAt &tone_at, int columns, int rows, int left_px, int top_px, int block_w_px,
                    int block_h_px);
  // blocks() through Cairo: SVG and PDF as rectangles, PNG at fractional places by scaling.
  void paint_blocks(const ToneAt &tone_at, int columns, int rows, PointPx top_left, double block_w, double block_h);

  int width_;
  int height_;
  PictureFormat format_;
  std::unique_ptr<std::string> vector_bytes_;  // SVG / PDF as Cairo writes them (a stable address)
  cairo_surface_t *surface_ = nullptr;
  cairo_t *cr_ = nullptr;
  // A PNG page's pixels, mapped by the page itself (see white_pages in drawing.cpp).
  void *pixels_ = nullptr;
  std::size_t pixels_bytes_ = 0;
};

// Text metrics of the pictures' font at `size_px`, without a page.
double text_width(std::string_view s, double size_px);
// The distance from the baseline up to the top of capitals and tall letters, and down to
// the bottom of descenders (g, p, y).
double text_ascent(double size_px);
double text_descent(double size_px);

}  // namespace app
