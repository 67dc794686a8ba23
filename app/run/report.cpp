#include "app/run/report.hpp"

#include <cassert>

#include <fmt/format.h>

namespace app {

const ReportEntry *Report::find(std::string_view key) const {
  for (const ReportEntry &entry : entries_) {
    if (entry.key == key) return &entry;
  }
  return nullptr;
}

std::string Report::text(std::string_view key) const {
  const ReportEntry *entry = find(key);
  return entry != nullptr && entry->text ? *entry->text : std::string();
}

void Report::both(std::string key, std::string text, nlohmann::ordered_json json) {
  assert(find(key) == nullptr);
  entries_.push_back({std::move(key), std::move(text), std::move(json)});
}

void Report::both(std::string key, const std::string &text) { both(std::move(key), text, nlohmann::ordered_json(text)); }

void Report::json_only(std::string key, nlohmann::ordered_json json) {
  assert(find(key) == nullptr);
  entries_.push_back({std::move(key), std::nullopt, std::move(json)});
}

void Report::add(ReportEntry entry) {
  assert(find(entry.key) == nullptr);
  entries_.push_back(std::move(entry));
}

std::string format_summary(const Report &report) {
  std::string out;
  for (const auto &[key, value] : summary_pairs(report)) out += fmt::format("{}: {}\n", key, value);
  return out;
}

std::vector<std::pair<std::string, std::string>> summary_pairs(const Report &report) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const ReportEntry &entry : report.entries()) {
    if (entry.text) pairs.emplace_back(entry.key, *entry.text);
  }
  return pairs;
}

nlohmann::ordered_json report_json(const Report &report) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const ReportEntry &entry : report.entries()) j[entry.key] = entry.json;
  return j;
}

std::string end_text(std::string_view ending, std::string_view message) {
  return message.empty() ? std::string(ending) : fmt::format("{} ({})", ending, message);
}

}  // namespace app
