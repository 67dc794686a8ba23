#include "app/mms/mms_marks.hpp"

#include <algorithm>
#include <cstddef>

#include <fmt/format.h>

#include "app/mms/mms_protocol.hpp"

namespace app {

MmsMarks::MmsMarks(int w, int h)
    : width(w),
      height(h),
      walls(static_cast<std::size_t>(w * h), 0),
      colors(static_cast<std::size_t>(w * h), 0),
      texts(static_cast<std::size_t>(w * h)) {}

void MmsMarks::set_wall(int x, int y, char side, bool on) {
  const auto bit = [](char s) -> unsigned char {
    switch (s) {
      case 'n': return 1;
      case 'e': return 2;
      case 's': return 4;
      default: return 8;
    }
  };
  const auto apply = [&](int cx, int cy, char s) {
    if (!inside(cx, cy)) return;
    unsigned char &cell = walls[static_cast<std::size_t>(cy * width + cx)];
    cell = on ? static_cast<unsigned char>(cell | bit(s)) : static_cast<unsigned char>(cell & ~bit(s));
  };
  if (!inside(x, y)) return;  // the neighbour of a cell outside is outside or on the edge: ignored too
  apply(x, y, side);
  switch (side) {
    case 'n': apply(x, y + 1, 's'); break;
    case 'e': apply(x + 1, y, 'w'); break;
    case 's': apply(x, y - 1, 'n'); break;
    default: apply(x - 1, y, 'e'); break;
  }
}

void MmsMarks::apply(const MmsCommand &c) {
  const bool in = inside(c.x, c.y);
  // The index only inside: y * width + x of a cell outside may overflow an int.
  const std::size_t i =
      in ? static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c.x) : 0;
  switch (c.verb) {
    case MmsVerb::set_wall:
    case MmsVerb::clear_wall: set_wall(c.x, c.y, c.side, c.verb == MmsVerb::set_wall); break;
    case MmsVerb::set_color:
      if (in) colors[i] = c.color;
      break;
    case MmsVerb::clear_color:
      if (in) colors[i] = 0;
      break;
    case MmsVerb::set_text:
      if (in) texts[i] = c.text;
      break;
    case MmsVerb::clear_text:
      if (in) texts[i].clear();
      break;
    case MmsVerb::clear_all_color: std::fill(colors.begin(), colors.end(), 0); break;
    case MmsVerb::clear_all_text:
      for (std::string &t : texts) t.clear();
      break;
    default: break;
  }
}

std::string render_marks(const MmsMarks &m, bool color) {
  std::string out;
  const auto at = [&m](int x, int y) { return static_cast<std::size_t>(y * m.width + x); };
  for (int y = m.height - 1; y >= 0; --y) {
    for (int x = 0; x < m.width; ++x) out += (m.walls[at(x, y)] & 1) != 0 ? "o---" : "o   ";
    out += "o\n";
    for (int x = 0; x < m.width; ++x) {
      out += (m.walls[at(x, y)] & 8) != 0 ? '|' : ' ';
      const std::string &text = m.texts[at(x, y)];
      const char c = m.colors[at(x, y)];
      std::string shown = !text.empty() ? text.substr(0, 3) : (c != 0 ? std::string(1, c) : std::string());
      shown.resize(3, ' ');
      if (const auto rgb = mms_color_rgb(c); color && rgb) {
        // The cell's background in mms's colour; the text black on light colours, else white.
        const int ink = rgb->r + rgb->g + rgb->b > 380 ? 30 : 97;
        out += fmt::format("\x1b[48;2;{};{};{}m\x1b[{}m{}\x1b[0m", rgb->r, rgb->g, rgb->b, ink, shown);
      } else {
        out += shown;
      }
    }
    out += (m.walls[at(m.width - 1, y)] & 2) != 0 ? "|\n" : " \n";
  }
  for (int x = 0; x < m.width; ++x) out += (m.walls[at(x, 0)] & 4) != 0 ? "o---" : "o   ";
  out += "o\n";
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) {
      const std::string &text = m.texts[at(x, y)];
      if (text.size() > 3) out += fmt::format("text ({},{}): {}\n", x, y, text);
    }
  }
  return out;
}

}  // namespace app
