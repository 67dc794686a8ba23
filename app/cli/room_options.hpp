#pragma once
// The room command's options, each described once as the run family's are
// (app/run/option_fields.hpp: the flag, its help with the default, the field it sets or the
// parse that sets it), registered by app/cli/option_binding.hpp, and their rules: an option
// that does nothing for the room run asked is warned about in the words `run` uses
// ("warning: --goal has no effect without --strategy wavefront"), and the run goes on.
//
// The room's echo is its summary's own keys (app/run/metric_run_report.hpp), so these fields have
// no `echo`; --start, --resolution, --boundary, --seed and --out are registered by their own
// code (their arity or checks are shared with other commands).

#include <span>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/run/metric_run.hpp"
#include "app/run/option_fields.hpp"
#include "app/run/run_options.hpp"

namespace app {

template <>
std::span<const OptionField<MetricRunOptions>> option_fields();

// One "warning: ..." line for each option given that does nothing for this room run (the
// strategy's own options with another strategy, the depth rays' with another model), in the
// table's order.
std::vector<std::string> check_room_options_apply(const GivenOptions &given, const MetricRunOptions &options);

// Checks across the options once they are all read (--cells with --resolution, a threshold
// not finite): common::InputError.
void check_room_options(const MetricRunOptions &options);

}  // namespace app
