#pragma once
// Which run options apply to the chosen set-up, as its row in sensing/setups.hpp says.

#include <string>
#include <vector>

#include "sensing/setups.hpp"

namespace app {

// given: the sensing::ModelOption bits of the options the user typed. Throws
// common::InputError for --p-free/--p-occ given to a set-up that marks with the course's
// fixed numbers (the run would not use them, and its summary would not say what it used);
// returns a "warning: ..." line for each other option its model does not read.
std::vector<std::string> check_model_options(const sensing::SetUp &setup, unsigned given);

}  // namespace app
