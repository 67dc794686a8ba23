#include "app/picture/drawing.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <numbers>

#include "app/picture/cairo_library.hpp"
#include "app/picture/png_encode.hpp"
#include "common/error.hpp"

namespace app {
namespace {

constexpr const char *kFontFamily = "DejaVu Sans";

// A PNG page's many rectangles, and its lines of this many points and more, are drawn a band
// of kBandRows rows at a time (see fill_rects and polyline).
constexpr std::size_t kBandedFromPoints = 10'000;
constexpr int kBandRows = 256;

void set_colour(cairo_t *cr, Rgb c) { cairo().set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0); }

// Grey anti-aliasing, no hinting: the same glyph shapes at every size and in every format.
void set_font(cairo_t *cr, double size_px) {
  cairo().select_font_face(cr, kFontFamily, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo().set_font_size(cr, size_px);
  cairo_font_options_t *options = cairo().font_options_create();
  cairo().font_options_set_antialias(options, CAIRO_ANTIALIAS_GRAY);
  cairo().font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
  cairo().font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  cairo().set_font_options(cr, options);
  cairo().font_options_destroy(options);
}

cairo_status_t append_bytes(void *closure, const unsigned char *data, unsigned int length) {
  static_cast<std::string *>(closure)->append(reinterpret_cast<const char *>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// A context on a 1 x 1 image for text metrics, made once.
cairo_t *metrics_context() {
  static cairo_t *cr = [] {
    cairo_surface_t *s = cairo().image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
    cairo_t *c = cairo().create(s);
    cairo().surface_destroy(s);
    return c;
  }();
  return cr;
}

void check(cairo_t *cr, const char *what) {
  const cairo_status_t status = cairo().status(cr);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw common::RuntimeFailure(std::string("cairo: ") + what + ": " + cairo().status_to_string(status));
  }
}

// `bytes` of white pixels (every byte 0xff; RGB24 ignores the top byte) in pages of their
// own. A big map's page is tens of megabytes: in huge pages where the kernel has them, it
// costs a few dozen page faults instead of thousands, and memset is cheaper than Cairo's
// paint of fresh memory (together about a tenth of a 256 x 256 run's CPU before).
void *white_pages(std::size_t bytes) {
  void *p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw common::RuntimeFailure("cairo: cannot start a picture: out of memory");
#ifdef MADV_HUGEPAGE
  ::madvise(p, bytes, MADV_HUGEPAGE);  // advice only: without huge pages the page works the same
#endif
  std::memset(p, 0xff, bytes);
  return p;
}

// The image surface's pixels as PNG (app/picture/png_encode.hpp: 8-bit RGB, the Up filter).
std::string encode_png(cairo_surface_t *surface) {
  cairo().surface_flush(surface);
  return rgb24_png(cairo().image_surface_get_data(surface), cairo().image_surface_get_width(surface),
                   cairo().image_surface_get_height(surface), cairo().image_surface_get_stride(surface));
}

}  // namespace

std::string_view to_string(PictureFormat f) {
  switch (f) {
    case PictureFormat::png: return "png";
    case PictureFormat::svg: return "svg";
    case PictureFormat::pdf: return "pdf";
  }
  return "png";
}

std::optional<PictureFormat> picture_format_named(std::string_view name) {
  for (const PictureFormat f : {PictureFormat::png, PictureFormat::svg, PictureFormat::pdf}) {
    if (name == to_string(f)) return f;
  }
  return std::nullopt;
}

std::optional<PictureFormat> picture_format_of_file(std::string_view path) {
  const std::size_t dot = path.rfind('.');
  if (dot == std::string_view::npos || path.find('/', dot) != std::string_view::npos) return std::nullopt;
  std::string extension(path.substr(dot + 1));
  for (char &ch : extension) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return picture_format_named(extension);
}

Drawing::Drawing(int width_px, int height_px, PictureFormat format)
    : width_(std::max(1, width_px)), height_(std::max(1, height_px)), format_(format),
      vector_bytes_(std::make_unique<std::string>()) {
  switch (format) {
    case PictureFormat::png: {
      const int stride = cairo().format_stride_for_width(CAIRO_FORMAT_RGB24, width_);
      pixels_bytes_ = static_cast<std::size_t>(stride) * static_cast<std::size_t>(height_);
      pixels_ = white_pages(pixels_bytes_);
      surface_ = cairo().image_surface_create_for_data(static_cast<unsigned char *>(pixels_), CAIRO_FORMAT_RGB24,
                                                       width_, height_, stride);
      break;
    }
    case PictureFormat::svg:
      surface_ = cairo().svg_surface_create_for_stream(append_bytes, vector_bytes_.get(), width_, height_);
      cairo().svg_surface_set_document_unit(surface_, CAIRO_SVG_UNIT_PX);
      break;
    case PictureFormat::pdf:
      // A pixel a PostScript point: a 480 px picture prints 6.7 inches wide.
      surface_ = cairo().pdf_surface_create_for_stream(append_bytes, vector_bytes_.get(), width_, height_);
      break;
  }
  cr_ = cairo().create(surface_);
  check(cr_, "cannot start a picture");
  if (format == PictureFormat::png) return;  // white already
  set_colour(cr_, kWhite);
  cairo().paint(cr_);
}

Drawing::Drawing(Drawing &&other) noexcept
    : width_(other.width_), height_(other.height_), format_(other.format_) {
  std::swap(surface_, other.surface_);
  std::swap(cr_, other.cr_);
  std::swap(vector_bytes_, other.vector_bytes_);
  std::swap(pixels_, other.pixels_);
  std::swap(pixels_bytes_, other.pixels_bytes_);
}

Drawing::~Drawing() {
  if (cr_ != nullptr) cairo().destroy(cr_);
  if (surface_ != nullptr) cairo().surface_destroy(surface_);
  if (pixels_ != nullptr) ::munmap(pixels_, pixels_bytes_);
}

void Drawing::fill_rect(RectPx r, Rgb c) {
  cairo().rectangle(cr_, r.x, r.y, r.w, r.h);
  set_colour(cr_, c);
  cairo().fill(cr_);
}

void Drawing::each_band(bool banded, const std::function<void(int top_px, int bottom_px)> &draw) {
  if (!banded || format_ != PictureFormat::png) {
    draw(0, height_);
    return;
  }
  for (int top = 0; top < height_; top += kBandRows) {
    const int bottom = std::min(height_, top + kBandRows);
    cairo().save(cr_);
    cairo().rectangle(cr_, 0.0, top, width_, bottom - top);
    cairo().clip(cr_);
    draw(top, bottom);
    cairo().restore(cr_);
  }
}

void Drawing::fill_rects(const RectsInRows &rects_in, Rgb c) {
  set_colour(cr_, c);
  cairo().set_fill_rule(cr_, CAIRO_FILL_RULE_WINDING);
  const RectSink add = [this](const RectPx &r) { cairo().rectangle(cr_, r.x, r.y, r.w, r.h); };
  each_band(true, [&](int top_px, int bottom_px) {
    rects_in(top_px, bottom_px, add);
    cairo().fill(cr_);
  });
}

void Drawing::stroke_rect(RectPx r, double line_px, Rgb c) {
  cairo().rectangle(cr_, r.x, r.y, r.w, r.h);
  cairo().set_line_width(cr_, line_px);
  cairo().set_line_join(cr_, CAIRO_LINE_JOIN_MITER);
  set_colour(cr_, c);
  cairo().stroke(cr_);
}

void Drawing::polyline(const std::vector<PointPx> &points, double line_px, Rgb c) {
  polyline(points.size(), [&points](std::size_t i) { return points[i]; }, line_px, c);
}

void Drawing::polyline(std::size_t count, const PointAt &point_at, double line_px, Rgb c) {
  if (count < 2) return;
  cairo().set_line_width(cr_, line_px);
  cairo().set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo().set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
  set_colour(cr_, c);
  // A long line on a PNG page is stroked a band of rows at a time, clipped to the band, with
  // only the segments that come within reach of the band: Cairo's path and its outline of the
  // line (about 600 bytes a point, 1.2 GB for the path of a 1024 x 1024 run) are then a band's.
  // With round joins and caps the stroke is the union of its segments' strokes, so where the
  // line is cut (a new sub-path) the caps fall outside the band: every pixel in it is as one
  // stroke of the whole line draws it.
  const double reach_px = line_px / 2 + 2;
  const bool banded = format_ == PictureFormat::png && count >= kBandedFromPoints;
  each_band(banded, [&](int top_px, int bottom_px) {
    const auto in_reach = [&](PointPx a, PointPx b) {
      return !banded || (std::min(a.y, b.y) - reach_px < bottom_px && std::max(a.y, b.y) + reach_px > top_px);
    };
    PointPx previous = point_at(0);
    bool drawing = false;  // previous is the end of the sub-path being drawn
    for (std::size_t i = 1; i < count; ++i) {
      const PointPx next = point_at(i);
      if (in_reach(previous, next)) {
        if (!drawing) cairo().move_to(cr_, previous.x, previous.y);
        cairo().line_to(cr_, next.x, next.y);
        drawing = true;
      } else {
        drawing = false;
      }
      previous = next;
    }
    cairo().stroke(cr_);
  });
}

void Drawing::disc(PointPx centre, double radius_px, Rgb c) {
  cairo().new_sub_path(cr_);
  cairo().arc(cr_, centre.x, centre.y, radius_px, 0.0, 2.0 * std::numbers::pi);
  set_colour(cr_, c);
  cairo().fill(cr_);
}

void Drawing::ringed_disc(PointPx centre, double radius_px, Rgb c, double ring_px, Rgb ring) {
  disc(centre, radius_px + ring_px, ring);
  disc(centre, radius_px, c);
}

void Drawing::blocks(const std::vector<Rgb> &tones, int columns, int rows, PointPx top_left, double block_w,
                     double block_h) {
  const auto width = static_cast<std::size_t>(std::max(0, columns));
  blocks([&](int i, int j) { return tones[static_cast<std::size_t>(j) * width + static_cast<std::size_t>(i)]; }, columns,
         rows, top_left, block_w, block_h);
}

void Drawing::blocks(const ToneAt &tone_at, int columns, int rows, PointPx top_left, double block_w, double block_h) {
  if (columns <= 0 || rows <= 0) return;
  const auto whole_px = [](double v, double least) { return v >= least && v <= 1e6 && v == std::floor(v); };
  if (format_ == PictureFormat::png && whole_px(top_left.x, -1e6) && whole_px(top_left.y, -1e6) && whole_px(block_w, 1) &&
      whole_px(block_h, 1)) {
    write_blocks(tone_at, columns, rows, static_cast<int>(top_left.x), static_cast<int>(top_left.y),
                 static_cast<int>(block_w), static_cast<int>(block_h));
    return;
  }
  paint_blocks(tone_at, columns, rows, top_left, block_w, block_h);
}

void Drawing::write_blocks(const ToneAt &tone_at, int columns, int rows, int left_px, int top_px, int block_w_px,
                           int block_h_px) {
  // Block (i, j) covers exactly [left + i w, left + (i + 1) w) x [top + j h, top + (j + 1) h),
  // cut to the page (Cairo's scaled nearest-neighbour fill, in 16.16 fixed point, can put a
  // block's first column in the block before it at big scales).
  const long long right_px = left_px + static_cast<long long>(columns) * block_w_px;
  const int x0 = std::clamp(left_px, 0, width_);
  const int x1 = static_cast<int>(std::clamp<long long>(right_px, 0, width_));
  if (x0 >= x1) return;
  cairo().surface_flush(surface_);
  auto *data = static_cast<unsigned char *>(pixels_);
  const int stride = cairo().image_surface_get_stride(surface_);
  std::vector<std::uint32_t> words(static_cast<std::size_t>(x1 - x0));
  for (int j = 0; j < rows; ++j) {
    const long long block_top = top_px + static_cast<long long>(j) * block_h_px;
    const int y0 = static_cast<int>(std::clamp<long long>(block_top, 0, height_));
    const int y1 = static_cast<int>(std::clamp<long long>(block_top + block_h_px, 0, height_));
    if (y0 >= y1) continue;
    for (int x = x0; x < x1;) {
      const int i = (x - left_px) / block_w_px;
      const Rgb t = tone_at(i, j);
      const std::uint32_t word = static_cast<std::uint32_t>(t.r) << 16 | static_cast<std::uint32_t>(t.g) << 8 | t.b;
      const auto end = static_cast<int>(std::min<long long>(x1, left_px + (i + 1LL) * block_w_px));
      std::fill(words.begin() + (x - x0), words.begin() + (end - x0), word);
      x = end;
    }
    for (int y = y0; y < y1; ++y) {
      std::memcpy(data + static_cast<std::ptrdiff_t>(y) * stride + static_cast<std::ptrdiff_t>(x0) * 4, words.data(),
                  words.size() * sizeof(std::uint32_t));
    }
  }
  cairo().surface_mark_dirty(surface_);
}

void Drawing::paint_blocks(const ToneAt &tone_at, int columns, int rows, PointPx top_left, double block_w,
                           double block_h) {
  if (format_ == PictureFormat::png) {
    // One pixel a block, scaled up by nearest neighbour.
    cairo_surface_t *image = cairo().image_surface_create(CAIRO_FORMAT_RGB24, columns, rows);
    cairo().surface_flush(image);
    unsigned char *data = cairo().image_surface_get_data(image);
    const int stride = cairo().image_surface_get_stride(image);
    for (int j = 0; j < rows; ++j) {
      auto *row = reinterpret_cast<std::uint32_t *>(data + static_cast<std::ptrdiff_t>(j) * stride);
      for (int i = 0; i < columns; ++i) {
        const Rgb t = tone_at(i, j);
        row[i] = static_cast<std::uint32_t>(t.r) << 16 | static_cast<std::uint32_t>(t.g) << 8 | t.b;
      }
    }
    cairo().surface_mark_dirty(image);
    cairo().save(cr_);
    cairo().translate(cr_, top_left.x, top_left.y);
    cairo().scale(cr_, block_w, block_h);
    cairo().set_source_surface(cr_, image, 0.0, 0.0);
    cairo().pattern_set_filter(cairo().get_source(cr_), CAIRO_FILTER_NEAREST);
    cairo().rectangle(cr_, 0.0, 0.0, columns, rows);
    cairo().fill(cr_);
    cairo().restore(cr_);
    cairo().surface_destroy(image);
    return;
  }
  // SVG and PDF: rectangles, a run of equal blocks in a row as one, no anti-aliasing (no
  // seams between neighbours).
  cairo().save(cr_);
  cairo().set_antialias(cr_, CAIRO_ANTIALIAS_NONE);
  for (int j = 0; j < rows; ++j) {
    int i = 0;
    while (i < columns) {
      const Rgb first = tone_at(i, j);
      int run = 1;
      while (i + run < columns && tone_at(i + run, j) == first) ++run;
      fill_rect({top_left.x + i * block_w, top_left.y + j * block_h, run * block_w, block_h}, first);
      i += run;
    }
  }
  cairo().restore(cr_);
}

double Drawing::text(PointPx at, std::string_view s, double size_px, Rgb c, Align align) {
  const std::string str(s);
  set_font(cr_, size_px);
  cairo_text_extents_t e;
  cairo().text_extents(cr_, str.c_str(), &e);
  double x = at.x;
  if (align == Align::centre) x -= e.x_advance / 2.0;
  if (align == Align::right) x -= e.x_advance;
  cairo().move_to(cr_, x, at.y);
  set_colour(cr_, c);
  cairo().show_text(cr_, str.c_str());
  cairo().new_path(cr_);
  return e.x_advance;
}

Rgb Drawing::at(int x, int y) {
  if (format_ != PictureFormat::png || x < 0 || y < 0 || x >= width_ || y >= height_) return kWhite;
  cairo().surface_flush(surface_);
  const unsigned char *data = cairo().image_surface_get_data(surface_);
  const int stride = cairo().image_surface_get_stride(surface_);
  const std::uint32_t p = reinterpret_cast<const std::uint32_t *>(data + static_cast<std::ptrdiff_t>(y) * stride)[x];
  return Rgb{static_cast<unsigned char>(p >> 16 & 0xff), static_cast<unsigned char>(p >> 8 & 0xff),
             static_cast<unsigned char>(p & 0xff)};
}

std::string Drawing::encode() {
  check(cr_, "cannot draw the picture");
  if (format_ == PictureFormat::png) return encode_png(surface_);
  cairo().destroy(cr_);
  cr_ = nullptr;
  cairo().surface_finish(surface_);
  const cairo_status_t status = cairo().surface_status(surface_);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw common::RuntimeFailure(std::string("cairo: cannot write the picture: ") + cairo().status_to_string(status));
  }
  return std::move(*vector_bytes_);
}

double text_width(std::string_view s, double size_px) {
  const std::string str(s);
  cairo_t *cr = metrics_context();
  set_font(cr, size_px);
  cairo_text_extents_t e;
  cairo().text_extents(cr, str.c_str(), &e);
  return e.x_advance;
}

namespace {

cairo_font_extents_t font_extents(double size_px) {
  cairo_t *cr = metrics_context();
  set_font(cr, size_px);
  cairo_font_extents_t e;
  cairo().font_extents(cr, &e);
  return e;
}

}  // namespace

double text_ascent(double size_px) { return font_extents(size_px).ascent; }

double text_descent(double size_px) { return font_extents(size_px).descent; }

}  // namespace app
