#include "app/mms/mms_outputs.hpp"

#include <string>
#include <vector>

namespace app {

std::vector<NamedInput> program_inputs(const MmsOptions &mms) {
  std::vector<NamedInput> inputs;
  for (std::size_t i = 0; i < mms.command.size(); ++i) {
    inputs.push_back({i == 0 ? "the program" : "the program's argument", mms.command[i]});
  }
  return inputs;
}

const std::vector<std::string> &mms_own_names() {
  static const std::vector<std::string> names{"marks.txt"};
  return names;
}

std::vector<NamedFile> mms_own_files(const MmsRun &run) { return {{"marks.txt", render_marks(run.mms.marks, false)}}; }

}  // namespace app
