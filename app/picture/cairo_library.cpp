#include "app/picture/cairo_library.hpp"

#include <dlfcn.h>

#include <cstring>
#include <string>

#include "common/error.hpp"

namespace app {
namespace {

constexpr const char *kCairoSoname = "libcairo.so.2";

[[noreturn]] void cannot_load(const std::string &reason) {
  throw common::RuntimeFailure("pictures need the Cairo library (" + std::string(kCairoSoname) +
                               ", Debian's libcairo2): " + reason);
}

// The function `symbol` of the library into `slot`.
template <typename Function>
void bind(void *library, const char *symbol, Function &slot) {
  void *address = ::dlsym(library, symbol);
  if (address == nullptr) cannot_load(std::string("it has no ") + symbol);
  static_assert(sizeof slot == sizeof address);
  std::memcpy(&slot, &address, sizeof slot);  // a function's address as dlsym gives it
}

// Contexts, surfaces, fonts and text.
void bind_surfaces_and_text(void *l, CairoLibrary &c) {
  bind(l, "cairo_create", c.create);
  bind(l, "cairo_destroy", c.destroy);
  bind(l, "cairo_font_extents", c.font_extents);
  bind(l, "cairo_font_options_create", c.font_options_create);
  bind(l, "cairo_font_options_destroy", c.font_options_destroy);
  bind(l, "cairo_font_options_set_antialias", c.font_options_set_antialias);
  bind(l, "cairo_font_options_set_hint_metrics", c.font_options_set_hint_metrics);
  bind(l, "cairo_font_options_set_hint_style", c.font_options_set_hint_style);
  bind(l, "cairo_get_source", c.get_source);
  bind(l, "cairo_format_stride_for_width", c.format_stride_for_width);
  bind(l, "cairo_image_surface_create", c.image_surface_create);
  bind(l, "cairo_image_surface_create_for_data", c.image_surface_create_for_data);
  bind(l, "cairo_image_surface_get_data", c.image_surface_get_data);
  bind(l, "cairo_image_surface_get_height", c.image_surface_get_height);
  bind(l, "cairo_image_surface_get_stride", c.image_surface_get_stride);
  bind(l, "cairo_image_surface_get_width", c.image_surface_get_width);
  bind(l, "cairo_pattern_set_filter", c.pattern_set_filter);
  bind(l, "cairo_pdf_surface_create_for_stream", c.pdf_surface_create_for_stream);
  bind(l, "cairo_select_font_face", c.select_font_face);
  bind(l, "cairo_set_font_options", c.set_font_options);
  bind(l, "cairo_set_font_size", c.set_font_size);
  bind(l, "cairo_set_source_surface", c.set_source_surface);
  bind(l, "cairo_show_text", c.show_text);
  bind(l, "cairo_status", c.status);
  bind(l, "cairo_status_to_string", c.status_to_string);
  bind(l, "cairo_surface_destroy", c.surface_destroy);
  bind(l, "cairo_surface_finish", c.surface_finish);
  bind(l, "cairo_surface_flush", c.surface_flush);
  bind(l, "cairo_surface_mark_dirty", c.surface_mark_dirty);
  bind(l, "cairo_surface_status", c.surface_status);
  bind(l, "cairo_svg_surface_create_for_stream", c.svg_surface_create_for_stream);
  bind(l, "cairo_svg_surface_set_document_unit", c.svg_surface_set_document_unit);
  bind(l, "cairo_text_extents", c.text_extents);
}

// Paths, paint and state.
void bind_drawing(void *l, CairoLibrary &c) {
  bind(l, "cairo_arc", c.arc);
  bind(l, "cairo_clip", c.clip);
  bind(l, "cairo_fill", c.fill);
  bind(l, "cairo_line_to", c.line_to);
  bind(l, "cairo_move_to", c.move_to);
  bind(l, "cairo_new_path", c.new_path);
  bind(l, "cairo_new_sub_path", c.new_sub_path);
  bind(l, "cairo_paint", c.paint);
  bind(l, "cairo_rectangle", c.rectangle);
  bind(l, "cairo_restore", c.restore);
  bind(l, "cairo_save", c.save);
  bind(l, "cairo_scale", c.scale);
  bind(l, "cairo_set_antialias", c.set_antialias);
  bind(l, "cairo_set_fill_rule", c.set_fill_rule);
  bind(l, "cairo_set_line_cap", c.set_line_cap);
  bind(l, "cairo_set_line_join", c.set_line_join);
  bind(l, "cairo_set_line_width", c.set_line_width);
  bind(l, "cairo_set_source_rgb", c.set_source_rgb);
  bind(l, "cairo_stroke", c.stroke);
  bind(l, "cairo_translate", c.translate);
}

CairoLibrary load_cairo() {
  // Never closed: pictures may be drawn until the program ends.
  void *library = ::dlopen(kCairoSoname, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    const char *reason = ::dlerror();
    cannot_load(reason != nullptr ? reason : "dlopen failed");
  }
  CairoLibrary c;
  bind_surfaces_and_text(library, c);
  bind_drawing(library, c);
  return c;
}

}  // namespace

const CairoLibrary &cairo() {
  static const CairoLibrary library = load_cairo();
  return library;
}

}  // namespace app
