#pragma once
// Telling a world file's format, the one rule every reader of worlds goes by (show, run,
// batch, convert and the rest, through read_world_file and detect_format in world_files.hpp):
//
//   a binary .maz      the first byte that is not a tab, LF or CR is 0x01 to 0x0F (a cell's
//                      wall bits; text has none)
//   otherwise the first meaningful line decides: after a UTF-8 BOM, lines that are blank
//   (blanks, tabs, a CR) or comments ('#' first, the room format's comments) are skipped, and
//                      '<' first               XML
//                      'o' or '+' first        a text map
//                      a digit first           a num file
//                      a room keyword first    a room file (name, boundary, rect, wall,
//                                              start, goal)
//   a first line "#VRML_SIM ..." is a Webots world, written but not read.
//
// The bytes are looked at as they arrive, each once: a file read in pieces (a pipe) is told
// as the same file read at once, and only as much is read as the decision needs. A file
// whose first meaningful line does not start within common::kFormatLineWithinBytes (1 MiB) is
// refused there, with the line the look stopped at.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "common/input_file.hpp"
#include "maze/world/world_files.hpp"

namespace maze {

class FormatDetector {
 public:
  explicit FormatDetector(std::string file, std::size_t within = common::kFormatLineWithinBytes)
      : file_(std::move(file)), within_(within) {}

  // `text`: the file's first bytes, each call the same bytes and maybe more; `at_end`: the
  // file has no more. The format once the bytes tell it (at the end they always do); nothing
  // while more bytes may change it. Throws common::InputError: "the file is empty", "cannot
  // tell the format" (LINE:COL of the first meaningful line, or of where the look stopped).
  std::optional<Format> look(std::string_view text, bool at_end);

 private:
  bool look_at_start(std::string_view text, bool at_end);
  std::optional<Format> first_meaningful(std::string_view text, bool at_end) const;
  [[noreturn]] void cannot_tell(int line, int column, std::string_view why) const;

  std::string file_;
  std::size_t within_;
  bool started_ = false;      // the BOM and a .wbt first line looked at
  bool maz_possible_ = true;  // only tabs, LFs and CRs so far
  bool in_comment_ = false;
  std::size_t pos_ = 0;  // the next byte to look at
  std::size_t line_start_ = 0;
  int line_ = 1;
};

}  // namespace maze
