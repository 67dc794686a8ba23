#include "app/batch/batch.hpp"
#include "app/run/report_keys.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <ostream>
#include <streambuf>
#include <thread>

#include <fmt/format.h>

#include "app/report/files_recorder.hpp"
#include "common/csv.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "maze/world/world.hpp"
#include "maze/world/world.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;

// An output stream that drops everything (a batch run's map and summary).
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char *, std::streamsize n) override { return n; }
};

// What a file's content is: no world, a maze, or an arena (a room file, the course's XML of
// obstacles). A file whose format is known but does not read is the format's kind (it is run,
// to say why).
enum class Content { none, maze, arena };

Content content_of(const fs::path &path) {
  maze::Format format{};
  try {
    format = maze::read_world_format(path.string());  // as far as telling it takes, as show tells it
  } catch (const common::InputError &) {
    return Content::none;
  }
  try {
    if (format == maze::Format::room) return Content::arena;
    if (format != maze::Format::xml) return Content::maze;
    const std::string text = maze::read_world_file(path.string()).text;  // XML: the whole tells
    return maze::holds_arena(text, format, path.string()) ? Content::arena : Content::maze;
  } catch (const common::InputError &) {
    return Content::maze;
  }
}

// Whether `choice` runs a folder's file of this content.
bool runs(KindChoice choice, Content content) {
  if (content == Content::none) return false;
  return choice != KindChoice::maze || content == Content::maze;
}

// The run's "end" line as a failed row says it: "ended: incomplete (3 cells unvisited)".
std::string ended_error(std::string_view ending, const std::string &message) {
  return fmt::format("ended: {}", end_text(ending, message));
}

void run_maze(RunOptions options, const BatchJob &job, const RunControls &controls, BatchItem &item) {
  options.world = job.world;
  if (job.start_position) {
    options.world_overrides.start.reset();
    options.world_overrides.random_start = false;
    options.world_overrides.start_position = job.start_position;
  }
  NullBuffer buffer;
  std::ostream sink(&buffer);
  item.summary = run_and_write(options, sink, controls);
  item.report = run_report(options, item.summary);
  item.ran = true;
  item.interrupted = item.summary.interrupted;
  item.ok = exit_status(item.summary) == 0;
  if (!item.ok) item.error = ended_error(robot::to_string(item.summary.reason), item.summary.message);
}

void run_room_job(RunOptions options, const BatchJob &job, bool (*interrupted)(), BatchItem &item) {
  const auto started = std::chrono::steady_clock::now();
  options.world = job.world;
  const maze::World world = maze::load_world(job.world);
  NullBuffer buffer;
  std::ostream sink(&buffer);
  Report report;
  const MetricRunSummary summary = run_metric_world(world, options, sink, started, interrupted, &report);
  item.report = std::move(report);
  item.ran = true;
  item.interrupted = summary.interrupted;
  item.ok = metric_run_exit_status(summary) == 0;
  if (!item.ok) item.error = ended_error(robot::to_string(summary.ending), summary.message);
}

BatchItem run_one(const BatchOptions &options, const BatchJob &job, bool (*interrupted)()) {
  BatchItem item;
  item.world = job_name(job);
  item.kind = job.kind;
  RunControls controls;
  controls.interrupted = interrupted;
  run_row(item, [&] {
    if (job.kind == RunKind::room) run_room_job(options.room, job, interrupted, item);
    else run_maze(options.run, job, controls, item);
  });
  return item;
}

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

KindChoice parse_kind_choice(const std::string &text) {
  if (text == "auto") return KindChoice::automatic;
  if (text == "maze") return KindChoice::maze;
  if (text == "room") return KindChoice::room;
  throw common::InputError(fmt::format("--kind must be auto, maze or room (got '{}')", text));
}

