// The directory of `run --out DIR` (app/report/output_dir.hpp).

#include "app/report/output_dir.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/standard_streams.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;

// The first missing ancestor of dir (dir itself when only it is missing), to remove on failure.
// A link is there, dangling or not: never counted missing, so never removed.
fs::path first_missing(const fs::path &dir) {
  fs::path missing;
  for (fs::path p = dir; !p.empty(); p = p.parent_path()) {
    std::error_code ec;
    if (fs::exists(fs::symlink_status(p, ec)) || ec) break;
    missing = p;
    if (p == p.parent_path()) break;
  }
  return missing;
}

void probe_writable(const std::string &dir) {
  const fs::path probe = fs::path(dir) / fmt::format(".maze_mapper.probe.{}", ::getpid());
  const std::string name = probe.string();
  const int slot = common::register_temporary(name);  // a signal meanwhile removes it
  const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  const int open_errno = errno;
  if (fd >= 0) {
    ::close(fd);
    ::unlink(name.c_str());
  }
  common::unregister_temporary(slot);
  if (fd < 0) refuse_out_dir(dir, fmt::format("cannot create a file there: {}", std::strerror(open_errno)));
}



// The names write_outputs() may write in DIR (snapshots/ apart).
constexpr std::array<const char *, 15> kOutputNames{
    "map.pgm",   "map.yaml",  "map.png",   "map.svg",   "map.pdf",     "truth.png", "truth.svg", "truth.pdf",
    "summary.json", "trace.csv", "replay.html", "plan.png", "plan.svg", "plan.pdf", "plan.csv"};

// Where `name` comes in the wrote line: a core name at its place in kOutputNames, the
// snapshots right after trace.csv, a kind's own names after every core name.
double line_rank(const std::string &name) {
  const auto rank_of = [](std::string_view core) {
    return static_cast<double>(std::find(kOutputNames.begin(), kOutputNames.end(), core) - kOutputNames.begin());
  };
  return name.starts_with("snapshots/") ? rank_of("trace.csv") + 0.5 : rank_of(name);
}

// "NN.png" (or .svg, .pdf), two digits or more: a snapshot's name.
bool is_snapshot_name(const std::string &name) {
  if (name.size() < 6 || !(name.ends_with(".png") || name.ends_with(".svg") || name.ends_with(".pdf"))) return false;
  return std::all_of(name.begin(), name.end() - 4, [](char c) { return c >= '0' && c <= '9'; });
}

// The file `name` names in dir; for a folder's name ("snapshots/"), the file of that folder
// that has `input`'s name (links followed), empty when there is none.
fs::path output_path_for(const fs::path &dir, const std::string &name, const std::string &input) {
  if (!name.ends_with('/')) return dir / name;
  std::error_code ec;
  const fs::path real = fs::canonical(input, ec);
  return ec ? fs::path() : dir / name / real.filename();
}

// Why DIR's entry `name` (an output's name) cannot take the output, empty when it can: a
// regular file (replaced), a FIFO or a character device (written as the output comes), or
// nothing there. A symbolic link is the user's (neither written through nor removed), as
// are a directory, a socket or a block device; a folder's name ("snapshots/") must be a
// real directory, and a link among its snapshot files is the user's too.
std::string why_not_an_output(const fs::path &dir, const std::string &name) {
  std::error_code ec;
  const fs::path entry = dir / (name.ends_with('/') ? name.substr(0, name.size() - 1) : name);
  const fs::file_status status = fs::symlink_status(entry, ec);
  if (ec || !fs::exists(status)) return {};
  const std::string shown = entry.filename().string();
  if (fs::is_symlink(status)) {
    return fmt::format("{} is a symbolic link (to {}), which a run neither writes through nor removes: remove it or "
                       "choose another directory", shown, fs::read_symlink(entry, ec).string());
  }
  if (name.ends_with('/')) {
    if (!fs::is_directory(status)) return fmt::format("{} is not a directory, where the run's {} goes", shown, name);
    for (const fs::directory_entry &file : fs::directory_iterator(entry, ec)) {
      if (!is_snapshot_name(file.path().filename().string())) continue;
      if (const std::string why = why_not_an_output(dir, name + file.path().filename().string()); !why.empty()) {
        return name + why;
      }
    }
    return {};
  }
  if (fs::is_regular_file(status) || fs::is_fifo(status) || fs::is_character_file(status)) return {};
  return fmt::format("{} is {}, not a file a run can replace", shown,
                     fs::is_directory(status) ? "a directory" : "neither a regular file nor a FIFO");
}

