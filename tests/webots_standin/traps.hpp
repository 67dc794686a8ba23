// Appended to the stand-in's Device.hpp (build.sh): the two patterns of Webots' own headers
// that trip our warnings, so the stand-in build fails unless Webots' include folders are
// SYSTEM includes. DistanceSensor.hpp: a constructor parameter `name` shadows Device's
// member (-Wshadow). GPS.hpp: `const double getSpeed() const` (-Wignored-qualifiers).
#include "../../c/webots/types.h"

namespace webots_standin {

class Trap {
 public:
  explicit Trap(const char *name) : name(name) {}
  const double getSpeed() const { return 0.0; }
  const char *label() const { return name; }

 private:
  const char *name;
};

}  // namespace webots_standin
