// A floodfill micromouse algorithm for the mms protocol, in C++ (standard library only).
//
// It talks to the simulator on standard input and output, one command a line, as it would
// to mms (github.com/mackorone/mms), so it runs unchanged there and in
//
//   maze_mapper mms worlds/classic16x16.txt --cell-size 0.18 -- build/release/examples/mms/mms_floodfill
//
// It starts in cell (0,0) facing north and searches for the centre: in each cell it asks
// for the walls around it, marks them (setWall), floods the distances to the centre through
// the walls it knows (unknown sides count as open), shows them (setText), and moves to a
// neighbour one step closer. It exits once it stands in the centre. Log lines go to
// standard error.

#include <array>
#include <cstdlib>
#include <deque>
#include <iostream>
#include <string>
#include <vector>

namespace {

// ---- the mms protocol -------------------------------------------------------------------

namespace api {

std::string command(const std::string &text, bool answered = true) {
  std::cout << text << std::endl;
  if (!answered) return {};
  std::string answer;
  if (!std::getline(std::cin, answer)) {
    std::cerr << "the simulator closed the conversation\n";
    std::exit(1);
  }
  return answer;
}

int mazeWidth() { return std::stoi(command("mazeWidth")); }
int mazeHeight() { return std::stoi(command("mazeHeight")); }
bool wallFront() { return command("wallFront") == "true"; }
bool wallRight() { return command("wallRight") == "true"; }
bool wallLeft() { return command("wallLeft") == "true"; }
bool moveForward() { return command("moveForward") == "ack"; }  // false: crash
void turnRight() { command("turnRight"); }
void turnLeft() { command("turnLeft"); }
void setWall(int x, int y, char side) {
  command("setWall " + std::to_string(x) + " " + std::to_string(y) + " " + side, false);
}
void setColor(int x, int y, char color) {
  command("setColor " + std::to_string(x) + " " + std::to_string(y) + " " + color, false);
}
void setText(int x, int y, const std::string &text) {
  command("setText " + std::to_string(x) + " " + std::to_string(y) + " " + text, false);
}

}  // namespace api

// ---- the algorithm ----------------------------------------------------------------------

constexpr std::array<char, 4> kSides{'n', 'e', 's', 'w'};
constexpr std::array<int, 4> kDx{0, 1, 0, -1};
constexpr std::array<int, 4> kDy{1, 0, -1, 0};

class Mouse {
 public:
  Mouse() : width_(api::mazeWidth()), height_(api::mazeHeight()), walls_(static_cast<std::size_t>(width_ * height_), 0),
            shown_(walls_.size(), -1) {}

  int run() {
    std::cerr << "floodfill: " << width_ << "x" << height_ << " maze, searching for the centre\n";
    int moves = 0;
    while (!goal(x_, y_)) {
      if (!step()) return 1;
      ++moves;
    }
    std::cerr << "floodfill: reached the centre (" << x_ << "," << y_ << ") in " << moves << " moves\n";
    return 0;
  }

 private:
  int index(int x, int y) const { return y * width_ + x; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  bool goal(int x, int y) const {
    return (x == (width_ - 1) / 2 || x == width_ / 2) && (y == (height_ - 1) / 2 || y == height_ / 2);
  }
  bool open(int x, int y, int side) const {
    return inside(x + kDx[side], y + kDy[side]) && (walls_[index(x, y)] & (1 << side)) == 0;
  }

  void add_wall(int side) {
    walls_[index(x_, y_)] |= static_cast<unsigned char>(1 << side);
    const int nx = x_ + kDx[side];
    const int ny = y_ + kDy[side];
    if (inside(nx, ny)) walls_[index(nx, ny)] |= static_cast<unsigned char>(1 << ((side + 2) % 4));
    api::setWall(x_, y_, kSides[side]);
  }

  void sense() {
    if (api::wallFront()) add_wall(heading_);
    if (api::wallRight()) add_wall((heading_ + 1) % 4);
    if (api::wallLeft()) add_wall((heading_ + 3) % 4);
  }

  std::vector<int> flood() const {
    std::vector<int> distance(walls_.size(), -1);
    std::deque<int> queue;
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) {
        if (!goal(x, y)) continue;
        distance[index(x, y)] = 0;
        queue.push_back(index(x, y));
      }
    }
    while (!queue.empty()) {
      const int at = queue.front();
      queue.pop_front();
      const int x = at % width_;
      const int y = at / width_;
      for (int side = 0; side < 4; ++side) {
        if (!open(x, y, side)) continue;
        const int next = index(x + kDx[side], y + kDy[side]);
        if (distance[next] >= 0) continue;
        distance[next] = distance[at] + 1;
        queue.push_back(next);
      }
    }
    return distance;
  }

  void face(int side) {
    const int quarter_turns = (side - heading_ + 4) % 4;
    if (quarter_turns == 3) {
      api::turnLeft();
    } else {
      for (int i = 0; i < quarter_turns; ++i) api::turnRight();
    }
    heading_ = side;
  }

  bool step() {
    sense();
    const std::vector<int> distance = flood();
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) {
        const int d = distance[index(x, y)];
        if (d < 0 || d == shown_[index(x, y)]) continue;
        api::setText(x, y, std::to_string(d));
        shown_[index(x, y)] = d;
      }
    }
    int best_side = -1;
    int best = -1;
    for (const int quarter_turns : {0, 1, 3, 2}) {  // straight ahead first
      const int side = (heading_ + quarter_turns) % 4;
      if (!open(x_, y_, side)) continue;
      const int d = distance[index(x_ + kDx[side], y_ + kDy[side])];
      if (d >= 0 && (best < 0 || d < best)) {
        best = d;
        best_side = side;
      }
    }
    if (best_side < 0) {
      std::cerr << "floodfill: no way to the centre from (" << x_ << "," << y_ << ")\n";
      return false;
    }
    face(best_side);
    if (!api::moveForward()) {
      std::cerr << "floodfill: crashed at (" << x_ << "," << y_ << ")\n";
      return false;
    }
    x_ += kDx[heading_];
    y_ += kDy[heading_];
    api::setColor(x_, y_, 'G');
    return true;
  }

  int width_;
  int height_;
  std::vector<unsigned char> walls_;  // per cell: bit 0 north, 1 east, 2 south, 3 west
  std::vector<int> shown_;            // the distance each cell's text shows (-1: none)
  int x_ = 0;
  int y_ = 0;
  int heading_ = 0;  // index into kSides
};

}  // namespace

int main() { return Mouse().run(); }