// Whether writing `output` would replace `input`: one file, not a character device.
bool is_same_content(const std::string &output, const std::string &input) {
  struct stat st {};
  return ::stat(output.c_str(), &st) == 0 && !S_ISCHR(st.st_mode) && common::same_file(output, input);
}

// Removes a file an earlier run left (a regular file or a link; never anything else).
void remove_stale(const fs::path &path) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (ec || !(fs::is_regular_file(status) || fs::is_symlink(status))) return;
  fs::remove(path, ec);
}

// The files of an earlier run that this one did not write: those of `names` (what this one may
// write) in `dir`, and, when "snapshots/" is among them, snapshots/NN.png (snapshots/ itself
// when that empties it).
void remove_stale_files(const fs::path &dir, const std::vector<std::string> &names,
                        const std::vector<std::string> &written) {
  const auto was_written = [&written](const std::string &name) {
    return std::find(written.begin(), written.end(), name) != written.end();
  };
  for (const std::string &name : names) {
    if (!name.ends_with('/') && !was_written(name)) remove_stale(dir / name);
  }
  if (std::find(names.begin(), names.end(), "snapshots/") == names.end()) return;
  const fs::path snapshots = dir / "snapshots";
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(snapshots, ec))) return;
  for (const fs::directory_entry &entry : fs::directory_iterator(snapshots, ec)) {
    const std::string name = "snapshots/" + entry.path().filename().string();
    if (is_snapshot_name(entry.path().filename().string()) && !was_written(name)) remove_stale(entry.path());
  }
  if (fs::is_empty(snapshots, ec) && !ec) fs::remove(snapshots, ec);
}

}  // namespace

void prepare_output_dir(const std::string &dir) {
  if (dir.empty()) refuse_out_dir(dir, "an empty path");
  const fs::path path(dir);
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) refuse_out_dir(dir, "exists and is not a directory");
    probe_writable(dir);
    return;
  }
  if (fs::is_symlink(fs::symlink_status(path, ec))) {
    refuse_out_dir(dir, fmt::format("a symbolic link to {}, which does not exist (create that directory, or give "
                                    "another path)", fs::read_symlink(path, ec).string()));
  }
  const fs::path created = first_missing(path);
  errno = 0;
  fs::create_directories(path, ec);
  if (ec || !fs::is_directory(path)) {
    const std::string reason = ec ? ec.message() : std::string(std::strerror(errno != 0 ? errno : EACCES));
    if (!created.empty()) fs::remove_all(created, ec);
    refuse_out_dir(dir, fmt::format("cannot create the directory: {}", reason));
  }
  try {
    probe_writable(dir);
  } catch (const common::InputError &) {
    if (!created.empty()) fs::remove_all(created, ec);
    throw;
  }
}

const std::vector<std::string> &run_output_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all(kOutputNames.begin(), kOutputNames.end());
    all.emplace_back("snapshots/");
    return all;
  }();
  return names;
}

void refuse_outputs_over_inputs(const std::string &dir, const std::vector<std::string> &names,
                                const std::vector<NamedInput> &inputs) {
  for (const NamedInput &input : inputs) {
    for (const std::string &name : names) {
      const fs::path output = output_path_for(fs::path(dir), name, input.path);
      if (output.empty() || !is_same_content(output.string(), input.path)) continue;
      throw common::InputError(fmt::format("--out {} is also an input ({} {}): refusing to overwrite it",
                                           output.string(), input.what, input.path));
    }
  }
}

