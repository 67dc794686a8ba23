// The drawing module's big-picture paths, pixel by pixel: blocks written straight into a PNG
// page at whole pixels, many rectangles and long lines drawn a band of rows at a time.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "app/picture/drawing.hpp"

namespace {

using app::PointPx;
using app::RectPx;
using app::Rgb;

Rgb tone_of(int column, int row) {
  return Rgb{static_cast<unsigned char>(10 * column), static_cast<unsigned char>(40 * row), 77};
}

}  // namespace

TEST_CASE("blocks at whole pixels: every block's pixels exactly, its first and last column and row included") {
  // 102 px blocks: the size where a scaled nearest-neighbour fill put a block's first column
  // in the block before it, 2 px from the page's left.
  const int columns = 16;
  const int rows = 3;
  const int block = 102;
  const PointPx at{13, 7};
  app::Drawing page(13 + columns * block + 20, 7 + rows * block + 20);
  page.blocks(tone_of, columns, rows, at, block, block);
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const int left = 13 + i * block;
      const int top = 7 + j * block;
      for (const int x : {left, left + block / 2, left + block - 1}) {
        for (const int y : {top, top + block - 1}) {
          CAPTURE(i);
          CAPTURE(j);
          CHECK(page.at(x, y) == tone_of(i, j));
        }
      }
    }
  }
  CHECK(page.at(12, 50) == app::kWhite);
  CHECK(page.at(13 + columns * block, 50) == app::kWhite);
  CHECK(page.at(50, 7 + rows * block) == app::kWhite);
}

TEST_CASE("blocks cut at the page's edges and at fractional places still fill what they cover") {
  app::Drawing page(100, 60);
  page.blocks(tone_of, 4, 2, PointPx{-30, 20}, 40, 40);  // columns 0 and 1 partly off the page
  CHECK(page.at(0, 30) == tone_of(0, 0));
  CHECK(page.at(10, 30) == tone_of(1, 0));
  CHECK(page.at(99, 59) == tone_of(3, 0));
  CHECK(page.at(50, 10) == app::kWhite);
  app::Drawing fractional(100, 60);
  fractional.blocks(tone_of, 2, 1, PointPx{10.5, 10.5}, 20.25, 20.25);
  CHECK(fractional.at(20, 20) == tone_of(0, 0));
  CHECK(fractional.at(40, 20) == tone_of(1, 0));
  CHECK(fractional.at(5, 5) == app::kWhite);
}

TEST_CASE("many rectangles given a band of rows at a time: each filled whole, the gaps white") {
  // A column of 40 bars 10 px high, 20 px apart, over 800 rows: bands of 256 rows cut some.
  std::vector<RectPx> bars;
  for (int k = 0; k < 40; ++k) bars.push_back({20.0, 5.0 + 20.0 * k, 60.0, 10.0});
  int png_calls = 0;
  app::Drawing page(100, 810);
  page.fill_rects(
      [&](double top, double bottom, const app::Drawing::RectSink &add) {
        ++png_calls;
        for (const RectPx &r : bars) {
          if (r.y < bottom && r.y + r.h > top) add(r);  // only the band's, as a caller should
        }
      },
      app::kInk);
  CHECK(png_calls == 4);  // rows 0-255, 256-511, 512-767, 768-809
  for (const RectPx &r : bars) {
    for (const double y : {r.y, r.y + r.h - 1}) {
      CHECK(page.at(static_cast<int>(r.x), static_cast<int>(y)) == app::kInk);
      CHECK(page.at(static_cast<int>(r.x + r.w - 1), static_cast<int>(y)) == app::kInk);
    }
    CHECK(page.at(static_cast<int>(r.x), static_cast<int>(r.y + r.h)) == app::kWhite);
  }
  int svg_calls = 0;
  app::Drawing svg(100, 810, app::PictureFormat::svg);
  svg.fill_rects(
      [&](double top, double bottom, const app::Drawing::RectSink &add) {
        ++svg_calls;
        CHECK(top == 0.0);
        CHECK(bottom == 810.0);
        add(bars.front());
      },
      app::kInk);
  CHECK(svg_calls == 1);
}

TEST_CASE("a long line drawn a band at a time: every segment drawn, nothing beside it") {
  // 12,001 points (a line this long is drawn in bands) along the page's top rows, but for a
  // jump down to the bottom row and back every 1000 points: those segments cross bands with no
  // end in them.
  std::vector<PointPx> points;
  for (int i = 0; i <= 12'000; ++i) {
    const double x = 20.0 + i * 0.075;
    points.push_back({x, i % 1000 == 500 ? 990.0 : 20.0 + i % 7});
  }
  app::Drawing page(960, 1000);
  page.polyline(points.size(), [&](std::size_t i) { return points[i]; }, 3.0, app::kInk);
  int undrawn = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    for (const double f : {0.25, 0.5, 0.75}) {
      const PointPx p{points[i - 1].x + f * (points[i].x - points[i - 1].x),
                      points[i - 1].y + f * (points[i].y - points[i - 1].y)};
      // Dark: where the line overlaps itself Cairo's coverage can fall a hair short of ink.
      if (page.at(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))).r > 60) ++undrawn;
    }
  }
  CHECK(undrawn == 0);
  CHECK(page.at(5, 5) == app::kWhite);  // beyond every segment's reach
  CHECK(page.at(600, 600) == app::kWhite);
}
