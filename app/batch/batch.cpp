#include "common/csv.hpp"
#include "app/report/files_recorder.hpp"
#include "app/batch/batch.hpp"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <ostream>
#include <streambuf>
#include <thread>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "maze/world.hpp"
#include "maze/xml_arena.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;

// An output stream that drops everything (a batch run's map and summary).
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char *, std::streamsize n) override { return n; }
};

// Whether the first bytes are a format at all (a broken maze file is still run, to say why).
bool format_only(const std::string &head, const fs::path &path) {
  try {
    (void)maze::detect_format(head, path.string());
    return true;
  } catch (const common::InputError &) {
    return false;
  }
}

// Whether a file's content is one of the maze formats (its first bytes decide; an XML file,
// its walls: the course's arenas are not mazes).
bool looks_like_maze(const fs::path &path) {
  std::ifstream file(path, std::ios::binary);
  std::string head(4096, '\0');
  file.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(file.gcount()));
  try {
    // An arena (a room file, the course's XML of obstacles) is not a maze to run.
    const maze::Format format = maze::detect_format(head, path.string());
    if (format == maze::Format::room) return false;
    if (format == maze::Format::xml) return !maze::xml_world_is_arena(maze::read_file(path.string()), path.string(), {});
    return true;
  } catch (const common::InputError &) {
    return format_only(head, path);
  }
}

BatchItem run_one(RunOptions options, const BatchJob &job, bool (*interrupted)()) {
  BatchItem item;
  item.world = job_name(job);
  options.world = job.world;
  if (job.start_position) {
    options.world_overrides.start.reset();
    options.world_overrides.random_start = false;
    options.world_overrides.start_position = job.start_position;
  }
  NullBuffer buffer;
  std::ostream sink(&buffer);
  RunControls controls;
  controls.interrupted = interrupted;
  run_row(item, [&] {
    item.summary = run_and_write(options, sink, controls);
    item.report = run_report(options, item.summary);
    item.ran = true;
    item.interrupted = item.summary.interrupted;
    item.ok = exit_status(item.summary) == 0;
    if (!item.ok) {
      item.error = item.summary.message.empty()
                       ? fmt::format("ended: {}", robot::to_string(item.summary.reason))
                       : fmt::format("ended: {} ({})", robot::to_string(item.summary.reason), item.summary.message);
    }
  });
  return item;
}

std::string percent(double v) { return fmt::format("{:.2f}%", v); }

}  // namespace

bool natural_less(const std::string &a, const std::string &b) {
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    if (!digit(a[i]) || !digit(b[j])) {
      if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
      ++i;
      ++j;
      continue;
    }
    // Two runs of digits: the shorter without its leading zeros is the smaller number; equal
    // numbers compare by their leading zeros last, so that the order stays strict.
    std::size_t ei = i;
    std::size_t ej = j;
    while (ei < a.size() && digit(a[ei])) ++ei;
    while (ej < b.size() && digit(b[ej])) ++ej;
    std::size_t si = i;
    std::size_t sj = j;
    while (si + 1 < ei && a[si] == '0') ++si;
    while (sj + 1 < ej && b[sj] == '0') ++sj;
    const std::string_view x(a.data() + si, ei - si);
    const std::string_view y(b.data() + sj, ej - sj);
    if (x.size() != y.size()) return x.size() < y.size();
    if (x != y) return x < y;
    if (ei - i != ej - j) return ei - i < ej - j;
    i = ei;
    j = ej;
  }
  return a.size() - i < b.size() - j;
}

namespace {

// "a folder", "a dangling link", "a FIFO", ...: why a folder's entry is no file to run.
std::string kind_of(const fs::path &entry) {
  std::error_code ec;
  const fs::file_status target = fs::status(entry, ec);
  if (fs::is_symlink(fs::symlink_status(entry, ec)) && !fs::exists(target)) return "a dangling link";
  if (fs::is_directory(target)) return "a folder: folders are not searched";
  if (fs::is_fifo(target)) return "a FIFO";
  if (fs::is_block_file(target) || fs::is_character_file(target)) return "a device";
  if (fs::is_socket(target)) return "a socket";
  return "not a regular file";
}

}  // namespace

