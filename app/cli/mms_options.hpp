#pragma once
// The options of an mms-protocol run as `mms` and `batch ... -- COMMAND` spell them:
// --walls truth|sensed, --until exit|goal|start, --wall-limit S, --max-line BYTES,
// --ignore-invalid; and the mms batch's command line.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "app/batch/batch.hpp"
#include "app/mms/mms_session.hpp"

namespace app {

void add_mms_options(CLI::App &command, MmsOptions &options);
// Throws common::InputError when --strategy or --speed-run was given (they do not apply);
// warns when --time-limit (simulated seconds) was given without --wall-limit, the wall-clock
// guard that --time-limit was in mms before.
void check_mms_command_line(const CLI::App &command);
// Whether the command line gave one of add_mms_options' options.
bool mms_options_given(const CLI::App &command);

// `batch WORLD... -- COMMAND [ARGS...]`: the mms batch (app/batch/mms_batch.hpp) on the listed
// worlds, its table on stdout and, with csv set, its CSV; returns the exit status. Throws
// common::InputError when there is no command, or an option does not apply (--strategy,
// --speed-run: the algorithm decides where the robot goes).
int run_mms_batch_command(const CLI::App &command, const RunOptions &options, MmsOptions mms,
                          const std::vector<std::string> &child_command, const WorldList &list, int jobs,
                          const std::string &csv);

}  // namespace app