WorldList expand_worlds(const std::vector<std::string> &paths, KindChoice choice) {
  WorldList list;
  if (choice != KindChoice::maze) list.skipped_as = "not worlds";
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
      (runs(choice, content_of(file)) ? list.worlds : list.skipped).push_back(file.string());
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

RunKind run_kind_of(const std::string &path, KindChoice choice) {
  if (choice == KindChoice::room) return RunKind::room;
  if (choice == KindChoice::maze) return RunKind::maze;
  std::error_code ec;
  return fs::is_regular_file(path, ec) && content_of(path) == Content::arena ? RunKind::room : RunKind::maze;
}

std::vector<BatchJob> plain_jobs(const std::vector<std::string> &worlds, KindChoice choice) {
  std::vector<BatchJob> jobs;
  for (const std::string &w : worlds) jobs.push_back({w, std::nullopt, run_kind_of(w, choice)});
  return jobs;
}

std::vector<BatchJob> each_start_jobs(const std::vector<std::string> &worlds, const maze::WorldOverrides &overrides,
                                      KindChoice choice) {
  std::vector<BatchJob> jobs;
  for (const std::string &w : worlds) {
    const RunKind kind = run_kind_of(w, choice);
    if (kind == RunKind::room) {
      jobs.push_back({w, std::nullopt, kind});  // a room run starts where its world says
      continue;
    }
    std::size_t count = 0;
    try {
      maze::WorldOverrides size_only;
      size_only.cell_size_m = overrides.cell_size_m;
      count = maze::load_world(w, size_only).maze().start_positions().size();
    } catch (const common::InputError &) {
      jobs.push_back({w, std::nullopt, kind});  // its run says why
      continue;
    }
    for (std::size_t n = 1; n <= count; ++n) jobs.push_back({w, static_cast<int>(n), kind});
  }
  return jobs;
}

BatchOptions::BatchOptions(RunOptions run_options)
    : run(std::move(run_options)),
      room(room_options_for(run, metres_run_options(), [](std::string_view) { return false; })) {}

BatchOptions::BatchOptions(RunOptions run_options, RunOptions room_options)
    : run(std::move(run_options)), room(std::move(room_options)) {}

RunOptions room_options_for(const RunOptions &options, const RunOptions &room_only,
                            const std::function<bool(std::string_view)> &given) {
  RunOptions room = options;
  room.strategy = room_only.strategy;
  room.metres = room_only.metres;
  room.output.quiet = true;
  room.model = sensing::ModelOptions{};
  room.model.kind = sensing::ModelKind::ray;  // the room command's default
  if (given("--model") && options.model.kind != sensing::ModelKind::cell) room.model = options.model;
  if (!given("--robot")) room.robot.clear();  // the set-up's
  const bool ranges_only = room.model.kind == sensing::ModelKind::bump || room.model.kind == sensing::ModelKind::depth;
  if (ranges_only && !given("--log-base")) room.sensor.base = mapping::LogBase::ten;
  return room;
}

std::vector<BatchItem> run_batch(const BatchOptions &options, const std::vector<std::string> &worlds,
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

std::vector<BatchItem> run_batch(const BatchOptions &options, const std::vector<BatchJob> &worlds,
                                 int jobs, const std::function<void(std::size_t, std::size_t)> &progress,
                                 bool (*interrupted)()) {
  std::vector<BatchItem> items(worlds.size());
  for_each_in_pool(
      worlds.size(), jobs, [&](std::size_t i) { items[i] = run_one(options, worlds[i], interrupted); },
      [&](std::size_t i) {
        items[i].world = job_name(worlds[i]);
        items[i].kind = worlds[i].kind;
        items[i].interrupted = true;
        items[i].error = "not run (interrupted by " + common::interrupt_name() + ")";
      },
      progress, interrupted);
  return items;
}

BatchRow row_of(const BatchItem &item) {
  BatchRow row;
  if (item.ran && item.report) row = row_from_report(*item.report);
  row.world = item.world;
  row.kind = item.kind;
  row.ok = item.ok;
  row.interrupted = item.interrupted;
  row.error = item.error;
  return row;
}

namespace {

std::string dash(const std::string &text) { return text.empty() ? std::string("-") : text; }
std::string percent_cell(const std::optional<double> &v) { return v ? fmt::format("{:.2f}%", *v) : "-"; }

// The table's cells of a row that ran, in kTableColumns' order (cell_accuracy's only when
// `rooms`).
std::vector<std::string> table_cells(const BatchRow &row, bool rooms) {
  std::vector<std::string> cells{dash(row.size), row.moves ? std::to_string(*row.moves) : "-",
                                 percent_cell(row.coverage_percent), percent_cell(row.wall_accuracy_percent)};
  if (rooms) cells.push_back(percent_cell(row.cell_accuracy_percent));
  cells.insert(cells.end(), {dash(row.goal), dash(row.speed_run),
                             row.wall_time_ms ? fmt::format("{:.0f}", *row.wall_time_ms) : "-"});
  return cells;
}

// The right-aligned columns between world and end: name and width.
struct TableColumn {
  std::string_view name;
  int width;
};
constexpr TableColumn kTableColumns[] = {{"size", 9},          {"moves", 6},        {report_key::coverage, 8},
                                         {report_key::wall_accuracy, 13}, {report_key::cell_accuracy, 13}, {"goal", 11},
                                         {"speed_run", 9},     {"ms", 7}};

std::string table_line(const std::string &world, std::size_t world_width, const std::vector<std::string> &cells,
                       bool rooms, const std::string &end) {
  std::string line = fmt::format("{:<{}}", world, world_width);
  std::size_t cell = 0;
  for (const TableColumn &column : kTableColumns) {
    if (column.name == report_key::cell_accuracy && !rooms) continue;
    line += fmt::format("  {:>{}}", cells[cell++], column.width);
  }
  return line + "  " + end + "\n";
}

}  // namespace

std::string format_batch_table(const std::vector<BatchItem> &items, double elapsed_ms,
                               const std::vector<std::string> &skipped, std::string_view skipped_as) {
  std::size_t width = 5;
  bool rooms = false;
  for (const BatchItem &item : items) {
    width = std::max(width, item.world.size());
    rooms = rooms || item.kind == RunKind::room;
  }
  std::vector<std::string> names;
  for (const TableColumn &column : kTableColumns) names.emplace_back(column.name);
  if (!rooms) names.erase(names.begin() + 4);
  std::string out = table_line("world", width, names, rooms, "end");
  BatchTotals totals;
  for (const BatchItem &item : items) {
    const BatchRow row = row_of(item);
    add_to_totals(totals, row);
    if (!item.ran) {
      out += fmt::format("{:<{}}  {}\n", item.world, width, item.error);
      continue;
    }
    out += table_line(item.world, width, table_cells(row, rooms), rooms, end_text(row.end, row.end_message));
  }
  out += format_totals(totals) + fmt::format("; elapsed {:.0f} ms", elapsed_ms);
  if (!skipped.empty()) {
    constexpr std::size_t kNamed = 3;
    std::string names_text;
    for (std::size_t i = 0; i < std::min(kNamed, skipped.size()); ++i) names_text += (i ? ", " : "") + skipped[i];
    if (skipped.size() > kNamed) names_text += fmt::format(" and {} more", skipped.size() - kNamed);
    out += fmt::format("; {} skipped, {}: {}", skipped.size(), skipped_as, names_text);
  }
  return out + "\n";
}

std::string format_batch_csv(const std::vector<BatchItem> &items) {
  std::string out = batch_csv_header() + '\n';
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