WorldList expand_worlds(const std::vector<std::string> &paths) {
  WorldList list;
  for (const std::string &path : paths) {
    std::error_code ec;
    if (!fs::is_directory(path, ec)) {
      list.worlds.push_back(path);
      continue;
    }
    std::vector<fs::path> files;
    std::vector<fs::path> others;  // subfolders, dangling links, FIFOs, devices, sockets
    for (const fs::directory_entry &entry : fs::directory_iterator(path, ec)) {
      std::error_code entry_ec;
      (entry.is_regular_file(entry_ec) ? files : others).push_back(entry.path());
    }
    if (ec) throw common::InputError(fmt::format("{}: cannot list the folder: {}", path, ec.message()));
    std::sort(files.begin(), files.end(),
              [](const fs::path &a, const fs::path &b) { return natural_less(a.string(), b.string()); });
    for (const fs::path &file : files) {
      (looks_like_maze(file) ? list.worlds : list.skipped).push_back(file.string());
    }
    std::sort(others.begin(), others.end(),
              [](const fs::path &a, const fs::path &b) { return natural_less(a.string(), b.string()); });
    for (const fs::path &other : others) list.skipped.push_back(fmt::format("{} ({})", other.string(), kind_of(other)));
  }
  return list;
}

std::string job_name(const BatchJob &job) {
  return job.start_position ? fmt::format("{} pos:{}", job.world, *job.start_position) : job.world;
}

std::vector<BatchJob> plain_jobs(const std::vector<std::string> &worlds) {
  std::vector<BatchJob> jobs;
  for (const std::string &w : worlds) jobs.push_back({w, std::nullopt});
  return jobs;
}

std::vector<BatchJob> each_start_jobs(const std::vector<std::string> &worlds, const maze::WorldOverrides &overrides) {
  std::vector<BatchJob> jobs;
  for (const std::string &w : worlds) {
    std::size_t count = 0;
    try {
      maze::WorldOverrides size_only;
      size_only.cell_size_m = overrides.cell_size_m;
      count = maze::load_world(w, size_only).maze.start_positions().size();
    } catch (const common::InputError &) {
      jobs.push_back({w, std::nullopt});  // its run says why
      continue;
    }
    for (std::size_t n = 1; n <= count; ++n) jobs.push_back({w, static_cast<int>(n)});
  }
  return jobs;
}

std::vector<BatchItem> run_batch(const RunOptions &options, const std::vector<std::string> &worlds,
                                 int jobs, const std::function<void(std::size_t, std::size_t)> &progress,
                                 bool (*interrupted)()) {
  return run_batch(options, plain_jobs(worlds), jobs, progress, interrupted);
}

void for_each_in_pool(std::size_t count, int jobs, const std::function<void(std::size_t)> &run,
                      const std::function<void(std::size_t)> &skip,
                      const std::function<void(std::size_t, std::size_t)> &progress, bool (*interrupted)()) {
  std::atomic<std::size_t> next{0};
  std::mutex report;
  std::size_t done = 0;
  const auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      if (interrupted != nullptr && interrupted()) {
        skip(i);
        continue;
      }
      run(i);
      const std::lock_guard lock(report);
      ++done;
      if (progress) progress(done, count);
    }
  };
  const auto threads = static_cast<std::size_t>(std::max(1, jobs));
  std::vector<std::jthread> pool;
  for (std::size_t t = 1; t < std::min(threads, count); ++t) pool.emplace_back(work);
  work();
}

std::vector<BatchItem> run_batch(const RunOptions &options, const std::vector<BatchJob> &worlds,
                                 int jobs, const std::function<void(std::size_t, std::size_t)> &progress,
                                 bool (*interrupted)()) {
  std::vector<BatchItem> items(worlds.size());
  for_each_in_pool(
      worlds.size(), jobs, [&](std::size_t i) { items[i] = run_one(options, worlds[i], interrupted); },
      [&](std::size_t i) {
        items[i].world = job_name(worlds[i]);
        items[i].interrupted = true;
        items[i].error = "not run (interrupted by " + common::interrupt_name() + ")";
      },
      progress, interrupted);
  return items;
}

namespace {

// The goal column: the report's "goal" ("reached", "not reached"), or nothing when the run
// was not asked to reach one.
std::string goal_cell(const BatchItem &item) { return item.report ? item.report->text("goal") : ""; }

// The speed-run column: the report's speed run's cells, or nothing when none was made.
std::string speed_run_cell(const BatchItem &item) {
  const ReportEntry *run = item.report ? item.report->find("speed_run") : nullptr;
  return run != nullptr && run->json.is_object() ? run->json["cells"].dump() : "";
}

}  // namespace

void add_to_totals(BatchTotals &t, const BatchRow &row) {
  ++t.worlds;
  if (row.interrupted) ++t.interrupted;
  if (row.ok) ++t.ok;
  if (!row.ran) return;
  ++t.ran;
  t.moves += row.moves;
  t.coverage_sum += row.coverage_percent;
  t.accuracy_sum += row.wall_accuracy_percent;
  t.run_ms += row.ms;
  if (!row.goal.empty()) ++t.with_goal;
  if (row.goal == "reached") ++t.goal_reached;
}

