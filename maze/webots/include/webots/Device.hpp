#pragma once
// Webots-compatible device API, the subset maze_mapper's embedded simulator implements
// (ARCHITECTURE.md). Public members mirror the Webots R2023b C++ API so a controller written
// against these headers compiles unchanged against a real Webots installation. Private
// members are the embedded simulator's plumbing and are not part of the API.

#include <string>

namespace webots {

namespace embedded {
class Simulation;  // maze/src: the world side behind these devices
}

class Device {
 public:
  virtual ~Device();
  Device(const Device &) = delete;
  Device &operator=(const Device &) = delete;

  const std::string &getName() const;  // as Webots: a reference to the name it holds
  std::string getModel() const;

 protected:
  Device(const std::string &name, embedded::Simulation &simulation, int index);
  embedded::Simulation &simulation() const { return *simulation_; }
  int index() const { return index_; }

 private:
  std::string name_;
  embedded::Simulation *simulation_;
  int index_;
};

}  // namespace webots
