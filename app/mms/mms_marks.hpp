#pragma once
// What an mms-protocol algorithm shows on the maze (setWall, setColor, setText: mms's
// display of the mouse's beliefs), kept as it sends them and drawn as text.

#include <string>
#include <vector>

namespace app {

// What the algorithm showed on the maze: walls it set, colours, texts (mms's display).
struct MmsMarks {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> walls;  // per cell y * W + x: N = 1, E = 2, S = 4, W = 8
  std::vector<char> colors;          // a colour letter, or 0
  std::vector<std::string> texts;

  MmsMarks(int w, int h);
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  // setWall / clearWall: the side and the neighbour's side facing it, as mms does.
  void set_wall(int x, int y, char side, bool on);
};

// The algorithm's marks drawn as a text map (o---o posts and walls, as `show` prints a
// maze), each cell showing the first 3 characters of its text, else its colour letter; with
// colour (a terminal), the cell's background in mms's colour (24-bit ANSI). Then "text (X,Y): TEXT" for texts cut short.
std::string render_marks(const MmsMarks &marks, bool color);

}  // namespace app
