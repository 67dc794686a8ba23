#pragma once
// What an mms-protocol algorithm shows on the maze (setWall, setColor, setText: mms's
// display of the mouse's beliefs), kept as it sends them and drawn as text.

#include <string>
#include <vector>

namespace app {

struct MmsCommand;

// What the algorithm showed on the maze: walls it set, colours, texts (mms's display).
struct MmsMarks {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> walls;  // per cell y * W + x: N = 1, E = 2, S = 4, W = 8
  std::vector<char> colors;          // a colour letter, or 0
  std::vector<std::string> texts;

  MmsMarks(int w, int h);
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  // setWall / clearWall: the side and the neighbour's side facing it, as mms does. Any x, y
  // (INT_MIN, INT_MAX too): a cell outside the maze is left alone.
  void set_wall(int x, int y, char side, bool on);
  // A display command (setWall, clearWall, setColor, clearColor, setText, clearText,
  // clearAllColor, clearAllText) applied as mms applies it: a cell outside the maze is
  // ignored. Any other command changes nothing.
  void apply(const MmsCommand &c);
};

// The algorithm's marks drawn as a text map (o---o posts and walls, as `show` prints a
// maze), each cell showing the first 3 characters of its text, else its colour letter; with
// colour (a terminal), the cell's background in mms's colour (24-bit ANSI). Then "text (X,Y): TEXT" for texts cut short.
std::string render_marks(const MmsMarks &marks, bool color);

}  // namespace app