std::string wrote_line(const std::string &dir, const std::vector<std::string> &written, std::size_t first_snapshot,
                       std::size_t snapshot_files) {
  std::vector<std::string> names(written.begin(), written.begin() + static_cast<std::ptrdiff_t>(first_snapshot));
  if (snapshot_files > 0) {
    names.push_back(fmt::format("snapshots/ ({} files, {} to {})", snapshot_files,
                                written[first_snapshot].substr(10), written[first_snapshot + snapshot_files - 1].substr(10)));
  }
  names.insert(names.end(), written.begin() + static_cast<std::ptrdiff_t>(first_snapshot + snapshot_files), written.end());
  std::string line = "wrote " + (fs::path(dir) / "").string() + ":";
  for (std::size_t i = 0; i < names.size(); ++i) line += (i == 0 ? " " : ", ") + names[i];
  return line;
}

OutputDir::OutputDir(std::string dir, const std::vector<NamedInput> &inputs, const std::vector<std::string> &own_names)
    : OutputDir(std::move(dir), inputs, OwnNamesOnly{[&own_names] {
                  std::vector<std::string> names = run_output_names();
                  names.insert(names.end(), own_names.begin(), own_names.end());
                  return names;
                }()}) {}

OutputDir::OutputDir(std::string dir, const std::vector<NamedInput> &inputs, OwnNamesOnly names)
    : dir_(std::move(dir)), names_(std::move(names.names)) {
  prepare_output_dir(dir_);
  refuse_outputs_over_inputs(dir_, names_, inputs);
  for (const std::string &name : names_) {
    if (const std::string why = why_not_an_output(fs::path(dir_), name); !why.empty()) refuse_out_dir(dir_, why);
  }
}

void OutputDir::begin(const std::string &name) {
  const fs::path relative(name);
  const std::string folder = relative.has_parent_path() ? relative.parent_path().string() + "/" : name;
  if (std::find(names_.begin(), names_.end(), folder) == names_.end()) {
    throw std::logic_error(fmt::format("--out {}: {} is not among the names checked against the inputs", dir_, name));
  }
  if (!writing_) {
    writing_.emplace();
    if (common::interrupted()) deadline_.emplace();
  }
  if (!relative.has_parent_path()) return;
  std::error_code ec;
  fs::create_directory(fs::path(dir_) / relative.parent_path(), ec);
  if (ec) refuse_out_dir(dir_, fmt::format("cannot create {}: {}", folder, ec.message()));
}

void OutputDir::write(const std::string &name, std::string_view bytes) {
  begin(name);
  common::write_file_atomically((fs::path(dir_) / name).string(), bytes);
  written(name);
}

void OutputDir::written(const std::string &name) {
  written_.push_back(name);
  if (deadline_) deadline_->written(name);
}

void OutputDir::commit(const std::string &name, common::OutputFile &file) {
  begin(name);
  file.commit();
  written(name);
}

void OutputDir::finish() {
  remove_stale_files(fs::path(dir_), names_, written_);
  std::stable_sort(written_.begin(), written_.end(), [](const std::string &a, const std::string &b) {
    return line_rank(a) < line_rank(b);
  });
  const auto is_snapshot = [](const std::string &name) { return name.starts_with("snapshots/"); };
  const auto first = std::find_if(written_.begin(), written_.end(), is_snapshot);
  const auto end = std::find_if_not(first, written_.end(), is_snapshot);
  common::print_stderr("{}\n", wrote_line(dir_, written_, static_cast<std::size_t>(first - written_.begin()),
                                        static_cast<std::size_t>(end - first)));
  deadline_.reset();
  writing_.reset();
}

void refuse_out_dir(const std::string &dir, const std::string &reason) {
  throw common::InputError(fmt::format("--out {}: {}", dir, reason));
}

}  // namespace app