std::string format_totals(const BatchTotals &t) {
  const int failed = t.worlds - t.ok - t.interrupted;
  std::string out = fmt::format("total: {} worlds, {} ok, {} failed", t.worlds, t.ok, failed);
  if (t.interrupted > 0) out += fmt::format(", {} interrupted", t.interrupted);
  const double ran = static_cast<double>(t.ran);
  out += fmt::format("; moves {}; mean coverage {}; mean wall_accuracy {}", t.moves,
                     percent(t.ran ? t.coverage_sum / ran : 0.0), percent(t.ran ? t.accuracy_sum / ran : 0.0));
  if (t.with_goal > 0) out += fmt::format("; goal reached {} of {}", t.goal_reached, t.with_goal);
  return out + fmt::format("; run time {:.0f} ms", t.run_ms);
}

BatchRow row_of(const BatchItem &item) {
  BatchRow row;
  row.world = item.world;
  row.ran = item.ran;
  row.ok = item.ok;
  row.interrupted = item.interrupted;
  row.error = item.error;
  if (!item.ran) return row;
  const RunSummary &s = item.summary;
  row.size = fmt::format("{}x{}", s.width, s.height);
  row.moves = s.moves;
  row.coverage_percent = s.score.coverage_percent();
  row.wall_accuracy_percent = s.score.wall_accuracy_percent();
  row.goal = goal_cell(item);
  row.speed_run = speed_run_cell(item);
  row.ms = s.wall_time_ms;
  row.end = std::string(robot::to_string(s.reason));
  return row;
}

std::string format_batch_table(const std::vector<BatchItem> &items, double elapsed_ms,
                               const std::vector<std::string> &skipped) {
  std::size_t width = 5;
  for (const BatchItem &item : items) width = std::max(width, item.world.size());
  std::string out = fmt::format("{:<{}}  {:>9}  {:>6}  {:>8}  {:>13}  {:>11}  {:>9}  {:>7}  {}\n", "world", width,
                                "size", "moves", "coverage", "wall_accuracy", "goal", "speed_run", "ms", "end");
  BatchTotals totals;
  for (const BatchItem &item : items) {
    add_to_totals(totals, row_of(item));
    if (!item.ran) {
      out += fmt::format("{:<{}}  {}\n", item.world, width, item.error);
      continue;
    }
    const RunSummary &s = item.summary;
    const auto dash = [](const std::string &text) { return text.empty() ? std::string("-") : text; };
    const std::string end = s.message.empty() ? std::string(robot::to_string(s.reason))
                                              : fmt::format("{} ({})", robot::to_string(s.reason), s.message);
    out += fmt::format("{:<{}}  {:>9}  {:>6}  {:>8}  {:>13}  {:>11}  {:>9}  {:>7.0f}  {}\n", item.world, width,
                       fmt::format("{}x{}", s.width, s.height), s.moves,
                       percent(s.score.coverage_percent()), percent(s.score.wall_accuracy_percent()),
                       dash(goal_cell(item)), dash(speed_run_cell(item)), s.wall_time_ms, end);
  }
  out += format_totals(totals) + fmt::format("; elapsed {:.0f} ms", elapsed_ms);
  if (!skipped.empty()) {
    constexpr std::size_t kNamed = 3;
    std::string names;
    for (std::size_t i = 0; i < std::min(kNamed, skipped.size()); ++i) names += (i ? ", " : "") + skipped[i];
    if (skipped.size() > kNamed) names += fmt::format(" and {} more", skipped.size() - kNamed);
    out += fmt::format("; {} skipped, not mazes: {}", skipped.size(), names);
  }
  return out + "\n";
}

std::string format_batch_csv_row(const BatchRow &row) {
  if (!row.ran) return fmt::format("{},,,,,,,,,{}\n", common::csv_field(row.world), common::csv_field(row.error));
  return fmt::format("{},{},{},{:.2f},{:.2f},{},{},{:.0f},{},{}\n", common::csv_field(row.world), row.size, row.moves,
                     row.coverage_percent, row.wall_accuracy_percent, row.goal, row.speed_run, row.ms, row.end,
                     common::csv_field(row.error));
}

std::string format_batch_csv(const std::vector<BatchItem> &items) {
  std::string out(kBatchCsvHeader);
  out += '\n';
  for (const BatchItem &item : items) {
    if (!item.interrupted) out += format_batch_csv_row(row_of(item));
  }
  return out;
}

int batch_exit_status(const std::vector<BatchItem> &items) {
  if (std::any_of(items.begin(), items.end(), [](const BatchItem &i) { return i.interrupted; })) return common::interrupted_exit_status();
  if (std::all_of(items.begin(), items.end(), [](const BatchItem &i) { return i.ok; })) return 0;
  if (std::all_of(items.begin(), items.end(), [](const BatchItem &i) { return i.bad_input; })) return 2;
  return 1;
}

}  // namespace app
