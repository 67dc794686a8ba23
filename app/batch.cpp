#include "app/batch.hpp"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <mutex>
#include <ostream>
#include <streambuf>
#include <thread>

#include <fmt/format.h>

#include "common/error.hpp"
#include "maze/world.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;

// An output stream that drops everything (a batch run's map and summary).
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char *, std::streamsize n) override { return n; }
};

bool loads(const std::string &path) {
  try {
    (void)maze::load_world(path);
    return true;
  } catch (const common::InputError &) {
    return false;
  }
}

BatchItem run_one(RunOptions options, const std::string &world) {
  BatchItem item;
  item.world = world;
  options.world = world;
  NullBuffer buffer;
  std::ostream sink(&buffer);
  try {
    item.summary = run_world(options, sink);
    item.ok = exit_status(item.summary) == 0;
    if (!item.ok) item.error = fmt::format("ended: {}", robot::to_string(item.summary.reason));
  } catch (const common::InputError &e) {
    item.bad_input = true;
    item.error = e.diagnostic();
  } catch (const std::exception &e) {
    item.error = fmt::format("error: {}", e.what());
  }
  return item;
}

std::string percent(double v) { return fmt::format("{:.2f}%", v); }

}  // namespace

std::vector<std::string> expand_worlds(const std::vector<std::string> &paths) {
  std::vector<std::string> worlds;
  for (const std::string &path : paths) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) {
      throw common::InputError(fmt::format("{}: no such file or directory", path));
    }
    if (!fs::is_directory(status)) {
      worlds.push_back(path);
      continue;
    }
    std::vector<std::string> files;
    for (const fs::directory_entry &entry : fs::directory_iterator(path)) {
      if (entry.is_regular_file()) files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    for (const std::string &file : files) {
      if (loads(file)) worlds.push_back(file);
    }
  }
  return worlds;
}

std::vector<BatchItem> run_batch(const RunOptions &options, const std::vector<std::string> &worlds,
                                 int jobs, const std::function<void(std::size_t, std::size_t)> &progress) {
  std::vector<BatchItem> items(worlds.size());
  std::atomic<std::size_t> next{0};
  std::mutex report;
  std::size_t done = 0;
  const auto work = [&] {
    for (std::size_t i = next++; i < worlds.size(); i = next++) {
      items[i] = run_one(options, worlds[i]);
      const std::lock_guard lock(report);
      ++done;
      if (progress) progress(done, worlds.size());
    }
  };
  const auto threads = static_cast<std::size_t>(std::max(1, jobs));
  std::vector<std::jthread> pool;
  for (std::size_t t = 1; t < std::min(threads, worlds.size()); ++t) pool.emplace_back(work);
  work();
  return items;
}

std::string format_batch_table(const std::vector<BatchItem> &items, double elapsed_ms) {
  std::size_t width = 5;
  for (const BatchItem &item : items) width = std::max(width, item.world.size());
  std::string out = fmt::format("{:<{}}  {:>9}  {:>6}  {:>8}  {:>13}  {:>7}\n", "world", width,
                                "size", "moves", "coverage", "wall_accuracy", "ms");
  int ok = 0;
  long moves = 0;
  double coverage = 0.0;
  double accuracy = 0.0;
  double run_ms = 0.0;
  for (const BatchItem &item : items) {
    if (!item.error.empty() && !item.ok && item.summary.width == 0) {
      out += fmt::format("{:<{}}  {}\n", item.world, width, item.error);
      continue;
    }
    const RunSummary &s = item.summary;
    out += fmt::format("{:<{}}  {:>9}  {:>6}  {:>8}  {:>13}  {:>7.0f}{}\n", item.world, width,
                       fmt::format("{}x{}", s.width, s.height), s.moves,
                       percent(s.score.coverage_percent()), percent(s.score.wall_accuracy_percent()),
                       s.wall_time_ms, item.ok ? "" : "  " + item.error);
    if (item.ok) ++ok;
    moves += s.moves;
    coverage += s.score.coverage_percent();
    accuracy += s.score.wall_accuracy_percent();
    run_ms += s.wall_time_ms;
  }
  const std::size_t ran = static_cast<std::size_t>(std::count_if(
      items.begin(), items.end(), [](const BatchItem &i) { return i.summary.width > 0; }));
  out += fmt::format("total: {} worlds, {} ok, {} failed; moves {}; mean coverage {}; mean "
                     "wall_accuracy {}; run time {:.0f} ms; elapsed {:.0f} ms\n",
                     items.size(), ok, items.size() - static_cast<std::size_t>(ok), moves,
                     percent(ran ? coverage / static_cast<double>(ran) : 0.0),
                     percent(ran ? accuracy / static_cast<double>(ran) : 0.0), run_ms, elapsed_ms);
  return out;
}

std::string format_batch_csv(const std::vector<BatchItem> &items) {
  const auto quoted = [](const std::string &text) {
    std::string q = "\"";
    for (const char c : text) {
      if (c == '"') q += '"';
      q += c;
    }
    return q + "\"";
  };
  std::string out = "world,size,moves,coverage,wall_accuracy,ms,end,error\n";
  for (const BatchItem &item : items) {
    const RunSummary &s = item.summary;
    if (s.width == 0) {
      out += fmt::format("{},,,,,,,{}\n", quoted(item.world), quoted(item.error));
      continue;
    }
    out += fmt::format("{},{}x{},{},{:.2f},{:.2f},{:.0f},{},{}\n", quoted(item.world), s.width,
                       s.height, s.moves, s.score.coverage_percent(), s.score.wall_accuracy_percent(),
                       s.wall_time_ms, robot::to_string(s.reason), quoted(item.error));
  }
  return out;
}

int batch_exit_status(const std::vector<BatchItem> &items) {
  if (std::all_of(items.begin(), items.end(), [](const BatchItem &i) { return i.ok; })) return 0;
  if (std::all_of(items.begin(), items.end(), [](const BatchItem &i) { return i.bad_input; })) return 2;
  return 1;
}

}  // namespace app
