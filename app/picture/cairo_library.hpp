#pragma once
// Cairo, loaded when the first picture is drawn rather than when the program starts: Cairo
// and the libraries it needs (pixman, fontconfig, freetype, X11 and xcb: sixteen of them) cost
// about 2 ms of every start, and most commands draw nothing. drawing.cpp, Cairo's only user,
// calls it through this table of its functions, by Cairo's own names without the prefix
// (cairo().arc for cairo_arc). The headers give the functions' types; nothing here links Cairo.

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

namespace app {

struct CairoLibrary {
  decltype(&::cairo_arc) arc = nullptr;
  decltype(&::cairo_clip) clip = nullptr;
  decltype(&::cairo_create) create = nullptr;
  decltype(&::cairo_destroy) destroy = nullptr;
  decltype(&::cairo_fill) fill = nullptr;
  decltype(&::cairo_font_extents) font_extents = nullptr;
  decltype(&::cairo_font_options_create) font_options_create = nullptr;
  decltype(&::cairo_font_options_destroy) font_options_destroy = nullptr;
  decltype(&::cairo_font_options_set_antialias) font_options_set_antialias = nullptr;
  decltype(&::cairo_font_options_set_hint_metrics) font_options_set_hint_metrics = nullptr;
  decltype(&::cairo_font_options_set_hint_style) font_options_set_hint_style = nullptr;
  decltype(&::cairo_format_stride_for_width) format_stride_for_width = nullptr;
  decltype(&::cairo_get_source) get_source = nullptr;
  decltype(&::cairo_image_surface_create) image_surface_create = nullptr;
  decltype(&::cairo_image_surface_create_for_data) image_surface_create_for_data = nullptr;
  decltype(&::cairo_image_surface_get_data) image_surface_get_data = nullptr;
  decltype(&::cairo_image_surface_get_height) image_surface_get_height = nullptr;
  decltype(&::cairo_image_surface_get_stride) image_surface_get_stride = nullptr;
  decltype(&::cairo_image_surface_get_width) image_surface_get_width = nullptr;
  decltype(&::cairo_line_to) line_to = nullptr;
  decltype(&::cairo_move_to) move_to = nullptr;
  decltype(&::cairo_new_path) new_path = nullptr;
  decltype(&::cairo_new_sub_path) new_sub_path = nullptr;
  decltype(&::cairo_paint) paint = nullptr;
  decltype(&::cairo_pattern_set_filter) pattern_set_filter = nullptr;
  decltype(&::cairo_pdf_surface_create_for_stream) pdf_surface_create_for_stream = nullptr;
  decltype(&::cairo_rectangle) rectangle = nullptr;
  decltype(&::cairo_restore) restore = nullptr;
  decltype(&::cairo_save) save = nullptr;
  decltype(&::cairo_scale) scale = nullptr;
  decltype(&::cairo_select_font_face) select_font_face = nullptr;
  decltype(&::cairo_set_antialias) set_antialias = nullptr;
  decltype(&::cairo_set_fill_rule) set_fill_rule = nullptr;
  decltype(&::cairo_set_font_options) set_font_options = nullptr;
  decltype(&::cairo_set_font_size) set_font_size = nullptr;
  decltype(&::cairo_set_line_cap) set_line_cap = nullptr;
  decltype(&::cairo_set_line_join) set_line_join = nullptr;
  decltype(&::cairo_set_line_width) set_line_width = nullptr;
  decltype(&::cairo_set_source_rgb) set_source_rgb = nullptr;
  decltype(&::cairo_set_source_surface) set_source_surface = nullptr;
  decltype(&::cairo_show_text) show_text = nullptr;
  decltype(&::cairo_status) status = nullptr;
  decltype(&::cairo_status_to_string) status_to_string = nullptr;
  decltype(&::cairo_stroke) stroke = nullptr;
  decltype(&::cairo_surface_destroy) surface_destroy = nullptr;
  decltype(&::cairo_surface_finish) surface_finish = nullptr;
  decltype(&::cairo_surface_flush) surface_flush = nullptr;
  decltype(&::cairo_surface_mark_dirty) surface_mark_dirty = nullptr;
  decltype(&::cairo_surface_status) surface_status = nullptr;
  decltype(&::cairo_svg_surface_create_for_stream) svg_surface_create_for_stream = nullptr;
  decltype(&::cairo_svg_surface_set_document_unit) svg_surface_set_document_unit = nullptr;
  decltype(&::cairo_text_extents) text_extents = nullptr;
  decltype(&::cairo_translate) translate = nullptr;
};

// The table, filled on first use from libcairo.so.2 (thread-safe). Throws
// common::RuntimeFailure "pictures need the Cairo library (libcairo.so.2, Debian's libcairo2):
// REASON" when it cannot be loaded or lacks a function.
const CairoLibrary &cairo();

}  // namespace app
