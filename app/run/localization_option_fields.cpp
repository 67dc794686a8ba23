// run --localize's options, described once as the run's are (app/run/option_fields.hpp).

#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/run/option_fields.hpp"

namespace app {

template <>
std::span<const OptionField<LocalizationOptions>> option_fields() {
  using L = LocalizationOptions;
  using Json = nlohmann::ordered_json;
  static const std::vector<OptionField<L>> fields{
      {"on", "--localize", "",
       [](const L &) {
         return std::string(
             "follow the robot with the localization lab's grid Bayes filter: it knows the maze's walls, not the "
             "start, and reads the four sides with the lidar at each cell (printed as it goes)");
       },
       [](L &l) -> FieldRef { return &l.on; }, nullptr, "", [](const L &l) { return Json(l.on); }},
      {"sensor", "--sensor", "",
       [](const L &) {
         return std::string("P1,P2,P3,P4: --localize's sensor model, P(z=wall|wall), P(z=no wall|wall), "
                            "P(z=wall|no wall), P(z=no wall|no wall) (default 0.8,0.2,0.4,0.6)");
       },
       [](L &l) -> FieldRef { return &l.sensor; }, nullptr, "",
       [](const L &l) { return l.sensor.empty() ? Json(nullptr) : Json(l.sensor); }},
      {"motion", "--motion", "",
       [](const L &l) {
         return fmt::format("P: --localize's motion model, a move succeeds with P, else the robot stays (default {:g})",
                            l.motion);
       },
       [](L &l) -> FieldRef { return &l.motion; }, nullptr, "", [](const L &l) { return Json(l.motion); }},
      {"localized", "--localized", "",
       [](const L &l) {
         return fmt::format("F: --localize calls the robot localized when one cell holds F of the belief (default {:g})",
                            l.localized);
       },
       [](L &l) -> FieldRef { return &l.localized; }, nullptr, "", [](const L &l) { return Json(l.localized); }},
  };
  return fields;
}

}  // namespace app
