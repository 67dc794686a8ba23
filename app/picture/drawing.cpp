#include "app/picture/drawing.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <numbers>

#include "app/picture/cairo_library.hpp"
#include "app/picture/png_encode.hpp"
#include "common/error.hpp"

namespace app {
namespace {

constexpr const char *kFontFamily = "DejaVu Sans";

// Lines of this many points and more, and as many rectangles, are drawn on a PNG page a band
// of kBandRows rows at a time (see polyline and fill_rects).
constexpr std::size_t kBandedFromShapes = 10'000;
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

void Drawing::fill_rects(const std::vector<RectPx> &rects, Rgb c) {
  if (rects.empty()) return;
  set_colour(cr_, c);
  cairo().set_fill_rule(cr_, CAIRO_FILL_RULE_WINDING);
  // Many rectangles on a PNG page (a big maze's walls) are filled a band of rows at a time,
  // clipped to the band, each band with the rectangles that reach into it: Cairo's path and
  // outline are then a band's, not the whole maze's. Whole-pixel clips: the same pixels.
  const bool banded = format_ == PictureFormat::png && rects.size() >= kBandedFromShapes;
  for (int top = 0; top < height_; top += banded ? kBandRows : height_) {
    cairo().save(cr_);
    if (banded) {
      cairo().rectangle(cr_, 0.0, top, width_, kBandRows);
      cairo().clip(cr_);
    }
    for (const RectPx &r : rects) {
      if (!banded || (r.y < top + kBandRows && r.y + r.h > top)) cairo().rectangle(cr_, r.x, r.y, r.w, r.h);
    }
    cairo().fill(cr_);
    cairo().restore(cr_);
  }
}

void Drawing::stroke_rect(RectPx r, double line_px, Rgb c) {
  cairo().rectangle(cr_, r.x, r.y, r.w, r.h);
  cairo().set_line_width(cr_, line_px);
  cairo().set_line_join(cr_, CAIRO_LINE_JOIN_MITER);
  set_colour(cr_, c);
  cairo().stroke(cr_);
}

void Drawing::polyline(const std::vector<PointPx> &points, double line_px, Rgb c) {
  if (points.size() < 2) return;
  cairo().set_line_width(cr_, line_px);
  cairo().set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo().set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
  set_colour(cr_, c);
  // A long line on a PNG page is stroked a band of rows at a time, clipped to the band: Cairo
  // then leaves out the segments outside it, so that its outline of the line, about 600 bytes
  // a point (1.2 GB for the path of a 1024 x 1024 run), is a band's and not the whole line's.
  // The clip is on whole pixels: every pixel is drawn as by one stroke.
  const bool banded = format_ == PictureFormat::png && points.size() >= kBandedFromShapes;
  for (int top = 0; top < height_; top += banded ? kBandRows : height_) {
    cairo().save(cr_);
    if (banded) {
      cairo().rectangle(cr_, 0.0, top, width_, kBandRows);
      cairo().clip(cr_);
    }
    cairo().move_to(cr_, points.front().x, points.front().y);
    for (std::size_t i = 1; i < points.size(); ++i) cairo().line_to(cr_, points[i].x, points[i].y);
    cairo().stroke(cr_);
    cairo().restore(cr_);
  }
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
  if (columns <= 0 || rows <= 0) return;
  if (format_ == PictureFormat::png) {
    // One pixel a block, scaled up by nearest neighbour: exact blocks at integer scales.
    cairo_surface_t *image = cairo().image_surface_create(CAIRO_FORMAT_RGB24, columns, rows);
    cairo().surface_flush(image);
    unsigned char *data = cairo().image_surface_get_data(image);
    const int stride = cairo().image_surface_get_stride(image);
    for (int j = 0; j < rows; ++j) {
      auto *row = reinterpret_cast<std::uint32_t *>(data + static_cast<std::ptrdiff_t>(j) * stride);
      for (int i = 0; i < columns; ++i) {
        const Rgb t = tones[static_cast<std::size_t>(j) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(i)];
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
      const std::size_t first = static_cast<std::size_t>(j) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(i);
      int run = 1;
      while (i + run < columns && tones[first + static_cast<std::size_t>(run)] == tones[first]) ++run;
      fill_rect({top_left.x + i * block_w, top_left.y + j * block_h, run * block_w, block_h}, tones[first]);
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
