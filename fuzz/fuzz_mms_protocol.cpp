// libFuzzer target: the lines an mms-protocol program writes (app::parse_mms_line), one a
// line, carried out on a 5 x 4 maze's display marks (app::MmsMarks::apply), mms's stats
// (app::MmsStats) and drawn at the end (app::render_marks). No input may crash or trip a
// sanitizer (a cell of INT_MAX, a count past an int, a text of control bytes), and every line
// must be either a command within the protocol's ranges or an error saying why.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "app/mms/mms_marks.hpp"
#include "app/mms/mms_protocol.hpp"

namespace {

constexpr std::size_t kMaxLines = 256;

// The protocol's own ranges: a side letter, a colour mms knows, at most 10 printable bytes.
bool well_formed(const app::MmsCommand &c) {
  if (c.verb == app::MmsVerb::set_wall || c.verb == app::MmsVerb::clear_wall) {
    if (std::string_view("nesw").find(c.side) == std::string_view::npos) return false;
  }
  if (c.verb == app::MmsVerb::set_color && !app::mms_color_name(c.color)) return false;
  if (c.text.size() > 10) return false;
  for (const char ch : c.text) {
    if (ch < 32 || ch > 126) return false;
  }
  return true;
}

// What the mouse adds to mms's stats for a command, without the robot: every move asked, as
// far as the protocol allows, and every turn.
void count(const app::MmsCommand &c, app::MmsStats &stats) {
  switch (c.verb) {
    case app::MmsVerb::move_forward:
      if (c.count < 1 || c.count > app::kMaxMoveCells) return;
      if (!stats.running()) stats.start_run();
      stats.add_distance(c.count);
      break;
    case app::MmsVerb::turn_left:
    case app::MmsVerb::turn_right: stats.add_turn(); break;
    case app::MmsVerb::ack_reset:
      stats.end_unfinished_run();
      stats.penalize_for_reset();
      break;
    case app::MmsVerb::get_stat:
      if (!stats.stat(c.stat)) std::abort();  // parse_mms_line accepts only names it knows
      break;
    default: break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char *>(data), size);
  app::MmsMarks marks(5, 4);
  app::MmsStats stats;
  for (std::size_t n = 0; n < kMaxLines && !text.empty(); ++n) {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    const app::ParsedLine parsed = app::parse_mms_line(line);
    if (parsed.command.has_value() == !parsed.error.empty()) std::abort();
    if (!parsed.command) continue;
    if (!well_formed(*parsed.command)) std::abort();
    (void)app::has_answer(parsed.command->verb);
    marks.apply(*parsed.command);
    count(*parsed.command, stats);
  }
  if (stats.running()) stats.finish_run();
  const std::string drawn = app::render_marks(marks, true) + app::render_marks(marks, false);
  if (drawn.empty()) std::abort();
  if (app::mms_number(stats.score()).empty()) std::abort();
  return 0;
}
